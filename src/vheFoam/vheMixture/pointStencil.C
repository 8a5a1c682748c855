/*---------------------------------------------------------------------------*\
  vheFoam: the cells that share a point with a cell, on every rank
\*---------------------------------------------------------------------------*/

#include "pointStencil.H"
#include "volFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(pointStencil, 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pointStencil::pointStencil(const fvMesh& mesh)
:
    MeshObject<fvMesh, TopologicalMeshObject, pointStencil>(mesh),
    mesh_(mesh),
    cellIds_(mesh.nCells()),
    coupledIndex_(mesh.nPoints(), -1),
    stamp_(mesh.nCells(), -1)
{
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled()) continue;
        const coupledPolyPatch& cpp = refCast<const coupledPolyPatch>(pp);
        if (cpp.size() && !cpp.parallel())
        {
            FatalErrorInFunction
                << "Patch " << pp.name() << " is a rotational cyclic: "
                << "records of the cells around its points are not rotated"
                << exit(FatalError);
        }
        for (const label p : pp.meshPoints())
        {
            if (coupledIndex_[p] >= 0) continue;
            coupledIndex_[p] = coupledPts_.size();
            coupledPts_.append(p);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::pointStencil::markAround
(
    const records& recs,
    UList<bool>& mark
) const
{
    forAll(recs, j)
    {
        if (recs[j].empty()) continue;
        for (const label k : mesh_.pointCells()[coupledPts_[j]])
        {
            mark[k] = true;
        }
    }
}


void Foam::pointStencil::gradient
(
    const scalarField& f,
    const UList<bool>& has,
    const labelUList& cells,
    List<vector>& g
) const
{
    const volVectorField& C = mesh_.C();
    const pointField& pts = mesh_.points();

    // f around the coupled points: value, cell centre - point
    const records recs
    (
        gather
        (
            5,
            [&](const label k, const label q, scalar* d)
            {
                if (!has[k]) return false;
                const vector r = C[k] - pts[q];
                d[0] = f[k];
                d[1] = r.x();
                d[2] = r.y();
                d[3] = r.z();
                return true;
            }
        )
    );

    // An empty direction gets a unit diagonal (its gradient 0)
    symmTensor empty(Zero);
    const Vector<label>& sD = mesh_.solutionD();
    if (sD.x() < 0) empty.xx() = 1;
    if (sD.y() < 0) empty.yy() = 1;
    if (sD.z() < 0) empty.zz() = 1;

    g.setSize(cells.size());
    forAll(cells, i)
    {
        const label c = cells[i];
        g[i] = Zero;
        symmTensor G(empty);
        vector b(Zero);
        auto add = [&](const vector& d, const scalar value)
        {
            const scalar w = 1/magSqr(d);
            G += w*sqr(d);
            b += w*d*(value - f[c]);
        };
        visit
        (
            c, recs, 5,
            [&](const label k)
            {
                if (has[k]) add(C[k] - C[c], f[k]);
            },
            [&](const scalar* r, const label q)
            {
                add(vector(r[2], r[3], r[4]) - (C[c] - pts[q]), r[1]);
            }
        );
        if (mag(det(G)) < SMALL) continue;
        g[i] = inv(G) & b;
    }
}


// ************************************************************************* //
