/*---------------------------------------------------------------------------*\
  vheFoam: per-body output function object
\*---------------------------------------------------------------------------*/

#include "bodies.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"
#include "ListOps.H"
#include "vheMixture.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bodies, 0);
    addToRunTimeSelectionTable(functionObject, bodies, dictionary);
}
}


namespace
{
    void writeVector(Foam::Ostream& os, const Foam::vector& v)
    {
        for (Foam::direction d = 0; d < Foam::vector::nComponents; ++d)
        {
            os << Foam::tab << v[d];
        }
    }
}


void Foam::functionObjects::bodies::writeFileHeader(Ostream& os)
{
    writeHeader(os, "vheFoam bodies: one row per body per write");
    writeHeaderValue(os, "threshold", threshold_);
    writeCommented(os, "Time");
    for
    (
        const char* col :
        {"id", "material", "colour", "volume", "centroid_x", "centroid_y",
         "centroid_z", "U_x", "U_y", "U_z", "omega_x", "omega_y", "omega_z",
         "D", "axis_x", "axis_y", "axis_z", "maxDevB", "gap"}
    )
    {
        writeTabbed(os, col);
    }
    os << endl;
}


Foam::functionObjects::bodies::bodies
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    threshold_(dict.getOrDefault<scalar>("threshold", 0.5)),
    regions_(mesh_, threshold_),
    last_(),
    lastTime_(0),
    nextId_(0)
{
    read(dict);
    writeFileHeader(file());
}


bool Foam::functionObjects::bodies::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    threshold_ = dict.getOrDefault<scalar>("threshold", 0.5);
    if (threshold_ <= 0 || threshold_ >= 1)
    {
        FatalIOErrorInFunction(dict)
            << "threshold must lie in (0, 1), got " << threshold_
            << exit(FatalIOError);
    }
    regions_.setThreshold(threshold_);
    return true;
}


bool Foam::functionObjects::bodies::execute()
{
    return true;
}


bool Foam::functionObjects::bodies::write()
{
    if (!foundObject<vheMixture>("vheProperties"))
    {
        return true;
    }
    const vheMixture& mixture = lookupObject<vheMixture>("vheProperties");

    DynamicList<body> found;
    DynamicList<List<point>> surface;
    // Material m's bodies over all its colours
    label m = -1;
    forAll(mixture.phases(), i)
    {
        const vheMixture::phase& p = mixture.phases()[i];
        if (p.solid)
        {
            if (p.colour == 0) ++m;
            findBodies(mixture.alphas()[i], m, p.colour, found, surface);
        }
    }

    List<body> all;
    all.transfer(found);
    number(all);
    gaps(all, surface);

    // Rows by id
    labelList order(all.size());
    forAll(all, i) { order[i] = all[i].id; }
    order = sortedOrder(order);

    Log << type() << ' ' << name() << " write: " << all.size()
        << " bodies" << nl << endl;

    if (Pstream::master())
    {
        for (const label i : order)
        {
            const body& b = all[i];
            writeCurrentTime(file());
            file() << tab << b.id << tab << b.material << tab << b.colour
                << tab << b.volume;
            writeVector(file(), b.centroid);
            writeVector(file(), b.U);
            writeVector(file(), b.omega);
            file() << tab << b.D;
            writeVector(file(), b.axis);
            file() << tab << b.maxDevB << tab << b.gap << endl;
        }
    }

    last_.transfer(all);
    lastTime_ = time_.value();
    return true;
}


// ************************************************************************* //
