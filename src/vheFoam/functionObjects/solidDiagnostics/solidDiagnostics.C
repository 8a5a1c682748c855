/*---------------------------------------------------------------------------*\
  vheFoam: solid diagnostics function object
\*---------------------------------------------------------------------------*/

#include "solidDiagnostics.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"
#include "vhe.h"
#include "fvc.H"
#include "uniformDimensionedFields.H"
#include "vheMixture.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(solidDiagnostics, 0);
    addToRunTimeSelectionTable(functionObject, solidDiagnostics, dictionary);
}
}


void Foam::functionObjects::solidDiagnostics::writeFileHeader(Ostream& os)
{
    writeHeader(os, "vheFoam solid diagnostics");
    writeHeaderValue(os, "solidThreshold", solidThreshold_);
    writeCommented(os, "Time");
    for
    (
        const char* col :
        {"solidVolume", "maxDevB", "minEigBstar", "maxDetDrift",
         "kinetic", "elastic", "potential", "total", "dissipated",
         "balance", "centroid_x", "centroid_y", "centroid_z",
         "solidU_x", "solidU_y", "solidU_z"}
    )
    {
        writeTabbed(os, col);
    }
    os << endl;
}


Foam::functionObjects::solidDiagnostics::solidDiagnostics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    solidThreshold_(0.5),
    dissipated_(0)
{
    read(dict);
    writeFileHeader(file());
}


bool Foam::functionObjects::solidDiagnostics::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    solidThreshold_ = dict.getOrDefault<scalar>("solidThreshold", 0.5);
    if (solidThreshold_ <= 0 || solidThreshold_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "solidThreshold must lie in (0, 1), got " << solidThreshold_
            << exit(FatalIOError);
    }
    return true;
}


bool Foam::functionObjects::solidDiagnostics::execute()
{
    // Every step: the viscous dissipation rate integral of 2 mu D:D at the
    // end of the step, times the step
    const volScalarField& mu = lookupObject<volScalarField>("mu");
    const volVectorField& U = lookupObject<volVectorField>("U");
    const volSymmTensorField D(symm(fvc::grad(U)));
    dissipated_ += mesh_.time().deltaTValue()
       *gSum(2*mu.primitiveField()*(D.primitiveField() && D.primitiveField())
            *mesh_.V());
    return true;
}


bool Foam::functionObjects::solidDiagnostics::write()
{
    const volScalarField& rho = lookupObject<volScalarField>("rho");
    const volVectorField& U = lookupObject<volVectorField>("U");
    const scalarField& V = mesh_.V();
    const label n = mesh_.nCells();

    scalarField e(n);
    vhe_kinetic_energy
    (
        n, rho.primitiveField().cdata(),
        reinterpret_cast<const double*>(U.primitiveField().cdata()), e.data()
    );
    const scalar kinetic = gSum(e*V);

    scalar solidVolume = 0, elastic = 0;
    double diag[3] = {0, 0, 0};
    vector centroid(Zero), solidU(Zero);

    if (foundObject<volSymmTensorField>("Bstar"))
    {
        const volScalarField& phis = lookupObject<volScalarField>("phis");
        const volScalarField& Ghat = lookupObject<volScalarField>("Ghat");
        const double* B = reinterpret_cast<const double*>
        (
            lookupObject<volSymmTensorField>("Bstar").primitiveField().cdata()
        );

        solidVolume = gSum(phis.primitiveField()*V);
        if (solidVolume > VSMALL)
        {
            centroid = gSum(phis.primitiveField()*V*mesh_.C().primitiveField())
                /solidVolume;
            solidU = gSum(phis.primitiveField()*V*U.primitiveField())
                /solidVolume;
        }
        vhe_elastic_energy
        (
            n, Ghat.primitiveField().cdata(), phis.primitiveField().cdata(),
            B, e.data()
        );
        elastic = gSum(e*V);
        vhe_solid_diagnostics
        (
            n, phis.primitiveField().cdata(), B, solidThreshold_, diag
        );
        reduce(diag[0], minOp<scalar>());
        reduce(diag[1], maxOp<scalar>());
        reduce(diag[2], maxOp<scalar>());
    }

    // Potential energy of gravity and the body force per unit mass
    vector a(Zero);
    if (time_.foundObject<uniformDimensionedVectorField>("g"))
    {
        a += time_.lookupObject<uniformDimensionedVectorField>("g").value();
    }
    if (foundObject<vheMixture>("vheProperties"))
    {
        a += lookupObject<vheMixture>("vheProperties").bodyForce().value();
    }
    const scalar potential =
        -gSum(rho.primitiveField()*(mesh_.C().primitiveField() & a)*V);
    const scalar total = kinetic + elastic + potential;

    Log << type() << ' ' << name() << " write:" << nl
        << "    solid volume " << solidVolume
        << ", max |dev B| " << diag[1]
        << ", min eig B* " << diag[0]
        << ", max |det B - 1| " << diag[2] << nl
        << "    centroid " << centroid << ", velocity " << solidU << nl
        << "    kinetic " << kinetic << " J, elastic " << elastic
        << " J, potential " << potential << " J, dissipated " << dissipated_
        << " J, balance " << total + dissipated_ << " J" << nl << endl;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        file()
            << tab << solidVolume << tab << diag[1] << tab << diag[0]
            << tab << diag[2] << tab << kinetic << tab << elastic
            << tab << potential << tab << total << tab << dissipated_
            << tab << total + dissipated_;
        for (const vector& v : {centroid, solidU})
        {
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                file() << tab << v[d];
            }
        }
        file() << endl;
    }
    return true;
}


// ************************************************************************* //
