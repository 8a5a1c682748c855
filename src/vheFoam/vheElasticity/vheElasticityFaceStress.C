/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the traction-continuous face stress at a solid/fluid face
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

void Foam::vheElasticity::interfaceSideStress
(
    const volSymmTensorField& sig,
    surfaceSymmTensorField& sigOwn,
    surfaceSymmTensorField& sigNei
) const
{
    // At a face where phi_s jumps, the stress of the solid side is its
    // value at the face, not at its cell centre: taking the cell-centre
    // stress is an O(dx) traction error at the interface (removing it
    // cut the oscillating Couette error 1.4-1.7x).  The solid side is
    // extrapolated to the face with the least-squares gradient of the
    // stress over its solid neighbours (phi_s >= 0.5), exact for linear
    // stress, blended by the jump of phi_s; a cell with too few solid
    // neighbours to fix a gradient keeps its cell-centre value.  On a
    // coupled patch (processor, cyclic) "own" is this side, "nei" the
    // other, whose gradient comes across with the patch.
    const volScalarField& phis = mixture_.phis();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const label nCells = mesh_.nCells();
    const scalar solid = 0.5;

    // Normal matrix M = sum w d d^T and right sides r_i = sum w d_i dsigma
    symmTensorField M(nCells, Zero);
    symmTensorField rx(nCells, Zero), ry(nCells, Zero), rz(nCells, Zero);
    auto add = [&](label P, const vector& d, const symmTensor& ds)
    {
        const scalar w = 1/magSqr(d);
        M[P] += w*sqr(d);
        rx[P] += (w*d.x())*ds;
        ry[P] += (w*d.y())*ds;
        rz[P] += (w*d.z())*ds;
    };
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        if (phis[P] < solid || phis[N] < solid) continue;
        const vector d(C[N] - C[P]);
        add(P, d, sig[N] - sig[P]);
        add(N, -d, sig[P] - sig[N]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const labelUList& fc = p.faceCells();
        const vectorField d(p.delta());
        const scalarField phisN
        (
            phis.boundaryField()[patchi].patchNeighbourField()
        );
        const symmTensorField sigN
        (
            sig.boundaryField()[patchi].patchNeighbourField()
        );
        forAll(fc, i)
        {
            const label P = fc[i];
            if (phis[P] < solid || phisN[i] < solid) continue;
            add(P, d[i], sigN[i] - sig[P]);
        }
    }

    // The least-squares gradient of sig along x, y and z per cell (zero
    // where M is singular), with coupled patches for the other side's
    const Vector<label> solD(mesh_.solutionD());
    PtrList<volSymmTensorField> g(3);
    forAll(g, d)
    {
        g.set
        (
            d,
            new volSymmTensorField
            (
                IOobject
                (
                    "sigmaGrad" + Foam::name(d), mesh_.time().timeName(), mesh_
                ),
                mesh_,
                dimensionedSymmTensor(dimPressure/dimLength, Zero),
                patchTypes(mesh_)
            )
        );
    }
    forAll(M, P)
    {
        symmTensor m(M[P]);
        const scalar scale = tr(m)/3;
        if (scale <= 0) continue;
        // empty directions: no neighbours, no extrapolation
        if (solD.x() < 0) { m.xx() = scale; m.xy() = m.xz() = 0; }
        if (solD.y() < 0) { m.yy() = scale; m.xy() = m.yz() = 0; }
        if (solD.z() < 0) { m.zz() = scale; m.xz() = m.yz() = 0; }
        if (det(m) < 1e-6*pow3(scale)) continue;
        const symmTensor iM(inv(m));
        g[0][P] = iM.xx()*rx[P] + iM.xy()*ry[P] + iM.xz()*rz[P];
        g[1][P] = iM.xy()*rx[P] + iM.yy()*ry[P] + iM.yz()*rz[P];
        g[2][P] = iM.xz()*rx[P] + iM.yz()*ry[P] + iM.zz()*rz[P];
    }
    forAll(g, d)
    {
        g[d].correctBoundaryConditions();
    }
    // The change of sig over dx with the gradients g0, g1, g2 along x, y, z
    auto along = []
    (
        const symmTensor& g0,
        const symmTensor& g1,
        const symmTensor& g2,
        const vector& dx
    )
    {
        return symmTensor(dx.x()*g0 + dx.y()*g1 + dx.z()*g2);
    };

    sigOwn.primitiveFieldRef() = symmTensorField(sig.primitiveField(), own);
    sigNei.primitiveFieldRef() = symmTensorField(sig.primitiveField(), nei);
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        const scalar jump = phis[P] - phis[N];
        if (mag(jump) < SMALL) continue;
        // the solid side: the owner if its phi_s is higher
        const label S = jump > 0 ? P : N;
        if (phis[S] < solid) continue;
        symmTensor& s = (S == P) ? sigOwn[facei] : sigNei[facei];
        s += mag(jump)*along(g[0][S], g[1][S], g[2][S], Cf[facei] - C[S]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const labelUList& fc = p.faceCells();
        const vectorField dP(p.Cf() - p.Cn());
        const vectorField dN(dP - p.delta());
        const scalarField phisN
        (
            phis.boundaryField()[patchi].patchNeighbourField()
        );
        symmTensorField& sO = sigOwn.boundaryFieldRef()[patchi];
        symmTensorField& sN = sigNei.boundaryFieldRef()[patchi];
        sO = sig.boundaryField()[patchi].patchInternalField();
        sN = sig.boundaryField()[patchi].patchNeighbourField();
        // the other side's gradients
        PtrList<symmTensorField> gN(3);
        forAll(gN, d)
        {
            gN.set(d, g[d].boundaryField()[patchi].patchNeighbourField());
        }
        forAll(fc, i)
        {
            const label P = fc[i];
            const scalar jump = phis[P] - phisN[i];
            if (mag(jump) < SMALL) continue;
            if (jump > 0 && phis[P] >= solid)
            {
                sO[i] += mag(jump)*along(g[0][P], g[1][P], g[2][P], dP[i]);
            }
            else if (jump < 0 && phisN[i] >= solid)
            {
                sN[i] += mag(jump)*along(gN[0][i], gN[1][i], gN[2][i], dN[i]);
            }
        }
    }
}


