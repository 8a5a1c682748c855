/*---------------------------------------------------------------------------*\
  vheFoam: each surface cell's interface plane (PLIC with RDF normals)
\*---------------------------------------------------------------------------*/

#include "interfacePlanes.H"
#include "vhe.h"
#include "volPointInterpolation.H"
#include "syncTools.H"
#include "globalIndex.H"
#include "coupledPolyPatch.H"
#include "profiling.H"

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


template<class Local, class Record>
void Foam::interfacePlanes::visitStencil
(
    const label c,
    const labelUList& coupledIndex,
    const List<List<scalar>>& records,
    const label width,
    labelList& stamp,
    DynamicList<scalar>& remoteSeen,
    const Local& local,
    const Record& record
) const
{
    const globalIndex& ids = cellIds_;
    remoteSeen.clear();
    stamp[c] = c;
    for (const label q : mesh_.cellPoints()[c])
    {
        const label j = coupledIndex[q];
        if (j < 0)
        {
            for (const label k : mesh_.pointCells()[q])
            {
                if (stamp[k] == c) continue;
                stamp[k] = c;
                local(k);
            }
            continue;
        }
        const List<scalar>& rl = records[j];
        for (label r = 0; r < rl.size(); r += width)
        {
            const label id = label(rl[r]);
            if (ids.isLocal(id))
            {
                const label k = ids.toLocal(id);
                if (stamp[k] == c) continue;
                stamp[k] = c;
            }
            else
            {
                if (remoteSeen.found(rl[r])) continue;
                remoteSeen.append(rl[r]);
            }
            record(&rl[r], q);
        }
    }
}


void Foam::interfacePlanes::rdfNormals(List<vector>& nNew) const
{
    const label nCells = mesh_.nCells();
    const volVectorField& C = mesh_.C();
    const pointField& pts = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    const labelListList& pointCells = mesh_.pointCells();

    // The points on processor and cyclic patches: there the cells around
    // a point are exchanged as records of the global cell id and data
    // relative to the point (frame-free); elsewhere they are read directly
    labelList coupledIndex;
    DynamicList<label> coupledPts;
    coupledPoints(coupledIndex, coupledPts);
    labelList surfIndex(nCells, -1);
    forAll(cells_, i) surfIndex[cells_[i]] = i;

    // The planes around the coupled points: id, normal, centre - point
    List<List<scalar>> planes(coupledPts.size());
    const uniqueRecords planeOp{7};
    forAll(coupledPts, j)
    {
        const label q = coupledPts[j];
        for (const label k : pointCells[q])
        {
            const label i = surfIndex[k];
            if (i < 0) continue;
            const vector r = centre_[i] - pts[q];
            planeOp
            (
                planes[j],
                List<scalar>
                ({
                    scalar(cellIds_.toGlobal(k)), normal_[i].x(),
                    normal_[i].y(), normal_[i].z(), r.x(), r.y(), r.z()
                })
            );
        }
    }
    syncTools::syncPointList
    (
        mesh_, coupledPts, planes, planeOp, List<scalar>(), noTransform()
    );

    // The cells that need the RDF: those sharing a point with a surface
    // cell, on any rank
    List<bool> band(nCells, false);
    forAll(cells_, i)
    {
        for (const label q : cellPoints[cells_[i]])
        {
            for (const label k : pointCells[q]) band[k] = true;
        }
    }
    forAll(coupledPts, j)
    {
        if (planes[j].empty()) continue;
        for (const label k : pointCells[coupledPts[j]]) band[k] = true;
    }

    // The RDF: a surface cell's own distance to its plane; in the others,
    // the mean of the distances of the planes sharing a point with the
    // cell, weighted by cos^2 of the angle between the normal and the line
    // from the plane's centre
    scalarField rdf(nCells, Zero);
    List<bool> has(nCells, false);
    labelList stamp(nCells, -1);
    DynamicList<scalar> remoteSeen;
    forAll(band, c)
    {
        if (!band[c]) continue;
        const label ic = surfIndex[c];
        if (ic >= 0)
        {
            rdf[c] = normal_[ic] & (C[c] - centre_[ic]);
            has[c] = true;
            continue;
        }
        scalar num = 0, den = 0;
        auto add = [&](const vector& n, const vector& s)
        {
            const scalar d = n & s;
            const scalar s2 = magSqr(s);
            const scalar w = s2 > VSMALL ? sqr(d)/s2 : 1;
            num += w*d;
            den += w;
        };
        visitStencil
        (
            c, coupledIndex, planes, 7, stamp, remoteSeen,
            [&](const label k)
            {
                const label i = surfIndex[k];
                if (i >= 0) add(normal_[i], C[c] - centre_[i]);
            },
            [&](const scalar* r, const label q)
            {
                add
                (
                    vector(r[1], r[2], r[3]),
                    C[c] - pts[q] - vector(r[4], r[5], r[6])
                );
            }
        );
        if (den > VSMALL)
        {
            rdf[c] = num/den;
            has[c] = true;
        }
    }

    stencilGradient(rdf, has, coupledIndex, coupledPts, nNew);
    forAll(nNew, i)
    {
        const scalar m = mag(nNew[i]);
        nNew[i] = m > SMALL ? nNew[i]/m : normal_[i];
    }
}


