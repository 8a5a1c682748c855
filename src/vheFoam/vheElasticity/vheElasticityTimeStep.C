/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the elastic Courant number and time step
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

Foam::tmp<Foam::scalarField> Foam::vheElasticity::sumMagSfByV() const
{
    return fvc::surfaceSum(mesh_.magSf())().primitiveField()/mesh_.V();
}


Foam::scalar Foam::vheElasticity::courantNo(scalar deltaT) const
{
    double co = 0;
    vhe_elastic_dt
    (
        mesh_.nCells(), mixture_.Ghat().primitiveField().cdata(),
        mixture_.phis().primitiveField().cdata(),
        mixture_.rho().primitiveField().cdata(), sumMagSfByV()().cdata(),
        1, deltaT, &co
    );
    return returnReduce(scalar(co), maxOp<scalar>());
}


Foam::scalar Foam::vheElasticity::maxDeltaT(scalar maxCo) const
{
    const double dt = vhe_elastic_dt
    (
        mesh_.nCells(), mixture_.Ghat().primitiveField().cdata(),
        mixture_.phis().primitiveField().cdata(),
        mixture_.rho().primitiveField().cdata(), sumMagSfByV()().cdata(),
        maxCo, 1, nullptr
    );
    return returnReduce(scalar(dt < VGREAT ? dt : VGREAT), minOp<scalar>());
}


// ************************************************************************* //
