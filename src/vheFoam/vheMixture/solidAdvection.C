/*---------------------------------------------------------------------------*\
  vheFoam: a solid's fraction carried geometrically (isoAdvector)
\*---------------------------------------------------------------------------*/

#include "solidAdvection.H"
#include "cellFaceRows.H"
#include "interfacePlanes.H"
#include "upwind.H"
#include "syncTools.H"
#include "fvc.H"
#include "profiling.H"
#include "vhe.h"
#include "vheFlat.H"
#include "linearFaceValues.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// A fraction strictly between these is a surface cell (isoAdvection's
// surfCellTol) and its isosurface is found to isoFaceTol
const scalar surfCellTol = 1e-8;
const scalar isoFaceTol = 1e-8;

// The bounding acts once a fraction is out of [0, 1] by more than this
const scalar boundTol = 1e-12;

// RDF passes of each surface cell's plane (interfacePlanes): one is the
// most accurate (translated disk at 32/64/128 cells: L1 9.3e-4, 2.1e-4,
// 6.5e-5 with one, 1.0e-3, 2.7e-4, 7.6e-5 with three); 0 would be the
// isosurface of the point-interpolated fraction (isoAdvector's isoAlpha)
const label nRDF = 1;

// The two sides of every coupled face (processor, cyclic) agree: each
// inflow side takes minus its partner's outflow volume, and a, if given,
// the change on the inflow side's cell.  phiB, dVB: every boundary face's
// flux and volume, in mesh order
void agreeOnCoupled
(
    const fvMesh& mesh,
    const UList<scalar>& phiB,
    UList<scalar>& dVB,
    scalarField* a
)
{
    const label nInt = mesh.nInternalFaces();
    const labelList& fOwn = mesh.faceOwner();
    scalarField other(dVB);
    syncTools::swapBoundaryFaceList(mesh, other);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!pp.coupled()) continue;
        forAll(pp, i)
        {
            const label b = pp.start() - nInt + i;
            if (phiB[b] >= 0) continue;
            const scalar v = -other[b];
            if (a)
            {
                const label c = fOwn[nInt + b];
                (*a)[c] -= (v - dVB[b])/mesh.V()[c];
            }
            dVB[b] = v;
        }
    }
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

    const fvMesh& mesh = alpha.mesh();
    const scalar dt = mesh.time().deltaTValue();
    const label nInt = mesh.nInternalFaces();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    // From the step's start (a PIMPLE outer iteration transports again)
    alpha == alpha.oldTime();
    const scalarField& a = alpha.primitiveField();

    // The volume through each face over the step: the upwind fraction's,
    // and at the downwind faces of each surface cell the volume its
    // isosurface sweeps
    tmp<surfaceScalarField> tdVf
    (
        upwind<scalar>(mesh, phi).flux(alpha)*mesh.time().deltaT()
    );
    surfaceScalarField& dVf = tdVf.ref();
    scalarField& dVfi = dVf.primitiveFieldRef();
    const scalarField& phii = phi.primitiveField();
    const scalarField& magSf = mesh.magSf().primitiveField();

    const interfacePlanes planes(alpha, surfCellTol, isoFaceTol, nRDF);
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const pointField& pts = mesh.points();
    List<unsigned char> surface(a.size(), static_cast<unsigned char>(0));
    forAll(a, c)
    {
        surface[c] = a[c] > surfCellTol && a[c] < 1 - surfCellTol;
    }
    // The velocity at a point x of cell c: U_c + (x - C_c).grad U, the
    // cell's Gauss gradient of the linearly interpolated face values
    // (exact for a linear field, as the cell-point interpolation)
    const vectorField& Uc = U.primitiveField();
    const scalarField& w = mesh.weights().primitiveField();
    const vectorField& Sf = mesh.Sf().primitiveField();
    // (a coupled face's value from its two cells, as an internal face's)
    List<vectorField> faceU(patches.size());
    forAll(patches, patchi)
    {
        faceU[patchi] = linearFaceValues(U.boundaryField()[patchi]);
    }
    auto velocityAt = [&](const label c, const point& x)
    {
        tensor g(Zero);
        for (const label f : mesh.cells()[c])
        {
            if (f < nInt)
            {
                const vector Uf = w[f]*Uc[own[f]] + (1 - w[f])*Uc[nei[f]];
                g += (own[f] == c ? Sf[f] : -Sf[f])*Uf;
                continue;
            }
            const label patchi = patches.whichPatch(f);
            const fvPatchVectorField& Up = U.boundaryField()[patchi];
            if (Up.empty()) continue;
            const label i = f - patches[patchi].start();
            g += mesh.Sf().boundaryField()[patchi][i]*faceU[patchi][i];
        }
        return vector(Uc[c] + ((x - mesh.C()[c]) & g)/mesh.V()[c]);
    };
    // The volume the cell's plane, moving with the velocity at its centre,
    // carries through a downwind face over the step (C core)
    DynamicList<point> fx;
    auto sweep = [&]
    (
        const label f, const point& x0, const vector& n0, const scalar Un0,
        const scalar phif, const scalar magSff
    )
    {
        const face& fc = mesh.faces()[f];
        fx = UIndirectList<point>(pts, fc);
        return vhe_face_sweep
        (
            fc.size(), flat(fx), x0.cdata(), n0.cdata(), Un0, dt, phif,
            magSff, 10*SMALL
        );
    };
    forAll(planes.cells(), pi)
    {
        const label c = planes.cells()[pi];
        const point& x0 = planes.centre()[pi];
        const vector& n0 = planes.normal()[pi];
        const scalar Un0 = velocityAt(c, x0) & n0;

        for (const label f : mesh.cells()[c])
        {
            if (f < nInt)
            {
                const scalar out = own[f] == c ? phii[f] : -phii[f];
                if (out <= 10*SMALL) continue;
                dVfi[f] = sweep(f, x0, n0, Un0, phii[f], magSf[f]);
                continue;
            }
            const label patchi = patches.whichPatch(f);
            const scalarField& phip = phi.boundaryField()[patchi];
            if (phip.empty()) continue;
            const label i = f - patches[patchi].start();
            if (phip[i] <= 10*SMALL) continue;
            dVf.boundaryFieldRef()[patchi][i] = sweep
            (
                f, x0, n0, Un0, phip[i],
                mesh.magSf().boundaryField()[patchi][i]
            );
        }
    }

    // The two sides of every coupled face agree on the volume crossing it
    {
        scalarField phiB(mesh.nBoundaryFaces(), Zero);
        scalarField dVB(mesh.nBoundaryFaces(), Zero);
        forAll(patches, patchi)
        {
            const label start = patches[patchi].start() - nInt;
            const scalarField& phip = phi.boundaryField()[patchi];
            SubList<scalar>(phiB, phip.size(), start) = phip;
            SubList<scalar>(dVB, phip.size(), start) =
                dVf.boundaryField()[patchi];
        }
        agreeOnCoupled(mesh, phiB, dVB, nullptr);
        forAll(patches, patchi)
        {
            scalarField& dVp = dVf.boundaryFieldRef()[patchi];
            dVp = SubList<scalar>
            (
                dVB, dVp.size(), patches[patchi].start() - nInt
            );
        }
    }

    alpha.primitiveFieldRef() -= fvc::surfaceIntegrate(dVf)().primitiveField();

    // Out of [0, 1] where a flux went wrong: put back through the cell's
    // downwind faces, in the surface cells and two layers of face
    // neighbours, where the geometric fluxes act, once something is out by
    // more than boundTol anywhere (as isoAdvection did); the rest (a
    // body's interior at 1 - dt div(phi)) is bound()'s and settle()'s.
    // Three passes, after each of which the two sides of every coupled
    // face agree again (the receiving cell takes the change), so that a
    // processor face bounds as the internal face it is in serial
    const scalar over = gMax(alpha.primitiveField()) - 1;
    const scalar under = gMin(alpha.primitiveField());
    if (over > boundTol || under < -boundTol)
    {
        const cellFaceRows& rows = cellFaceRows::New(mesh);
        const labelList& fOwn = mesh.faceOwner();
        const scalarField& V = mesh.V();
        List<unsigned char> check(surface);
        for (label ring = 0; ring < 2; ++ring)
        {
            const List<unsigned char> last(check);
            forAll(last, c)
            {
                if (!last[c]) continue;
                for (long j = rows.start()[c]; j < rows.start()[c + 1]; ++j)
                {
                    const label f = rows.faces()[j];
                    if (f < nInt) check[own[f] == c ? nei[f] : own[f]] = 1;
                }
            }
        }

        // Every face's flux and volume in one array, the boundary faces in
        // mesh order (none on empty patches)
        scalarField phiAll(mesh.nFaces(), Zero), dVAll(mesh.nFaces(), Zero);
        SubList<scalar>(phiAll, nInt) = phii;
        SubList<scalar>(dVAll, nInt) = dVfi;
        forAll(patches, patchi)
        {
            const scalarField& pp = phi.boundaryField()[patchi];
            const label start = patches[patchi].start();
            SubList<scalar>(phiAll, pp.size(), start) = pp;
            SubList<scalar>(dVAll, pp.size(), start) =
                dVf.boundaryField()[patchi];
        }

        scalarField& ai = alpha.primitiveFieldRef();
        for (label pass = 0; pass < 3; ++pass)
        {
            vhe_bound_downwind
            (
                mesh.nCells(), nInt, fOwn.cdata(), nei.cdata(), rows.start(),
                rows.faces(), V.cdata(), phiAll.cdata(), dVAll.data(),
                ai.data(), dt, check.cdata(), over > boundTol,
                under < -boundTol, 10*SMALL, 1
            );
            SubList<scalar> dVB(dVAll, mesh.nBoundaryFaces(), nInt);
            agreeOnCoupled
            (
                mesh, SubList<scalar>(phiAll, mesh.nBoundaryFaces(), nInt),
                dVB, &ai
            );
        }

        dVfi = SubList<scalar>(dVAll, nInt);
        forAll(patches, patchi)
        {
            scalarField& dVp = dVf.boundaryFieldRef()[patchi];
            dVp = SubList<scalar>(dVAll, dVp.size(), patches[patchi].start());
        }
    }
    alpha.correctBoundaryConditions();

    dVf /= mesh.time().deltaT();
    dVf.rename("alphaPhi." + alpha.name());
    return tdVf;
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

    const cellFaceRows& rows = cellFaceRows::New(mesh);

    List<scalar*> a(nS), F(nS);
    forAll(fields, k)
    {
        a[k] = fields[k].primitiveFieldRef().data();
        F[k] = fluxes[k].primitiveFieldRef().data();
    }
    scalarField work(mesh.nCells());
    const scalar moved = vhe_bound_fractions
    (
        mesh.nCells(), mesh.nInternalFaces(), mesh.owner().cdata(),
        mesh.neighbour().cdata(), rows.start(), rows.faces(),
        mesh.V().cdata(), nS, a.data(),
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
