/*---------------------------------------------------------------------------*\
  vheFoam: run-time refinement that selects the same cells on any number
  of ranks
\*---------------------------------------------------------------------------*/

#include "vheRefineFvMesh.H"
#include "argList.H"
#include "syncTools.H"
#include "volFields.H"

namespace Foam
{
    defineTypeNameAndDebug(vheRefineFvMesh, 0);
}


Foam::vheRefineFvMesh::vheRefineFvMesh(const IOobject& io)
:
    dynamicRefineFvMesh(io)
{}


template<class Type>
void Foam::vheRefineFvMesh::correctCoupled()
{
    typedef GeometricField<Type, fvPatchField, volMesh> FieldType;
    // Every rank the same fields in the same order: the exchanges pair up
    const Pstream::commsTypes comms =
        Pstream::defaultCommsType == Pstream::commsTypes::scheduled
      ? Pstream::commsTypes::blocking
      : Pstream::defaultCommsType;
    for (const word& name : sortedNames<FieldType>())
    {
        typename FieldType::Boundary& bf =
            lookupObjectRef<FieldType>(name).boundaryFieldRef();
        const label nReq = Pstream::nRequests();
        forAll(bf, patchi)
        {
            if (bf[patchi].coupled()) bf[patchi].initEvaluate(comms);
        }
        if (Pstream::parRun() && comms == Pstream::commsTypes::nonBlocking)
        {
            Pstream::waitRequests(nReq);
        }
        forAll(bf, patchi)
        {
            if (bf[patchi].coupled()) bf[patchi].evaluate(comms);
        }
    }
}


bool Foam::vheRefineFvMesh::update()
{
    const bool changed = dynamicRefineFvMesh::update();
    if (changed)
    {
        correctCoupled<scalar>();
        correctCoupled<vector>();
        correctCoupled<symmTensor>();
        correctCoupled<sphericalTensor>();
        correctCoupled<tensor>();
    }
    return changed;
}


void Foam::vheRefineFvMesh::selectRefineCandidates
(
    const scalar lowerRefineLevel,
    const scalar upperRefineLevel,
    const scalarField& vFld,
    bitSet& candidateCell
) const
{
    // The field at each point: the mean over all of its cells, the cells
    // of every rank (dynamicRefineFvMesh::cellToPoint takes the local ones)
    const labelListList& pCells = pointCells();
    scalarField sum(nPoints(), Zero), count(nPoints(), Zero);
    forAll(pCells, pointi)
    {
        for (const label celli : pCells[pointi])
        {
            sum[pointi] += vFld[celli];
        }
        count[pointi] = pCells[pointi].size();
    }
    syncTools::syncPointList(*this, sum, plusEqOp<scalar>(), scalar(0));
    syncTools::syncPointList(*this, count, plusEqOp<scalar>(), scalar(0));

    // As dynamicRefineFvMesh: a cell is a candidate when one of its points
    // lies within the levels
    const scalarField pointErr(error(sum/count, lowerRefineLevel, upperRefineLevel));
    const scalarField cellErr(maxPointField(pointErr));
    forAll(cellErr, celli)
    {
        if (cellErr[celli] > 0)
        {
            candidateCell.set(celli);
        }
    }
}


Foam::autoPtr<Foam::dynamicFvMesh> Foam::vheRefineFvMesh::New
(
    const argList& args,
    const Time& runTime
)
{
    const IOobject meshIO
    (
        dynamicFvMesh::defaultRegion, runTime.timeName(), runTime,
        IOobject::MUST_READ
    );
    IOobject dictHeader
    (
        "dynamicMeshDict", runTime.constant(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if
    (
        !args.found("dry-run") && !args.found("dry-run-write")
     && dictHeader.typeHeaderOk<IOdictionary>(true)
     && IOdictionary(dictHeader).get<word>("dynamicFvMesh")
     == dynamicRefineFvMesh::typeName
    )
    {
        Info<< "Selecting dynamicFvMesh " << dynamicRefineFvMesh::typeName
            << " (vheFoam's selection of cells: the same on any number of"
            << " ranks)" << endl;
        return autoPtr<dynamicFvMesh>(new vheRefineFvMesh(meshIO));
    }
    return dynamicFvMesh::New(args, runTime);
}


// ************************************************************************* //
