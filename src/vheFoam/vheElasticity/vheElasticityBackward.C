/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  second-order (backward, BDF2) time integration
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

Foam::scalar Foam::vheElasticity::backwardCoefficients
(
    scalar& carry
) const
{
    // OpenFOAM's backward scheme, coefft B^(n+1) - coefft0 B^n + coefft00
    // B^(n-1) = dt S^(n+1), as B^(n+1) - B^n = carry (B^n - B^(n-1)) +
    // (dt/coefft) S^(n+1), carry = coefft00/coefft.  Its first step (time
    // index < 2), and the Euler scheme: coefft 1, carry 0.
    carry = 0;
    if (!backward_ || mesh_.time().timeIndex() < 2)
    {
        return 1;
    }
    const scalar dt = mesh_.time().deltaTValue();
    const scalar dt0 = mesh_.time().deltaT0Value();
    const scalar coefft = 1 + dt/(dt + dt0);
    carry = dt*dt/(dt0*(dt + dt0))/coefft;
    return coefft;
}


Foam::scalar Foam::vheElasticity::stressStep(scalar deltaT) const
{
    scalar carry;
    return deltaT/backwardCoefficients(carry);
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::explicitVelocity
(
    const volVectorField& U,
    bool firstIter
) const
{
    if (!backward_ || !firstIter || mesh_.time().timeIndex() < 2)
    {
        return U;
    }
    // U^n + dt/dt0 (U^n - U^(n-1)): second-order at the new time
    const scalar ratio =
        mesh_.time().deltaTValue()/mesh_.time().deltaT0Value();
    const volVectorField& U0 = U.oldTime();
    return tmp<volVectorField>
    (
        new volVectorField("Uexplicit", U0 + ratio*(U0 - U0.oldTime()))
    );
}


Foam::tmp<Foam::symmTensorField> Foam::vheElasticity::predictorBstar() const
{
    tmp<symmTensorField> tB(new symmTensorField(Bstar_.primitiveField()));
    scalar carry;
    backwardCoefficients(carry);
    if (carry > 0)
    {
        tB.ref() += carry*increment_->oldTime().primitiveField();
    }
    return tB;
}


// ************************************************************************* //
