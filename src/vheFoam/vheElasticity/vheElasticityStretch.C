/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the upper-convected stretch of B*
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvc.H"
#include "vhe.h"
#include "vheFlat.H"
#include "linearFaceValues.H"
#include "syncTools.H"

#include <functional>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::tmp<Foam::tensorField> Foam::vheElasticity::solidVelocityGradient
(
    const volVectorField& U,
    const labelUList& cells
) const
{
    // velocityGradient's Gauss gradient (linear face velocity, its normal
    // component the flux phi/|S_f|) at the given cells only, summed over
    // their faces: the stretch needs it where there is solid, a few
    // percent of a scene's cells
    labelList index(mesh_.nCells(), -1);
    forAll(cells, i)
    {
        index[cells[i]] = i;
    }
    tmp<tensorField> tg(new tensorField(cells.size(), Zero));
    tensorField& g = tg.ref();
    const surfaceScalarField& phi = mixture_.phi();
    const vectorField& Sf = mesh_.Sf();
    const scalarField& w = mesh_.weights();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& u = U.primitiveField();
    const auto faceTerm = [](const vector& S, vector uf, scalar flux)
    {
        uf += (flux - (S & uf))/magSqr(S)*S;
        return S*uf;
    };
    forAll(own, f)
    {
        const label o = index[own[f]], n = index[nei[f]];
        if (o < 0 && n < 0) continue;
        const tensor t
        (
            faceTerm
            (
                Sf[f], w[f]*u[own[f]] + (1 - w[f])*u[nei[f]], phi[f]
            )
        );
        if (o >= 0) g[o] += t;
        if (n >= 0) g[n] -= t;
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        if (!p.size()) continue;
        const labelUList& fc = p.faceCells();
        const vectorField& Sp = mesh_.Sf().boundaryField()[patchi];
        const scalarField& phip = phi.boundaryField()[patchi];
        // fvc::interpolate's face values
        const vectorField uf(linearFaceValues(Up));
        forAll(fc, i)
        {
            const label o = index[fc[i]];
            if (o >= 0) g[o] += faceTerm(Sp[i], uf[i], phip[i]);
        }
    }
    forAll(cells, i)
    {
        g[i] /= mesh_.V()[cells[i]];
    }
    return tg;
}


void Foam::vheElasticity::bodyEdgeGradient
(
    const labelUList& cells,
    tensorField& g
) const
{
    // A cell of a body's edge that is mostly fluid (w(phi_s) = 0,
    // vhe_body_weight: its centre a quarter of a cell or more outside the
    // outline) carries no elastic stress, but keeps B* for when the body
    // moves over its centre.  Its velocity gradient is the fluid's shear,
    // which the body's material in it does not feel (no-slip puts the
    // shear in the fluid beside the body): stretched by it, the material
    // recorded the fluid's slide past the body as a strain that never
    // relaxes, and brought it into the body as a jolt of G times it when
    // its cell's share of the stress came on (a stiff disk in the
    // lid-driven cavity, G/(rho U^2) = 1e8, spun up to 2.7e4 times the lid
    // speed).  So there the material takes the strain rate of the body's
    // cells beside it, weighted by their phi_s (the solid extrapolated
    // into its edge, as the reference map technique does; Kamrin, Rycroft
    // and Nave 2012).  Only there: a cell with a share of the stress has
    // the stress increment's viscosity on its own velocity gradient in the
    // momentum equation, and its B* must take the same gradient, or the
    // stress it keeps is not the one the step applied (an explicit elastic
    // stress: a cavity disk at 1e8 spun up to 1441 times the lid speed
    // with the extrapolation up to phi_s = 1/2).  Cells without such a
    // neighbour (a body thinner than a cell) keep their own.
    const auto inBody = [](const scalar p)
    {
        return vhe_body_weight(p) > 0;
    };
    const scalarField& phis = mixture_.phis().primitiveField();
    labelList index(mesh_.nCells(), -1);
    forAll(cells, i)
    {
        index[cells[i]] = i;
    }
    tensorField sum(cells.size(), Zero);
    scalarField wsum(cells.size(), Zero);
    const auto take = [&](label i, scalar w, const tensor& t)
    {
        sum[i] += w*t;
        wsum[i] += w;
    };
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(own, f)
    {
        const label o = index[own[f]], n = index[nei[f]];
        if (o < 0 || n < 0) continue;
        const scalar po = phis[own[f]], pn = phis[nei[f]];
        if (!inBody(po) && inBody(pn)) take(o, pn, g[n]);
        if (!inBody(pn) && inBody(po)) take(n, po, g[o]);
    }

    // Across coupled patches: the other side's phi_s and gradient
    const label nInt = mesh_.nInternalFaces();
    scalarField bPhis(mesh_.nBoundaryFaces(), -1);
    tensorField bG(mesh_.nBoundaryFaces(), Zero);
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const auto forCoupledFaces = [&]
    (
        const std::function<void(label cell, label i, label b)>& visit
    )
    {
        forAll(pbm, patchi)
        {
            if (!pbm[patchi].coupled()) continue;
            const labelUList& fc = pbm[patchi].faceCells();
            const label b0 = pbm[patchi].start() - nInt;
            forAll(fc, j)
            {
                if (index[fc[j]] >= 0) visit(fc[j], index[fc[j]], b0 + j);
            }
        }
    };
    forCoupledFaces
    (
        [&](label c, label i, label b)
        {
            bPhis[b] = phis[c];
            bG[b] = g[i];
        }
    );
    syncTools::swapBoundaryFaceList(mesh_, bPhis);
    syncTools::swapBoundaryFaceList(mesh_, bG);
    forCoupledFaces
    (
        [&](label c, label i, label b)
        {
            if (!inBody(phis[c]) && inBody(bPhis[b])) take(i, bPhis[b], bG[b]);
        }
    );

    forAll(g, i)
    {
        if (wsum[i] > 0) g[i] = sum[i]/wsum[i];
    }
}


