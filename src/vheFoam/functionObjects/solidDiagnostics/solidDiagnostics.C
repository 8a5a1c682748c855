/*---------------------------------------------------------------------------*\
  vheFoam: solid diagnostics function object
\*---------------------------------------------------------------------------*/

#include "solidDiagnostics.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"
#include "vhe.h"

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
         "kinetic", "elastic"}
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
    solidThreshold_(0.5)
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

    if (foundObject<volSymmTensorField>("Bstar"))
    {
        const volScalarField& phis = lookupObject<volScalarField>("phis");
        const volScalarField& Ghat = lookupObject<volScalarField>("Ghat");
        const double* B = reinterpret_cast<const double*>
        (
            lookupObject<volSymmTensorField>("Bstar").primitiveField().cdata()
        );

        solidVolume = gSum(phis.primitiveField()*V);
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

    Log << type() << ' ' << name() << " write:" << nl
        << "    solid volume " << solidVolume
        << ", max |dev B| " << diag[1]
        << ", min eig B* " << diag[0]
        << ", max |det B - 1| " << diag[2] << nl
        << "    kinetic " << kinetic << " J, elastic " << elastic << " J"
        << nl << endl;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        file()
            << tab << solidVolume << tab << diag[1] << tab << diag[0]
            << tab << diag[2] << tab << kinetic << tab << elastic << endl;
    }
    return true;
}


// ************************************************************************* //
