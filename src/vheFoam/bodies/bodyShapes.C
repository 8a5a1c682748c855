/*---------------------------------------------------------------------------*\
  vheFoam: a body's shape drawn on the mesh
\*---------------------------------------------------------------------------*/

#include "bodyShapes.H"
#include "cyclicPolyPatch.H"
#include "volMesh.H"
#include <cmath>

namespace
{
    void setVec(double d[3], const Foam::vector& v)
    {
        d[0] = v.x(); d[1] = v.y(); d[2] = v.z();
    }

    Foam::vector getVec(const double d[3])
    {
        return Foam::vector(d[0], d[1], d[2]);
    }
}


Foam::bodyShapes::bodyShapes(const fvMesh& mesh, const label maxDepth)
:
    mesh_(mesh),
    maxDepth_(maxDepth),
    nDim_(mesh.nSolutionD()),
    bounds_(mesh.points(), true),
    periodic_(Zero),
    boxTimeIndex_(-1)
{
    // The cyclic directions: a cyclic patch's normal (as setBodies has
    // always found them)
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<cyclicPolyPatch>(pp))
        {
            const vector s = cmptMag(gSum(pp.faceAreas()));
            periodic_[findMax(List<scalar>({s.x(), s.y(), s.z()}))] = 1;
        }
    }
    for (direction k = 0; k < 3; ++k)
    {
        reduce(periodic_[k], maxOp<label>());
    }
}


void Foam::bodyShapes::updateBoxes() const
{
    const label timeIndex = mesh_.time().timeIndex();
    if
    (
        cellBox_.size() == mesh_.nCells()
     && (boxTimeIndex_ == timeIndex || !mesh_.changing())
    )
    {
        return;
    }
    cellBox_.setSize(mesh_.nCells());
    const pointField& pts = mesh_.points();
    const labelListList& cellPts = mesh_.cellPoints();
    forAll(cellBox_, c)
    {
        cellBox_[c] = boundBox(pts, cellPts[c], false);
    }
    treeBoundBox overall(bounds_);
    overall.inflate(1e-4);
    tree_.reset
    (
        new indexedOctree<treeDataCell>
        (
            treeDataCell(true, mesh_, polyMesh::CELL_TETS),
            overall,
            8,      // maxLevel
            10,     // leafsize
            5.0     // duplicity
        )
    );
    boxTimeIndex_ = timeIndex;
}


void Foam::bodyShapes::draw
(
    const vhe_shape& s,
    const tensor& Q,
    const vector& X,
    DynamicList<label>& cells,
    DynamicList<scalar>& fraction
) const
{
    updateBoxes();
    // A tensor's components are row-major, as the C core's rotation
    const double* q = Q.cdata();

    // The pose and its periodic images that may reach into the mesh
    DynamicList<vector> images(1, X);
    for (direction k = 0; k < 3; ++k)
    {
        if (!periodic_[k]) continue;
        const label n = images.size();
        const scalar L = bounds_.span()[k];
        for (label i = 0; i < n; ++i)
        {
            for (const scalar shift : {-1.0, 1.0})
            {
                vector Y(images[i]);
                Y[k] += shift*L;
                images.append(Y);
            }
        }
    }

    for (const vector& Y : images)
    {
        double x[3], slo[3], shi[3];
        setVec(x, Y);
        vhe_shape_bounds_posed(&s, q, x, slo, shi);

        // The cells whose boxes meet the shape's (the mesh's octree; the
        // box clipped to the mesh: a 2D disk is infinite along z)
        point qlo, qhi;
        bool inside = true;
        for (direction k = 0; k < 3; ++k)
        {
            const scalar pad = 1e-9*bounds_.mag();
            qlo[k] = max(slo[k], bounds_.min()[k] - pad);
            qhi[k] = min(shi[k], bounds_.max()[k] + pad);
            inside = inside && qlo[k] <= qhi[k];
        }
        if (!inside) continue;
        const labelList near
        (
            tree_->findBox(treeBoundBox(qlo, qhi))
        );
        for (const label c : near)
        {
            const boundBox& cb = cellBox_[c];
            double clo[3], chi[3];
            setVec(clo, cb.min());
            setVec(chi, cb.max());
            bool overlap = true;
            for (label k = 0; k < nDim_; ++k)
            {
                overlap = overlap && clo[k] < shi[k] && chi[k] > slo[k];
            }
            if (!overlap) continue;
            const scalar f = vhe_shape_fraction_posed
            (
                &s, q, x, clo, chi, nDim_, maxDepth_
            );
            if (f > 0)
            {
                cells.append(c);
                fraction.append(f);
            }
        }
    }
}


void Foam::bodyShapes::draw
(
    const vhe_shape& s,
    DynamicList<label>& cells,
    DynamicList<scalar>& fraction
) const
{
    draw(s, tensor::I, centre(s), cells, fraction);
}