Foam::tmp<Foam::surfaceSymmTensorField> Foam::vheElasticity::faceStress
(
    const volSymmTensorField& sig,
    const volScalarField& muEff
) const
{
    if (stabilisation_ <= 0)
    {
        return fvc::interpolate(sig);
    }
    surfaceSymmTensorField sigOwn(fvc::interpolate(sig));
    surfaceSymmTensorField sigNei(sigOwn);
    interfaceSideStress(sig, sigOwn, sigNei);
    return faceStress(sig, muEff, sigOwn, sigNei);
}


Foam::tmp<Foam::surfaceSymmTensorField> Foam::vheElasticity::faceStress
(
    const volSymmTensorField& sig,
    const volScalarField& muEff,
    const surfaceSymmTensorField& sigOwn,
    const surfaceSymmTensorField& sigNei
) const
{
    // Each side's stress weighted by the other side's viscosity: the
    // traction that is continuous across a face between a solid and a
    // fluid cell (the linear interpolation where the viscosities are
    // equal), with the solid side's stress taken at the face
    const volScalarField m
    (
        muEff + dimensionedScalar("small", muEff.dimensions(), ROOTVSMALL)
    );
    tmp<surfaceSymmTensorField> tsf
    (
        fvc::interpolate(sig/m)/fvc::interpolate(1/m)
    );
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& lw = mesh_.weights();
    // each side's stress weighted by (its interpolation weight)/(its
    // viscosity)
    auto weighted = []
    (
        scalar w, scalar mP, scalar mN,
        const symmTensor& sP, const symmTensor& sN
    )
    {
        const scalar wP = w/mP, wN = (1 - w)/mN;
        return symmTensor((wP*sP + wN*sN)/(wP + wN));
    };
    symmTensorField& sf = tsf.ref().primitiveFieldRef();
    forAll(own, facei)
    {
        sf[facei] = weighted
        (
            lw[facei], m[own[facei]], m[nei[facei]],
            sigOwn[facei], sigNei[facei]
        );
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const scalarField& w = p.weights();
        const scalarField mP(m.boundaryField()[patchi].patchInternalField());
        const scalarField mN(m.boundaryField()[patchi].patchNeighbourField());
        const symmTensorField& sO = sigOwn.boundaryField()[patchi];
        const symmTensorField& sN = sigNei.boundaryField()[patchi];
        symmTensorField& sb = tsf.ref().boundaryFieldRef()[patchi];
        forAll(sb, i)
        {
            sb[i] = weighted(w[i], mP[i], mN[i], sO[i], sN[i]);
        }
    }
    return tsf;
}


// ************************************************************************* //
