/*---------------------------------------------------------------------------*\
  vheFoam: a solid's fraction carried geometrically (isoAdvector)
\*---------------------------------------------------------------------------*/

#include "solidAdvection.H"
#include "isoAdvection.H"
#include "cyclicFvPatch.H"
#include "profiling.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// Each inflow cyclic face takes minus its partner's outflow, and its cell
// the difference (see the header)
void syncCyclic
(
    Foam::volScalarField& alpha,
    const Foam::surfaceScalarField& phi,
    Foam::surfaceScalarField& alphaPhi
)
{
    using namespace Foam;
    const fvMesh& mesh = alpha.mesh();
    const scalar deltaT = mesh.time().deltaTValue();
    scalarField& a = alpha.primitiveFieldRef();
    forAll(mesh.boundary(), patchi)
    {
        if (!isA<cyclicFvPatch>(mesh.boundary()[patchi])) continue;
        const cyclicFvPatch& cp =
            refCast<const cyclicFvPatch>(mesh.boundary()[patchi]);
        const label nbr = cp.neighbPatchID();
        const scalarField& phiP = phi.boundaryField()[patchi];
        scalarField& F = alphaPhi.boundaryFieldRef()[patchi];
        scalarField& Fn = alphaPhi.boundaryFieldRef()[nbr];
        const labelUList& fc = cp.faceCells();
        const labelUList& fcn = mesh.boundary()[nbr].faceCells();
        forAll(fc, k)
        {
            if (phiP[k] >= 0) continue;
            const label c = fc[k], cn = fcn[k];
            a[c] += (F[k] + Fn[k])*deltaT/mesh.V()[c];
            // isoAdvection bounded the cell with the upwind inflow: what
            // would take it out of [0, 1] stays on the outflow side
            const scalar over =
                (max(a[c] - 1, scalar(0)) + min(a[c], scalar(0)))
               *mesh.V()[c];
            a[c] -= over/mesh.V()[c];
            a[cn] += over/mesh.V()[cn];
            Fn[k] -= over/deltaT;
            F[k] = -Fn[k];
        }
    }
    // every rank (a processor patch's exchange)
    alpha.correctBoundaryConditions();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField> Foam::solidAdvection::advect
(
    volScalarField& alpha,
    const surfaceScalarField& phi,
    const volVectorField& U
)
{
    addProfiling(iso, "vheMixture::isoAdvection");

    // From the step's start (a PIMPLE outer iteration transports again)
    alpha == alpha.oldTime();

    const dimensionedScalar one("one", dimDensity, 1.0);
    const dimensionedScalar zero("zero", dimDensity, 0.0);
    tmp<surfaceScalarField> talphaPhi;
    {
        const int level = messageStream::level;
        messageStream::level = 0;
        isoAdvection advector(alpha, phi, U);
        advector.advect();
        messageStream::level = level;
        talphaPhi = advector.getRhoPhi(one, zero)/one;
    }
    talphaPhi.ref().rename("alphaPhi." + alpha.name());
    syncCyclic(alpha, phi, talphaPhi.ref());
    return talphaPhi;
}


// ************************************************************************* //
