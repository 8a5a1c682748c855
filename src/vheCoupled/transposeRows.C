/*---------------------------------------------------------------------------*\
  vheFoam: the coupled step's rows of the stress increment's transpose part
\*---------------------------------------------------------------------------*/

#include "transposeRows.H"
#include "implicitTranspose.H"
#include "surfaceFields.H"
#include "fvc.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

Foam::label Foam::transposeRows::width
(
    const fvMesh& mesh,
    const scalarField& muT,
    const label celli
)
{
    const cellList& cells = mesh.cells();
    const labelListList& cellCells = mesh.cellCells();
    bool wide = muT[celli] > 0;
    for (const label c : cellCells[celli])
    {
        wide = wide || muT[c] > 0;
    }
    if (!wide)
    {
        return cells[celli].size() + 1;
    }
    DynamicList<label> ring;
    ring.append(celli);
    for (const label c : cellCells[celli])
    {
        if (!ring.found(c)) ring.append(c);
        for (const label c2 : cellCells[c])
        {
            if (!ring.found(c2)) ring.append(c2);
        }
    }
    // the boundary faces' (coupled patches': other ranks' cells) too
    return ring.size() + cells[celli].size() - cellCells[celli].size();
}


void Foam::transposeRows::add
(
    const fvMesh& mesh,
    const volScalarField& muT,
    const volVectorField& U,
    const labelList& cmpts,
    const label start0,
    Mat A,
    Vec b
)
{
    const label nC = mesh.nCells();
    const label nd = cmpts.size();
    const label nb = nd + 1;

    // Each row cell's column cells and 3 x 3 blocks (j, i)
    List<DynamicList<label>> cols(nC);
    List<DynamicList<tensor>> blocks(nC);
    implicitTranspose::coefficients
    (
        mesh, muT.primitiveField(),
        [&](label P, direction j, label c, direction i, scalar v)
        {
            DynamicList<label>& cp = cols[P];
            label k = cp.find(c);
            if (k < 0)
            {
                k = cp.size();
                cp.append(c);
                blocks[P].append(tensor::zero);
            }
            blocks[P][k][3*j + i] += v;
        }
    );

    // The whole explicit term, integrated over each cell
    const vectorField whole
    (
        mesh.V()
       *fvc::div
        (
            muT*dev2(T(fvc::grad(U))), "div((mu*dev2(T(grad(U)))))"
        )().primitiveField()
    );

    List<PetscInt> rows(nd), colIdx;
    List<PetscScalar> vals;
    for (label P = 0; P < nC; ++P)
    {
        const label n = cols[P].size();
        vector part(Zero);
        colIdx.setSize(n*nd);
        vals.setSize(nd*n*nd);
        for (label k = 0; k < nd; ++k)
        {
            rows[k] = PetscInt((start0 + P)*nb + k);
        }
        for (label m = 0; m < n; ++m)
        {
            const label c = cols[P][m];
            const tensor& B = blocks[P][m];
            part += B & U[c];
            for (label l = 0; l < nd; ++l)
            {
                colIdx[m*nd + l] = PetscInt((start0 + c)*nb + l);
                for (label k = 0; k < nd; ++k)
                {
                    vals[k*n*nd + m*nd + l] = -B[3*cmpts[k] + cmpts[l]];
                }
            }
        }
        if (n && A)
        {
            MatSetValues
            (
                A, nd, rows.cdata(), n*nd, colIdx.cdata(), vals.cdata(),
                ADD_VALUES
            );
        }
        for (label k = 0; k < nd; ++k)
        {
            PetscScalar r = whole[P][cmpts[k]] - part[cmpts[k]];
            VecSetValues(b, 1, &rows[k], &r, ADD_VALUES);
        }
    }
}


// ************************************************************************* //
