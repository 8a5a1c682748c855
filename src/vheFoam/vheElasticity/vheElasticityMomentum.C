/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the elastic terms of the momentum equation
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muElastic
(
    scalar deltaT
) const
{
    // The stress increment's viscosity where the body's stress lives
    // (vhe_body_weight): none in the cells whose centre lies a quarter of
    // a cell or more outside its outline, as their stress is none.  Their
    // faces with the body's cells keep half of it (the linear face value),
    // as their face stress keeps half of the body's.
    tmp<volScalarField> tmu
    (
        new volScalarField
        (
            "muElastic",
            dimensionedScalar("deltaT", dimTime, stressStep(deltaT))
           *mixture_.Ghat()*mixture_.phis()
        )
    );
    const auto weigh = [](scalarField& mu, const scalarField& phis)
    {
        forAll(mu, i)
        {
            mu[i] *= vhe_body_weight(phis[i]);
        }
    };
    volScalarField& mu = tmu.ref();
    const volScalarField& phis = mixture_.phis();
    weigh(mu.primitiveFieldRef(), phis.primitiveField());
    forAll(mu.boundaryField(), patchi)
    {
        weigh(mu.boundaryFieldRef()[patchi], phis.boundaryField()[patchi]);
    }
    return tmu;
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muEff
(
    scalar deltaT
) const
{
    if (semiImplicit_)
    {
        return mixture_.mu() + muElastic(deltaT);
    }
    return tmp<volScalarField>(new volScalarField("muEff", mixture_.mu()));
}


Foam::tmp<Foam::volSymmTensorField> Foam::vheElasticity::explicitStress
(
    const volVectorField& U,
    scalar deltaT
) const
{
    if (!backward_)
    {
        return sigma();
    }
    // The stress of the new step's B*, B*^(n+1) = Bhat + tau (L B* +
    // B* L^T): the part linear about phi_s^(1/2) I is the implicit
    // viscosity muElastic, the rest, tau (L A + A L^T) with A = Bhat -
    // phi_s^(1/2) I, is taken with the current velocity gradient (an
    // O(dt^2) error per step, where linearising about I would leave
    // O(dt) at finite strain)
    symmTensorField Bs(predictorBstar());
    const tensorField gradU
    (
        dev(velocityGradient(U, deltaT)().primitiveField())
    );
    const tensorField L(gradU.T());
    const scalarField& phis = mixture_.phis().primitiveField();
    const scalar tau = stressStep(deltaT);
    forAll(Bs, celli)
    {
        if (phis[celli] <= mixture_.solidFractionMin()) continue;
        const symmTensor A(Bs[celli] - sqrt(phis[celli])*I);
        Bs[celli] += tau*twoSymm(L[celli] & A);
    }
    return stressOf(Bs);
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::divSigma
(
    const volSymmTensorField& sig,
    const volScalarField& muEff
) const
{
    if (stabilisation_ <= 0)
    {
        return fvc::div(sig, "div(sigma)");
    }
    return fvc::surfaceIntegrate(mesh_.Sf() & faceStress(sig, muEff));
}


// ************************************************************************* //
