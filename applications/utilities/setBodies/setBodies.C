/*---------------------------------------------------------------------------*\
Application
    setBodies

Description
    Places visco-hyperelastic bodies in a vheFoam case: writes the solid
    fractions alpha.<material>, reduces the fluid fractions where solid is
    placed (keeping their proportions, so the sum stays 1) and writes the
    undeformed B* = phi_s^(1/2) I.  Reads system/setBodiesDict:

    \verbatim
    maxDepth    5;              // sub-cell integration levels (optional)
    bodies
    {
        ball                    // one body
        {
            material    rubber; // a solid of constant/vheProperties
            shape       sphere; // sphere | cylinder | box | ellipsoid
            centre      (0.3 0.5 0.3);
            radius      0.2;    // sphere, cylinder
            axis        (0 0 1);// cylinder (default z)
            length      0.1;    // cylinder; omitted: infinite (a 2D disk)
            semiAxes    (a b c);// ellipsoid (axis aligned; 2D: an ellipse)
            min (x y z); max (x y z);   // box
        }
        suspension              // a packing of equal spheres or disks
        {
            material    rubber;
            packing     random; // random | lattice
            radius      0.05;
            gap         0.02;   // clearance between bodies and to walls
            count       16;     // random
            seed        1;      // random: same seed, same bodies
            n           (4 4 1);// lattice
            min (x y z); max (x y z);   // optional region, default: mesh
        }
    }
    \endverbatim

    A material's bodies are spread over its colours (alpha.<material>,
    alpha.<material>.1, ...): the entry colours of the material in
    constant/vheProperties, or as many as the colouring below needs plus
    two spares (one for a single body); bodies whose
    bounding spheres come within four cells of each other take different
    colours where the colours allow, so that they never merge.

    In a 2D case (z empty) bodies are disks (cylinders along z, infinite),
    boxes or ellipses (ellipsoids, infinite along z); packings make disks.
    Periodic (cyclic) directions are found from the mesh: bodies may cross
    them and are wrapped.  Every check is made before anything is written.
    Runs on a decomposed case with -parallel.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "cyclicPolyPatch.H"
#include "vheElasticity.H"
#include "vhe.h"
#include "bodyShapes.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

struct body
{
    word name;
    label material;     // index into solidNames
    label colour;       // the material's colour tracer
    vhe_shape shape;
};


static void setVec(double d[3], const vector& v)
{
    d[0] = v.x(); d[1] = v.y(); d[2] = v.z();
}


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Place visco-hyperelastic bodies: write alpha.<solid>, reduce the"
        " fluid fractions and write B* = phi_s^(1/2) I"
    );
    argList::addOption("dict", "file", "Alternative setBodiesDict");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const word dictName("setBodiesDict");
    #include "setSystemMeshDictionaryIO.H"
    Info<< "Reading " << dictIO.name() << nl << endl;
    IOdictionary bodiesDict(dictIO);

    IOdictionary props
    (
        IOobject("vheProperties", runTime.constant(), mesh,
                 IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    if (!props.isDict("fluids") || props.subDict("fluids").empty())
    {
        FatalIOErrorInFunction(props)
            << "No 'fluids' sub-dictionary with at least one fluid"
            << exit(FatalIOError);
    }
    const wordList fluidNames(props.subDict("fluids").toc());
    const wordList solidNames
    (
        props.isDict("solids") ? props.subDict("solids").toc() : wordList()
    );

    // Geometry of the mesh: dimension, bounds, periodic directions
    const label nDim = mesh.nSolutionD();
    if (nDim == 2 && mesh.solutionD()[vector::Z] != -1)
    {
        FatalErrorInFunction
            << "2D cases must have z as the empty direction"
            << exit(FatalError);
    }
    if (nDim == 1)
    {
        FatalErrorInFunction << "1D cases are not supported" << exit(FatalError);
    }
    const label maxDepth = bodiesDict.getOrDefault<label>("maxDepth", 5);
    const bodyShapes shapes(mesh, maxDepth);
    const boundBox& bb = shapes.bounds();
    double lo[3], hi[3];
    setVec(lo, bb.min());
    setVec(hi, bb.max());
    int periodic[3] =
        {int(shapes.periodic()[0]), int(shapes.periodic()[1]),
         int(shapes.periodic()[2])};
    Info<< "Mesh: " << nDim << "D, bounds " << bb << ", periodic in"
        << (periodic[0] ? " x" : "") << (periodic[1] ? " y" : "")
        << (periodic[2] ? " z" : "") << nl << endl;

    #include "readBodies.H"

    #include "setColours.H"

    #include "solidFractions.H"

    #include "bodyFields.H"

    // ---- Write (only now: every check has passed)
    Info<< nl << "Solid volume " << gSum(phis*mesh.V())
        << ", solid fraction max " << gMax(phis) << nl
        << "Writing";
    for (const volScalarField& a : fluidAlphas) { Info<< ' ' << a.name(); a.write(); }
    for (const volScalarField& a : solidAlphas) { Info<< ' ' << a.name(); a.write(); }
    Info<< ' ' << Bstar->name() << nl;
    Bstar->write();
    if (rigidState.size())
    {
        // <time>/uniform/rigidBodies, as the solver writes it
        IOdictionary state
        (
            IOobject
            (
                "rigidBodies", runTime.timeName(), "uniform", mesh,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            )
        );
        state.add("bodies", rigidState);
        Info<< "Writing " << state.objectPath() << nl;
        state.writeObject
        (
            IOstream::ASCII, IOstream::currentVersion,
            IOstream::UNCOMPRESSED, true
        );
    }

    Info<< "\nEnd\n" << endl;
    return 0;
}


// ************************************************************************* //
