/*---------------------------------------------------------------------------*\
  vheFoam: each surface cell's interface plane (PLIC with RDF normals)
\*---------------------------------------------------------------------------*/

#include "interfacePlanes.H"
#include "isoCutCell.H"
#include "volPointInterpolation.H"
#include "syncTools.H"
#include "globalIndex.H"
#include "coupledPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Per point, a flat list of records of `width` scalars, the first the
// record's global cell id; merging keeps one record per id (a cell's record
// reaches a point from each of the point's ranks and cyclic sides)
struct uniqueRecords
{
    label width;

    void operator()(List<scalar>& x, const List<scalar>& y) const
    {
        for (label j = 0; j < y.size(); j += width)
        {
            bool known = false;
            for (label i = 0; i < x.size() && !known; i += width)
            {
                known = x[i] == y[j];
            }
            if (known) continue;
            const label n = x.size();
            x.setSize(n + width);
            for (label k = 0; k < width; ++k) x[n + k] = y[j + k];
        }
    }
};

// The records hold no direction that a translation changes (positions are
// relative to the point), and rotational cyclics are refused
struct noTransform
{
    template<class Type>
    void operator()(const vectorTensorTransform&, const bool, List<Type>&)
    const
    {}

    template<class Type>
    void operator()(const coupledPolyPatch&, UList<Type>&) const
    {}