void Foam::interfacePlanes::stencilGradient
(
    const scalarField& f,
    const UList<bool>& has,
    const labelUList& coupledIndex,
    const labelUList& coupledPts,
    List<vector>& g
) const
{
    const label nCells = mesh_.nCells();
    const volVectorField& C = mesh_.C();
    const pointField& pts = mesh_.points();
    const labelListList& pointCells = mesh_.pointCells();

    // f around the coupled points: id, value, cell centre - point
    List<List<scalar>> recs(coupledPts.size());
    const uniqueRecords op{5};
    forAll(coupledPts, j)
    {
        const label q = coupledPts[j];
        for (const label k : pointCells[q])
        {
            if (!has[k]) continue;
            const vector r = C[k] - pts[q];
            op
            (
                recs[j],
                List<scalar>
                ({scalar(cellIds_.toGlobal(k)), f[k], r.x(), r.y(), r.z()})
            );
        }
    }
    syncTools::syncPointList
    (
        mesh_, coupledPts, recs, op, List<scalar>(), noTransform()
    );

    // The least-squares gradient over the cells that share a point with
    // the surface cell, weighted by 1/distance^2; an empty direction gets
    // a unit diagonal (its gradient 0)
    symmTensor empty(Zero);
    const Vector<label>& sD = mesh_.solutionD();
    if (sD.x() < 0) empty.xx() = 1;
    if (sD.y() < 0) empty.yy() = 1;
    if (sD.z() < 0) empty.zz() = 1;

    labelList stamp(nCells, -1);
    DynamicList<scalar> remoteSeen;
    g.setSize(cells_.size());
    forAll(cells_, i)
    {
        const label c = cells_[i];
        g[i] = Zero;
        symmTensor G(empty);
        vector b(Zero);
        auto add = [&](const vector& d, const scalar value)
        {
            const scalar w = 1/magSqr(d);
            G += w*sqr(d);
            b += w*d*(value - f[c]);
        };
        visitStencil
        (
            c, coupledIndex, recs, 5, stamp, remoteSeen,
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


void Foam::interfacePlanes::coupledPoints
(
    labelList& coupledIndex,
    DynamicList<label>& coupledPts
) const
{
    coupledIndex.setSize(mesh_.nPoints());
    coupledIndex = -1;
    coupledPts.clear();
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled()) continue;
        for (const label p : pp.meshPoints())
        {
            if (coupledIndex[p] >= 0) continue;
            coupledIndex[p] = coupledPts.size();
            coupledPts.append(p);
        }
    }
}


bool Foam::interfacePlanes::cutCell
(
    const label c,
    const scalar alpha,
    const scalar tol,
    const scalar g,
    const scalar guess,
    vhe_cut& out
) const
{
    // The cell for the C core: its points, and its faces in local point
    // indices, flipped where the cell is the face's neighbour
    const labelList& cp = mesh_.cellPoints()[c];
    const pointField& pts = mesh_.points();
    x_.setSize(3*cp.size());
    forAll(cp, i)
    {
        const point& p = pts[cp[i]];
        x_[3*i] = p.x();
        x_[3*i + 1] = p.y();
        x_[3*i + 2] = p.z();
    }
    const cell& faces = mesh_.cells()[c];
    start_.setSize(faces.size() + 1);
    flip_.setSize(faces.size());
    facePts_.clear();
    forAll(faces, k)
    {
        const label f = faces[k];
        start_[k] = facePts_.size();
        flip_[k] = mesh_.faceOwner()[f] != c;
        for (const label p : mesh_.faces()[f])
        {
            facePts_.append(cp.find(p));
        }
    }
    start_[faces.size()] = facePts_.size();

    vhe_cell cellC;
    cellC.npoints = cp.size();
    cellC.x = x_.cdata();
    cellC.nfaces = faces.size();
    cellC.face_start = start_.cdata();
    cellC.face_pts = facePts_.cdata();
    cellC.flip = flip_.cdata();
    const point& C = mesh_.C()[c];
    cellC.x0[0] = C.x();
    cellC.x0[1] = C.y();
    cellC.x0[2] = C.z();
    return
        vhe_cell_cut_fraction
        (
            &cellC, fCell_.cdata(), mesh_.V()[c], alpha, tol, g, guess, &out
        ) == 0
     && out.status == 0;
}


void Foam::interfacePlanes::cutPlanes
(
    const scalarField& a,
    const List<vector>& n,
    const scalar isoTol
)
{
    addProfiling(plic, "interfacePlanes::plic");
    const pointField& pts = mesh_.points();
    vhe_cut out;
    forAll(cells_, i)
    {
        const label c = cells_[i];
        const labelList& cp = mesh_.cellPoints()[c];
        const point& C = mesh_.C()[c];
        fCell_.setSize(cp.size());
        forAll(cp, j)
        {
            fCell_[j] = -(n[i] & (pts[cp[j]] - C));
        }
        // from the last plane's centre (Newton: the field is a plane)
        if (!cutCell(c, a[c], isoTol, 1, -(n[i] & (centre_[i] - C)), out))
        {
            continue;
        }
        if ((vector(out.area[0], out.area[1], out.area[2]) & n[i]) <= 0)
        {
            continue;
        }
        normal_[i] = n[i];
        centre_[i] = point(out.centre[0], out.centre[1], out.centre[2]);
        isoValue_[i] = out.iso;
        planar_[i] = true;
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
    cellIds_(mesh_.nCells()),
    pointValues_(pointValues)
{
    const scalarField& a = alpha.primitiveField();

    // 1. isoAdvector's isosurfaces of the point-interpolated fraction (a
    //    start from the fraction's own gradient, Youngs's normal, left the
    //    translated disk 1.6 to 1.9 times further from exact)
    {
        addProfiling(iso, "interfacePlanes::isoSurface");
        pointScalarField ap
        (
            volPointInterpolation::New(mesh_).interpolate(alpha)
        );
        interpolated_ = ap.primitiveField();
        pointValues_ = interpolated_;
        vhe_cut out;
        forAll(a, c)
        {
            if (a[c] <= surfTol || a[c] >= 1 - surfTol) continue;
            const labelList& cp = mesh_.cellPoints()[c];
            fCell_.setSize(cp.size());
            forAll(cp, j)
            {
                fCell_[j] = interpolated_[cp[j]];
            }
            if (!cutCell(c, a[c], isoTol, 0, 0, out)) continue;
            const vector A(out.area[0], out.area[1], out.area[2]);
            if (mag(A) < VSMALL) continue;
            cells_.append(c);
            normal_.append(A/mag(A));
            centre_.append(point(out.centre[0], out.centre[1], out.centre[2]));
            isoValue_.append(out.iso);
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
    List<vector> n;
    for (label pass = 0; pass < nRDF; ++pass)
    {
        {
            addProfiling(rdf, "interfacePlanes::rdf");
            rdfNormals(n);
        }
        cutPlanes(a, n, isoTol);
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
