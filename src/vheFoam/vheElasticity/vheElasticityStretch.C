/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the upper-convected stretch of B*
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvc.H"
#include "vhe.h"
#include "vheFlat.H"

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
        // linear interpolation across a coupled patch, else the boundary
        // value (fvc::interpolate's)
        const vectorField uf
        (
            Up.coupled()
          ? vectorField
            (
                p.weights()*Up.patchInternalField()
              + (1 - p.weights())*Up.patchNeighbourField()
            )
          : vectorField(Up)
        );
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