vhe_shape Foam::bodyShapes::readSetBodies
(
    const dictionary& dict,
    const label nDim
)
{
    vhe_shape s{};
    s.axis[2] = 1;

    const word shape(dict.get<word>("shape"));
    if (shape == "sphere")
    {
        s.kind = VHE_SPHERE;
        setVec(s.centre, dict.get<vector>("centre"));
        s.radius = dict.get<scalar>("radius");
    }
    else if (shape == "cylinder" || shape == "disk")
    {
        s.kind = VHE_CYLINDER;
        setVec(s.centre, dict.get<vector>("centre"));
        s.radius = dict.get<scalar>("radius");
        vector ax(dict.getOrDefault<vector>("axis", vector(0, 0, 1)));
        if (mag(ax) < SMALL)
        {
            FatalIOErrorInFunction(dict)
                << "axis of body " << dict.dictName() << " is zero"
                << exit(FatalIOError);
        }
        ax /= mag(ax);
        setVec(s.axis, ax);
        s.half_length = 0.5*dict.getOrDefault<scalar>("length", 0);
        if (nDim == 2 && (mag(ax.z()) < 1 - 1e-12 || s.half_length > 0))
        {
            FatalIOErrorInFunction(dict)
                << "In a 2D case (z empty) a cylinder must be a disk: axis"
                << " (0 0 1) and no length; body " << dict.dictName()
                << " has axis " << ax << exit(FatalIOError);
        }
    }
    else if (shape == "box")
    {
        s.kind = VHE_BOX;
        const vector lo(dict.get<vector>("min")), hi(dict.get<vector>("max"));
        if (cmptMin(hi - lo) <= 0 && nDim == 3)
        {
            FatalIOErrorInFunction(dict)
                << "box " << dict.dictName() << " has max <= min"
                << exit(FatalIOError);
        }
        setVec(s.centre, 0.5*(lo + hi));
        setVec(s.semi, 0.5*(hi - lo));
        if (nDim == 2) s.semi[2] = GREAT;
    }
    else if (shape == "ellipsoid")
    {
        s.kind = VHE_ELLIPSOID;
        setVec(s.centre, dict.get<vector>("centre"));
        const vector a(dict.get<vector>("semiAxes"));
        setVec(s.semi, a);
        if (cmptMin(a) <= 0)
        {
            FatalIOErrorInFunction(dict)
                << "semiAxes of " << dict.dictName() << " must be positive"
                << exit(FatalIOError);
        }
        // 2D: an ellipse (an elliptic cylinder along the empty z)
        if (nDim == 2) s.semi[2] = GREAT;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown shape '" << shape << "' for body " << dict.dictName()
            << nl << "    Valid shapes: (sphere cylinder box ellipsoid)"
            << exit(FatalIOError);
    }

    if ((s.kind == VHE_SPHERE || s.kind == VHE_CYLINDER) && s.radius <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "radius of " << dict.dictName() << " must be positive"
            << exit(FatalIOError);
    }
    if (nDim == 2 && s.kind == VHE_SPHERE)
    {
        FatalIOErrorInFunction(dict)
            << "Body " << dict.dictName() << " is a 3D shape (" << shape
            << ") but the case is 2D (z empty): use shape cylinder (a disk),"
            << " box or ellipsoid (an ellipse)" << exit(FatalIOError);
    }
    return s;
}


Foam::vector Foam::bodyShapes::nearestImage(const vector& d) const
{
    vector r(d);
    // 2D: no distance along the empty direction (a body's centre may lie
    // anywhere in it, the cells at its middle)
    if (nDim_ == 2) r.z() = 0;
    for (direction k = 0; k < 3; ++k)
    {
        if (!periodic_[k]) continue;
        const scalar L = bounds_.span()[k];
        r[k] -= L*std::floor(r[k]/L + 0.5);
    }
    return r;
}


Foam::scalar Foam::bodyShapes::sdf
(
    const vhe_shape& s,
    const tensor& Q,
    const vector& X,
    const vector& x
) const
{
    const vector Y(x - nearestImage(x - X));
    return vhe_shape_sdf_posed(&s, Q.cdata(), Y.cdata(), x.cdata());
}


Foam::scalar Foam::bodyShapes::cellSize(const label celli) const
{
    const scalar V = mesh_.V()[celli];
    return nDim_ == 2
      ? Foam::sqrt(V/max(bounds_.span().z(), VSMALL))
      : Foam::cbrt(V);
}


vhe_shape Foam::bodyShapes::read(const dictionary& dict)
{
    vhe_shape s{};
    const word kind(dict.get<word>("kind"));
    const wordList kinds({"sphere", "cylinder", "box", "ellipsoid"});
    s.kind = kinds.find(kind);
    if (s.kind < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Unknown shape kind '" << kind << "'; valid kinds: " << kinds
            << exit(FatalIOError);
    }
    setVec(s.centre, dict.get<vector>("centre"));
    setVec(s.axis, dict.get<vector>("axis"));
    s.radius = dict.get<scalar>("radius");
    s.half_length = dict.get<scalar>("halfLength");
    setVec(s.semi, dict.get<vector>("semi"));
    if (vhe_shape_check(&s) != VHE_OK)
    {
        FatalIOErrorInFunction(dict)
            << "Invalid " << kind << " (a radius or half-edges not positive,"
            << " or a zero axis)" << exit(FatalIOError);
    }
    return s;
}


Foam::dictionary Foam::bodyShapes::write(const vhe_shape& s)
{
    dictionary d;
    const wordList kinds({"sphere", "cylinder", "box", "ellipsoid"});
    d.add("kind", kinds[s.kind]);
    d.add("centre", getVec(s.centre));
    d.add("axis", getVec(s.axis));
    d.add("radius", s.radius);
    d.add("halfLength", s.half_length);
    d.add("semi", getVec(s.semi));
    return d;
}


// ************************************************************************* //