    template<class Type, template<class> class Container>
    void operator()(const coupledPolyPatch&, Container<Type>&) const
    {}
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::interfacePlanes::writePlane(const label c, const vector& n) const
{
    // Rises into the fraction, as the interpolated fraction does
    const point& C = mesh_.C()[c];
    const pointField& pts = mesh_.points();
    for (const label p : mesh_.cellPoints()[c])
    {
        pointValues_[p] = -(n & (pts[p] - C));
    }
}


void Foam::interfacePlanes::rdfNormals(List<vector>& nNew) const
{
    const label nCells = mesh_.nCells();
    const volVectorField& C = mesh_.C();
    const pointField& pts = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    const labelListList& pointCells = mesh_.pointCells();
    const globalIndex cellIds(nCells);

    // Each surface cell's plane at its points: id, normal, centre relative
    // to the point
    List<List<scalar>> planes(pts.size());
    const uniqueRecords planeOp{7};
    forAll(cells_, i)
    {
        const scalar id = cellIds.toGlobal(cells_[i]);
        for (const label p : cellPoints[cells_[i]])
        {
            const vector r = centre_[i] - pts[p];
            const List<scalar> rec
            ({
                id, normal_[i].x(), normal_[i].y(), normal_[i].z(),
                r.x(), r.y(), r.z()
            });
            planeOp(planes[p], rec);
        }
    }
    syncTools::syncPointList
    (
        mesh_, planes, planeOp, List<scalar>(), noTransform()
    );

    // The RDF: a surface cell's own distance to its plane; in a cell that
    // shares a point with one, the mean of the planes' distances weighted
    // by cos^2 of the angle between the normal and the line from the plane's
    // centre; at the points, as records of id, value, cell centre relative
    // to the point
    List<bool> surf(nCells, false);
    forAll(cells_, i) surf[cells_[i]] = true;
    List<List<scalar>> rdf(pts.size());
    const uniqueRecords rdfOp{5};
    DynamicList<scalar> seen;
    auto push = [&](const label c, const scalar value)
    {
        const scalar id = cellIds.toGlobal(c);
        for (const label p : cellPoints[c])
        {
            const vector r = C[c] - pts[p];
            rdfOp(rdf[p], List<scalar>({id, value, r.x(), r.y(), r.z()}));
        }
    };
    forAll(cells_, i)
    {
        push(cells_[i], normal_[i] & (C[cells_[i]] - centre_[i]));
    }
    List<bool> done(nCells, false);
    forAll(planes, p)
    {
        if (planes[p].empty()) continue;
        for (const label c : pointCells[p])
        {
            if (surf[c] || done[c]) continue;
            done[c] = true;
            scalar num = 0, den = 0;
            seen.clear();
            for (const label q : cellPoints[c])
            {
                const List<scalar>& pl = planes[q];
                for (label j = 0; j < pl.size(); j += 7)
                {
                    if (seen.found(pl[j])) continue;
                    seen.append(pl[j]);
                    const vector n(pl[j + 1], pl[j + 2], pl[j + 3]);
                    const vector s =
                        C[c] - pts[q] - vector(pl[j + 4], pl[j + 5], pl[j + 6]);
                    const scalar d = n & s;
                    const scalar s2 = magSqr(s);
                    const scalar w = s2 > VSMALL ? sqr(d)/s2 : 1;
                    num += w*d;
                    den += w;
                }
            }
            if (den > VSMALL) push(c, num/den);
        }
    }
    syncTools::syncPointList(mesh_, rdf, rdfOp, List<scalar>(), noTransform());

    // The normal: the RDF's least-squares gradient over the cells that
    // share a point with the surface cell; an empty direction gets a unit
    // diagonal (its gradient 0)
    symmTensor empty(Zero);
    const Vector<label>& sD = mesh_.solutionD();
    if (sD.x() < 0) empty.xx() = 1;
    if (sD.y() < 0) empty.yy() = 1;
    if (sD.z() < 0) empty.zz() = 1;

    nNew.setSize(cells_.size());
    forAll(cells_, i)
    {
        const label c = cells_[i];
        const scalar own = normal_[i] & (C[c] - centre_[i]);
        const scalar id = cellIds.toGlobal(c);
        nNew[i] = normal_[i];
        symmTensor G(empty);
        vector b(Zero);
        seen.clear();
        seen.append(id);
        for (const label q : cellPoints[c])
        {
            const List<scalar>& rl = rdf[q];
            const vector rc = C[c] - pts[q];
            for (label j = 0; j < rl.size(); j += 5)
            {
                if (seen.found(rl[j])) continue;
                seen.append(rl[j]);
                const vector d = vector(rl[j + 2], rl[j + 3], rl[j + 4]) - rc;
                const scalar w = 1/magSqr(d);
                G += w*sqr(d);
                b += w*d*(rl[j + 1] - own);
            }
        }
        if (mag(det(G)) < SMALL) continue;
        const vector g = inv(G) & b;
        const scalar mg = mag(g);
        if (mg < SMALL) continue;
        nNew[i] = g/mg;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfacePlanes::interfacePlanes
(
    const volScalarField& alpha,
    scalarField& pointValues,
    const scalar surfTol,
    const scalar isoTol,
    const label nRDF
)
:
    mesh_(alpha.mesh()),
    pointValues_(pointValues)
{
    const scalarField& a = alpha.primitiveField();

    // 1. isoAdvector's isosurfaces of the point-interpolated fraction
    {
        pointScalarField ap
        (
            volPointInterpolation::New(mesh_).interpolate(alpha)
        );
        interpolated_ = ap.primitiveField();
        pointValues_ = interpolated_;
        isoCutCell cut(mesh_, pointValues_);
        forAll(a, c)
        {
            if (a[c] <= surfTol || a[c] >= 1 - surfTol) continue;
            if (cut.vofCutCell(c, a[c], isoTol, 100) != 0) continue;
            const vector A = cut.isoFaceArea();
            if (mag(A) < VSMALL) continue;
            cells_.append(c);
            normal_.append(A/mag(A));
            centre_.append(cut.isoFaceCentre());
            isoValue_.append(cut.isoValue());
            planar_.append(false);
        }
    }

    // 2-4. RDF normals and the planes that cut the cells at their fractions
    if (nRDF > 0)
    {
        for (const polyPatch& pp : mesh_.boundaryMesh())
        {
            const coupledPolyPatch* cpp = isA<coupledPolyPatch>(pp);
            if (cpp && cpp->size() && !cpp->parallel())
            {
                FatalErrorInFunction
                    << "Patch " << pp.name() << " is a rotational cyclic: "
                    << "the solids' interface normals are not rotated "
                    << "across one" << exit(FatalError);
            }
        }
    }
    isoCutCell cut(mesh_, pointValues_);
    List<vector> n;
    for (label pass = 0; pass < nRDF; ++pass)
    {
        rdfNormals(n);
        forAll(cells_, i)
        {
            const label c = cells_[i];
            writePlane(c, n[i]);
            if (cut.vofCutCell(c, a[c], isoTol, 100) != 0) continue;
            if ((cut.isoFaceArea() & n[i]) <= 0) continue;
            normal_[i] = n[i];
            centre_[i] = cut.isoFaceCentre();
            isoValue_[i] = cut.isoValue();
            planar_[i] = true;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::interfacePlanes::setPointValues(const label i) const
{
    const label c = cells_[i];
    if (planar_[i])
    {
        writePlane(c, normal_[i]);
        return;
    }
    for (const label p : mesh_.cellPoints()[c])
    {
        pointValues_[p] = interpolated_[p];
    }
}


// ************************************************************************* //
