/*---------------------------------------------------------------------------*\
  vheFoam: each cell's faces as compressed rows
\*---------------------------------------------------------------------------*/

#include "cellFaceRows.H"

namespace Foam
{
    defineTypeNameAndDebug(cellFaceRows, 0);
}

Foam::cellFaceRows::cellFaceRows(const fvMesh& mesh)
:
    MeshObject<fvMesh, Foam::TopologicalMeshObject, cellFaceRows>(mesh),
    start_(mesh.nCells() + 1, long(0)),
    faces_(2*mesh.nInternalFaces() + mesh.nBoundaryFaces())
{
    const label nInt = mesh.nInternalFaces();
    label j = 0;
    forAll(mesh.cells(), c)
    {
        start_[c] = j;
        for (const label f : mesh.cells()[c])
        {
            if (f < nInt) faces_[j++] = f;
        }
        for (const label f : mesh.cells()[c])
        {
            if (f >= nInt) faces_[j++] = f;
        }
    }
    start_[mesh.nCells()] = j;
}
