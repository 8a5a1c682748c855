/*---------------------------------------------------------------------------*\
  vheFoam: liquid level function object
\*---------------------------------------------------------------------------*/

#include "liquidLevel.H"
#include "volFields.H"
#include "uniformDimensionedFields.H"
#include "boundBox.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(liquidLevel, 0);
    addToRunTimeSelectionTable(functionObject, liquidLevel, dictionary);
}
}


void Foam::functionObjects::liquidLevel::findColumns()
{
    columnCells_.setSize(locations_.size());
    columnHeights_.setSize(locations_.size());

    const pointField& pts = mesh_.points();
    const labelListList& cellPts = mesh_.cellPoints();

    forAll(locations_, i)
    {
        const point& p = locations_[i];
        DynamicList<label> cells;
        DynamicList<scalar> heights;
        forAll(cellPts, c)
        {
            const boundBox bb(pts, cellPts[c], false);
            bool inside = true;
            for (direction d = 0; d < 3; ++d)
            {
                if (d == up_) continue;
                // half-open, so a location on a face counts once
                inside = inside && p[d] >= bb.min()[d] && p[d] < bb.max()[d];
            }
            if (inside)
            {
                cells.append(c);
                heights.append(bb.max()[up_] - bb.min()[up_]);
            }
        }
        columnCells_[i].transfer(cells);
        columnHeights_[i].transfer(heights);

        if (returnReduce(columnCells_[i].size(), sumOp<label>()) == 0)
        {
            FatalErrorInFunction
                << name() << ": location " << p << " is outside the mesh"
                << exit(FatalError);
        }
    }
}


void Foam::functionObjects::liquidLevel::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Liquid level: integral of " + alphaName_ + " along -g");
    forAll(locations_, i)
    {
        writeHeaderValue(os, "location " + Foam::name(i), locations_[i]);
    }
    writeCommented(os, "Time");
    forAll(locations_, i)
    {
        writeTabbed(os, "h" + Foam::name(i));
    }
    os << endl;
}


Foam::functionObjects::liquidLevel::liquidLevel
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    alphaName_("alpha.liquid"),
    up_(2)
{
    read(dict);
    writeFileHeader(file());
}


bool Foam::functionObjects::liquidLevel::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    alphaName_ = dict.getOrDefault<word>("alpha", "alpha.liquid");
    locations_ = dict.get<pointField>("locations");

    const uniformDimensionedVectorField& g =
        mesh_.time().lookupObject<uniformDimensionedVectorField>("g");
    const vector gv(g.value());
    const vector ga(cmptMag(gv));
    up_ = findMax(List<scalar>({ga.x(), ga.y(), ga.z()}));
    if (mag(gv) < SMALL || ga[up_] < (1 - 1e-9)*mag(gv))
    {
        FatalIOErrorInFunction(dict)
            << name() << ": gravity " << gv << " must be non-zero and along"
            << " a coordinate axis" << exit(FatalIOError);
    }
    findColumns();
    return true;
}


bool Foam::functionObjects::liquidLevel::execute()
{
    return true;
}


bool Foam::functionObjects::liquidLevel::write()
{
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);

    scalarField h(locations_.size(), 0);
    forAll(locations_, i)
    {
        forAll(columnCells_[i], k)
        {
            h[i] += alpha[columnCells_[i][k]]*columnHeights_[i][k];
        }
    }
    reduce(h, sumOp<scalarField>());

    Log << type() << ' ' << name() << " write: h = " << h << endl;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        for (const scalar hi : h) file() << tab << hi;
        file() << endl;
    }
    return true;
}


// ************************************************************************* //
