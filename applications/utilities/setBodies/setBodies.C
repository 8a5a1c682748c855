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

    // ---- Read every body (all checks before anything is written)
    DynamicList<body> bodies;
    if (!bodiesDict.isDict("bodies"))
    {
        FatalIOErrorInFunction(bodiesDict)
            << "No 'bodies' sub-dictionary" << exit(FatalIOError);
    }
    for (const entry& e : bodiesDict.subDict("bodies"))
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bodiesDict.subDict("bodies"))
                << "bodies: entry '" << e.keyword() << "' is not a dictionary"
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        const word material(d.get<word>("material"));
        const label m = solidNames.find(material);
        if (m < 0)
        {
            FatalIOErrorInFunction(d)
                << "Body " << e.keyword() << ": material '" << material
                << "' is not a solid of " << props.objectPath() << nl
                << "    Solids: " << solidNames << exit(FatalIOError);
        }

        if (d.found("packing"))
        {
            const word packing(d.get<word>("packing"));
            const scalar radius = d.get<scalar>("radius");
            const scalar gap = d.getOrDefault<scalar>("gap", 0);
            if (radius <= 0 || gap < 0)
            {
                FatalIOErrorInFunction(d)
                    << "Packing " << e.keyword()
                    << ": radius must be > 0 and gap >= 0"
                    << exit(FatalIOError);
            }
            double rlo[3], rhi[3];
            setVec(rlo, d.getOrDefault<vector>("min", bb.min()));
            setVec(rhi, d.getOrDefault<vector>("max", bb.max()));

            List<scalar> centres;
            label count = 0;
            int status = VHE_OK;
            if (packing == "lattice")
            {
                const Vector<label> n(d.get<Vector<label>>("n"));
                int ni[3] = {int(n.x()), int(n.y()), int(nDim == 2 ? 1 : n.z())};
                count = ni[0]*ni[1]*ni[2];
                centres.setSize(3*count);
                status = vhe_pack_lattice
                (
                    rlo, rhi, ni, radius, gap, nDim, centres.data()
                );
            }
            else if (packing == "random")
            {
                count = d.get<label>("count");
                const label seed = d.getOrDefault<label>("seed", 1);
                centres.setSize(3*count);
                size_t placed = 0;
                int per[3] = {periodic[0], periodic[1], periodic[2]};
                // A region smaller than the mesh is not periodic
                for (int k = 0; k < 3; ++k)
                {
                    if (rlo[k] > lo[k] + SMALL || rhi[k] < hi[k] - SMALL)
                    {
                        per[k] = 0;
                    }
                }
                status = vhe_pack_random
                (
                    rlo, rhi, per, nDim, count, radius, gap, uint64_t(seed),
                    size_t(1000000), centres.data(), &placed
                );
                if (status == VHE_ENOFIT)
                {
                    FatalIOErrorInFunction(d)
                        << "Packing " << e.keyword() << ": only " << placed
                        << " of " << count << " bodies of radius " << radius
                        << " with gap " << gap << " fit in the region"
                        << exit(FatalIOError);
                }
            }
            else
            {
                FatalIOErrorInFunction(d)
                    << "Unknown packing '" << packing << "'" << nl
                    << "    Valid packings: (lattice random)"
                    << exit(FatalIOError);
            }
            if (status != VHE_OK)
            {
                FatalIOErrorInFunction(d)
                    << "Packing " << e.keyword() << ": " << count
                    << " bodies of radius " << radius << " with gap " << gap
                    << " cannot fit in the region" << exit(FatalIOError);
            }
            for (label b = 0; b < count; ++b)
            {
                body bd;
                bd.name = e.keyword() + "_" + Foam::name(b);
                bd.material = m;
                bd.colour = 0;
                bd.shape = vhe_shape{};
                bd.shape.kind = nDim == 2 ? VHE_CYLINDER : VHE_SPHERE;
                bd.shape.axis[2] = 1;
                bd.shape.radius = radius;
                for (int k = 0; k < 3; ++k) bd.shape.centre[k] = centres[3*b+k];
                bodies.append(bd);
            }
            Info<< "Packing " << e.keyword() << ": " << count << ' '
                << packing << (nDim == 2 ? " disks" : " spheres")
                << " of radius " << radius << ", gap " << gap << nl;
        }
        else
        {
            body bd;
            bd.name = e.keyword();
            bd.material = m;
            bd.colour = 0;
            bd.shape = bodyShapes::readSetBodies(d, nDim);
            bodies.append(bd);
        }
    }

    // Bodies must lie in the mesh, except across periodic directions
    for (const body& b : bodies)
    {
        double blo[3], bhi[3];
        vhe_shape_bounds(&b.shape, blo, bhi);
        for (int k = 0; k < nDim; ++k)
        {
            const scalar tol = 1e-9*(hi[k] - lo[k]);
            const bool inside = periodic[k]
              ? (b.shape.centre[k] >= lo[k] - tol && b.shape.centre[k] <= hi[k] + tol)
              : (blo[k] >= lo[k] - tol && bhi[k] <= hi[k] + tol);
            if (!inside)
            {
                FatalIOErrorInFunction(bodiesDict)
                    << "Body " << b.name << " lies (partly) outside the mesh"
                    << " in direction " << vector::componentNames[k]
                    << ": body spans [" << blo[k] << ", " << bhi[k]
                    << "], mesh [" << lo[k] << ", " << hi[k] << "]"
                    << exit(FatalIOError);
            }
        }
    }

    // ---- Colours: per material, the entry colours or as many as the
    // bodies need plus two spares; bodies whose bounding spheres come within four cells of each
    // other take different colours (greedy, in the order given), so that
    // they never merge (vheMixture, bodyColours)
    const label nCellsAll = returnReduce(mesh.nCells(), sumOp<label>());
    scalar cellVolume = 1;
    for (int k = 0; k < nDim; ++k) cellVolume *= hi[k] - lo[k];
    const scalar h = std::pow(cellVolume/nCellsAll, 1.0/nDim);
    const label maxColours = 16;      // as vheMixture allows
    labelList nColours(solidNames.size(), 1), offset(solidNames.size(), 0);
    label nPhases = 0;
    forAll(solidNames, m)
    {
        DynamicList<label> mine;
        forAll(bodies, i)
        {
            if (bodies[i].material == m) mine.append(i);
        }
        const dictionary& sd = props.subDict("solids").subDict(solidNames[m]);
        // Without an entry: the colours the greedy colouring needs, plus
        // two spares for bodyColours to move approaching bodies to (a
        // spare colour costs nothing while no body has it: vheMixture
        // leaves empty phases out); one body, one colour
        const bool given = sd.found("colours");
        nColours[m] = given ? sd.get<label>("colours") : maxColours;
        if (nColours[m] < 1 || nColours[m] > maxColours)
        {
            FatalIOErrorInFunction(sd)
                << "colours of " << solidNames[m] << " must lie in [1, "
                << maxColours << "], got " << nColours[m]
                << exit(FatalIOError);
        }
        List<double> centre(3*mine.size()), radius(mine.size());
        List<int> colour(mine.size(), 0);
        forAll(mine, j)
        {
            const vhe_shape& sh = bodies[mine[j]].shape;
            double blo[3], bhi[3];
            vhe_shape_bounds(&sh, blo, bhi);
            scalar r2 = 0;
            for (int k = 0; k < nDim; ++k) r2 += sqr(0.5*(bhi[k] - blo[k]));
            radius[j] = std::sqrt(r2);
            for (int k = 0; k < 3; ++k)
            {
                centre[3*j + k] = k < nDim ? sh.centre[k] : 0.0;
            }
        }
        double period[3];
        for (int k = 0; k < 3; ++k)
        {
            period[k] = periodic[k] ? hi[k] - lo[k] : 0.0;
        }
        const int shared = vhe_colour_bodies
        (
            mine.size(), centre.cdata(), radius.cdata(), period, 4*h,
            nColours[m], colour.data()
        );
        forAll(mine, j) bodies[mine[j]].colour = colour[j];
        if (!given)
        {
            int used = 0;
            forAll(mine, j) used = std::max(used, colour[j] + 1);
            nColours[m] = mine.size() > 1 ? min(used + 2, maxColours) : 1;
        }
        offset[m] = nPhases;
        nPhases += nColours[m];
        Info<< "Material " << solidNames[m] << ": " << mine.size()
            << " bodies in " << nColours[m] << " colour"
            << (nColours[m] > 1 ? "s" : "");
        if (shared)
        {
            Info<< ", " << shared << " of them near a body of their colour";
        }
        Info<< nl;
    }

    // ---- Solid fractions per material and colour, by sub-cell integration
    const label nCells = mesh.nCells();
    List<scalarField> solid(nPhases, scalarField(nCells, 0));
    scalarField phis(nCells, 0);
    dictionary rigidState;
    for (const body& b : bodies)
    {
        // The body and its periodic images, drawn as the rigid bodies
        // redraw it when it moves (bodyShapes)
        DynamicList<label> cells;
        DynamicList<scalar> fraction;
        shapes.draw(b.shape, cells, fraction);
        scalar placed = 0;
        forAll(cells, i)
        {
            const label c = cells[i];
            solid[offset[b.material] + b.colour][c] += fraction[i];
            phis[c] += fraction[i];
            placed += fraction[i]*mesh.V()[c];
        }
        reduce(placed, sumOp<scalar>());
        double volume = vhe_shape_volume(&b.shape);
        if (nDim == 2 && b.shape.kind == VHE_CYLINDER)
        {
            volume *= bb.span().z();     // area times the mesh depth
        }
        if (nDim == 2 && b.shape.kind == VHE_ELLIPSOID)
        {
            volume = constant::mathematical::pi*b.shape.semi[0]
               *b.shape.semi[1]*bb.span().z();
        }
        Info<< "Body " << b.name << " (" << solidNames[b.material]
            << ", colour " << b.colour
            << "): volume " << volume << ", on the mesh " << placed << nl;

        // A rigid body's shape, pose and volume on this mesh: the solver
        // carries the shape with the body's rigid motion and redraws it
        // every step (rigidPoses)
        const dictionary& sd =
            props.subDict("solids").subDict(solidNames[b.material]);
        if (sd.getOrDefault<Switch>("rigid", false))
        {
            const unsigned precision = IOstream::defaultPrecision(17);
            dictionary bd;
            bd.add("material", solidNames[b.material]);
            bd.add("colour", b.colour);
            bd.add("shape", bodyShapes::write(b.shape));
            bd.add("volume", placed);
            bd.add("centre", bodyShapes::centre(b.shape));
            bd.add("orientation", tensor::I);
            rigidState.add(b.name, bd);
            IOstream::defaultPrecision(precision);
        }
    }

    const scalar maxPhis = gMax(phis);
    if (maxPhis > 1 + 1e-6)
    {
        FatalIOErrorInFunction(bodiesDict)
            << "Bodies overlap: the solid fraction reaches " << maxPhis
            << " > 1" << exit(FatalIOError);
    }
    phis = min(phis, scalar(1));

    // ---- Fields: read where present (for their boundary conditions)
    const wordList genericTypes(vheElasticity::patchTypes(mesh));
    auto readOrCreate = [&](const word& name) -> volScalarField*
    {
        IOobject io(name, runTime.timeName(), mesh,
                    IOobject::MUST_READ, IOobject::NO_WRITE);
        if (io.typeHeaderOk<volScalarField>(true))
        {
            return new volScalarField(io, mesh);
        }
        io.readOpt() = IOobject::NO_READ;
        return new volScalarField
        (
            io, mesh, dimensionedScalar(dimless, Zero), genericTypes
        );
    };

    PtrList<volScalarField> fluidAlphas(fluidNames.size());
    forAll(fluidNames, i)
    {
        fluidAlphas.set(i, readOrCreate("alpha." + fluidNames[i]));
        if (fluidNames.size() == 1) fluidAlphas[i].primitiveFieldRef() = 1;
    }
    // Colour k > 0 of a material: alpha.<material>.<k>, with colour 0's
    // boundary conditions; files of colours beyond the material's go
    PtrList<volScalarField> solidAlphas(nPhases);
    forAll(solidNames, m)
    {
        for (label k = 0; k < nColours[m]; ++k)
        {
            const label i = offset[m] + k;
            const word name("alpha." + solidNames[m]);
            solidAlphas.set
            (
                i,
                k == 0
              ? readOrCreate(name)
              : new volScalarField
                (
                    IOobject
                    (
                        name + "." + Foam::name(k), runTime.timeName(), mesh,
                        IOobject::NO_READ, IOobject::NO_WRITE
                    ),
                    solidAlphas[offset[m]]
                )
            );
            solidAlphas[i].primitiveFieldRef() = min(solid[i], scalar(1));
            solidAlphas[i].correctBoundaryConditions();
        }
        for (label k = nColours[m]; ; ++k)
        {
            const fileName f
            (
                runTime.timePath()
               /word("alpha." + solidNames[m] + "." + Foam::name(k))
            );
            if (!isFile(f) && !isFile(f + ".gz")) break;
            rm(f);
            rm(f + ".gz");
        }
    }

    // Fluids keep their proportions and fill what the solids leave
    scalarField fluidSum(nCells, 0);
    for (const volScalarField& a : fluidAlphas) fluidSum += a.primitiveField();
    forAll(fluidAlphas, i)
    {
        scalarField& a = fluidAlphas[i].primitiveFieldRef();
        forAll(a, c)
        {
            a[c] = fluidSum[c] > SMALL
                ? a[c]*(1 - phis[c])/fluidSum[c]
                : (i == 0 ? 1 - phis[c] : 0);
        }
        fluidAlphas[i].correctBoundaryConditions();
    }

    IOobject bio("Bstar", runTime.timeName(), mesh,
                 IOobject::MUST_READ, IOobject::NO_WRITE);
    autoPtr<volSymmTensorField> Bstar;
    if (bio.typeHeaderOk<volSymmTensorField>(true))
    {
        Bstar.reset(new volSymmTensorField(bio, mesh));
    }
    else
    {
        bio.readOpt() = IOobject::NO_READ;
        Bstar.reset
        (
            new volSymmTensorField
            (
                bio, mesh, dimensionedSymmTensor(dimless, Zero), genericTypes
            )
        );
    }
    vhe_bstar_undeformed
    (
        nCells, phis.cdata(),
        reinterpret_cast<double*>(Bstar->primitiveFieldRef().data())
    );
    Bstar->correctBoundaryConditions();

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
