/*---------------------------------------------------------------------------*\
  vheFoam: a phase's volume, centroid, velocity and shape
\*---------------------------------------------------------------------------*/

#include "phaseStatistics.H"
#include "volFields.H"
#include "volPointInterpolation.H"
#include "isoSurfaceTopo.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(phaseStatistics, 0);
    addToRunTimeSelectionTable(functionObject, phaseStatistics, dictionary);
}
}


void Foam::functionObjects::phaseStatistics::writeFileHeader(Ostream& os)
{
    string names;
    for (const word& n : alphaNames_) names += (names.empty() ? "" : " + ") + n;
    writeHeader(os, "Volume, centroid, velocity and shape of " + names);
    writeCommented(os, "Time");
    for (const char* c : {"volume", "x", "y", "z", "Ux", "Uy", "Uz", "area",
                          "circularity"})
    {
        writeTabbed(os, c);
    }
    os << endl;
}


Foam::functionObjects::phaseStatistics::phaseStatistics
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    alphaNames_()
{
    read(dict);
    writeFileHeader(file());
}


bool Foam::functionObjects::phaseStatistics::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    if (dict.found("alphas"))
    {
        alphaNames_ = dict.get<wordList>("alphas");
    }
    else
    {
        alphaNames_ = wordList(1, dict.get<word>("alpha"));
    }
    return true;
}


bool Foam::functionObjects::phaseStatistics::execute()
{
    return true;
}


bool Foam::functionObjects::phaseStatistics::write()
{
    volScalarField alpha(lookupObject<volScalarField>(alphaNames_[0]));
    for (label k = 1; k < alphaNames_.size(); ++k)
    {
        alpha += lookupObject<volScalarField>(alphaNames_[k]);
    }
    const volVectorField& U = lookupObject<volVectorField>("U");
    const scalarField& V = mesh_.V();
    scalar vol = 0;
    vector c(Zero), u(Zero);
    forAll(alpha, i)
    {
        const scalar w = alpha[i]*V[i];
        vol += w;
        c += w*mesh_.C()[i];
        u += w*U[i];
    }
    // The interface: the alpha = 1/2 iso-surface of the cell values and
    // their interpolates to the points (a ribbon of the mesh's thickness
    // in 2D).  (The integral of |grad alpha| overestimates it by the
    // diffuse edge's spread: 1.3 % for a circle at 20 cells per radius.)
    const pointScalarField alphap
    (
        volPointInterpolation::New(mesh_).interpolate(alpha)
    );
    const isoSurfaceTopo iso
    (
        mesh_, alpha.primitiveField(), alphap.primitiveField(), 0.5
    );
    scalar area = 0;
    forAll(iso, facei)
    {
        area += iso[facei].mag(iso.points());
    }
    reduce(vol, sumOp<scalar>());
    reduce(area, sumOp<scalar>());
    reduce(c, sumOp<vector>());
    reduce(u, sumOp<vector>());
    c /= max(vol, VSMALL);
    u /= max(vol, VSMALL);

    // Circle (2D: the mesh is one cell thick, t, in its empty direction;
    // vol = A t, area = P t) or sphere of the phase's volume
    scalar circ = 0;
    if (mesh_.nSolutionD() == 2)
    {
        const boundBox& bb = mesh_.bounds();
        scalar t = 1;
        for (direction d = 0; d < 3; ++d)
        {
            if (mesh_.geometricD()[d] < 0) t = bb.span()[d];
        }
        circ = 2*sqrt(constant::mathematical::pi*vol*t)/max(area, VSMALL);
    }
    else
    {
        circ = cbrt(36*constant::mathematical::pi*sqr(vol))/max(area, VSMALL);
    }

    Log << type() << ' ' << name() << " write: volume " << vol
        << " centroid " << c << " velocity " << u
        << " circularity " << circ << endl;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        file() << tab << vol;
        for (direction d = 0; d < 3; ++d) file() << tab << c[d];
        for (direction d = 0; d < 3; ++d) file() << tab << u[d];
        file() << tab << area << tab << circ << endl;
    }
    return true;
}


// ************************************************************************* //