void Foam::vheElasticity::stretch(const volVectorField& U, scalar deltaT)
{
    // The flow is incompressible, but the cell gradient of U (interpolated
    // from cell values) is not exactly traceless, least of all where the
    // velocity changes fast (a heavy body hitting a wall): stretch with its
    // deviatoric part, so that det(F) = 1 and det B stays 1.  (dev, not the
    // trace over the solved directions only: the stress increment that the
    // semi-implicit momentum equation takes, Ghat phi_s dt (L + L^T -
    // 2/3 tr(L) I), is then exactly the increment of the stretched B*.)
    if (!backward_ && stabilisation_ <= 0)
    {
        // Only the cells that carry a deformation (B* is 0 elsewhere)
        const scalarField& phis = mixture_.phis().primitiveField();
        DynamicList<label> cells(phis.size()/8);
        forAll(phis, c)
        {
            if (phis[c] > mixture_.solidFractionMin()) cells.append(c);
        }
        tensorField gradU(solidVelocityGradient(U, cells));
        gradU = dev(gradU);
        bodyEdgeGradient(cells, gradU);
        symmTensorField Bs(Bstar_.primitiveField(), cells);
        vhe_stretch(cells.size(), deltaT, flat(gradU), flat(Bs));
        symmTensorField& B = Bstar_.primitiveFieldRef();
        forAll(cells, i)
        {
            B[cells[i]] = Bs[i];
        }
        return;
    }
    volTensorField gradU(velocityGradient(U, deltaT));
    gradU.primitiveFieldRef() = dev(gradU.primitiveField());
    if (!backward_)
    {
        vhe_stretch
        (
            mesh_.nCells(), deltaT, flat(gradU.primitiveField()),
            flat(Bstar_.primitiveFieldRef())
        );
        return;
    }
    // BDF2: B* - tau (L B* + B* L^T) = B*_advected + carry x the last
    // step's increment (the constant-step form: 3 B^(n+1) - 4 B^n +
    // B^(n-1) = 2 dt (L B + B L^T)^(n+1), B^n here already advected)
    const symmTensorField advected(Bstar_.primitiveField());
    const symmTensorField Bhat(predictorBstar());
    const size_t singular = vhe_stretch_implicit
    (
        mesh_.nCells(), stressStep(deltaT), flat(gradU.primitiveField()),
        flat(Bhat), flat(Bstar_.primitiveFieldRef())
    );
    const label nSingular = returnReduce(label(singular), sumOp<label>());
    if (nSingular)
    {
        WarningInFunction
            << nSingular << " cells with a singular BDF2 stretch (velocity"
            << " gradient x time step too large): B* kept" << endl;
    }
    increment_->primitiveFieldRef() = Bstar_.primitiveField() - advected;
}

// ************************************************************************* //
