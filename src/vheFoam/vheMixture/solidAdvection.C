/*---------------------------------------------------------------------------*\
  vheFoam: a solid's fraction carried geometrically (isoAdvector)
\*---------------------------------------------------------------------------*/

#include "solidAdvection.H"
#include "isoAdvection.H"
#include "cyclicFvPatch.H"
#include "profiling.H"
#include "vhe.h"

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

    // isoAdvection's clip is not conservative: bound() does it instead
    const_cast<dictionary&>(alpha.mesh().solverDict(alpha.name()))
        .set("clip", false);

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


Foam::scalar Foam::solidAdvection::bound
(
    UPtrList<volScalarField>& fields,
    UPtrList<surfaceScalarField>& fluxes,
    const scalar deltaT
)
{
    const label nS = fields.size();
    if (nS == 0) return 0;
    const fvMesh& mesh = fields[0].mesh();
    const label nInt = mesh.nInternalFaces();

    // Each cell's internal faces (compressed rows, C core)
    const cellList& cells = mesh.cells();
    List<long> start(mesh.nCells() + 1, long(0));
    DynamicList<int> faces(2*nInt);
    forAll(cells, c)
    {
        start[c] = faces.size();
        for (const label f : cells[c])
        {
            if (f < nInt) faces.append(f);
        }
    }
    start[mesh.nCells()] = faces.size();

    List<scalar*> a(nS), F(nS);
    forAll(fields, k)
    {
        a[k] = fields[k].primitiveFieldRef().data();
        F[k] = fluxes[k].primitiveFieldRef().data();
    }
    scalarField work(mesh.nCells());
    const scalar moved = vhe_bound_fractions
    (
        mesh.nCells(), mesh.owner().cdata(), mesh.neighbour().cdata(),
        start.cdata(), faces.cdata(), mesh.V().cdata(), nS, a.data(),
        F.data(), deltaT, work.data(), 10
    );

    // every rank (a processor patch's exchange)
    for (volScalarField& f : fields) f.correctBoundaryConditions();
    return returnReduce(moved, sumOp<scalar>());
}


Foam::scalar Foam::solidAdvection::settle
(
    UPtrList<volScalarField>& fields,
    scalarField& solidSum
)
{
    const label nS = fields.size();
    solidSum = 0;
    if (nS == 0) return 0;
    const scalarField& V = fields[0].mesh().V();

    // Into [0, 1], each field's volume change noted
    List<scalar> change(nS, Zero);
    forAll(fields, k)
    {
        scalarField& a = fields[k].primitiveFieldRef();
        forAll(a, celli)
        {
            if (a[celli] < 0)
            {
                change[k] -= a[celli]*V[celli];
                a[celli] = 0;
            }
        }
        solidSum += a;
    }
    forAll(solidSum, celli)
    {
        if (solidSum[celli] <= 1) continue;
        forAll(fields, k)
        {
            scalar& a = fields[k].primitiveFieldRef()[celli];
            change[k] -= a*(1 - 1/solidSum[celli])*V[celli];
            a /= solidSum[celli];
        }
        solidSum[celli] = 1;
    }

    // Each field's change undone on its partly filled cells
    scalar unplaced = 0;
    bool moved = false;
    forAll(fields, k)
    {
        const scalar dV = returnReduce(change[k], sumOp<scalar>());
        if (dV == 0) continue;
        moved = true;
        scalarField& a = fields[k].primitiveFieldRef();
        const scalarField w(a*(1 - a)*max(1 - solidSum, scalar(0))*V);
        const scalar sumW = gSum(w);
        if (sumW <= mag(dV))
        {
            unplaced += mag(dV);
            continue;
        }
        const scalarField da(-dV*w/sumW/V);
        a += da;
        solidSum += da;
    }
    if (moved)
    {
        for (volScalarField& f : fields) f.correctBoundaryConditions();
    }
    return unplaced;
}


// ************************************************************************* //
