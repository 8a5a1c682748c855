/*---------------------------------------------------------------------------*\
  vheFoam: each surface cell's interface plane (PLIC with RDF normals)
\*---------------------------------------------------------------------------*/

#include "interfacePlanes.H"
#include "vhe.h"
#include "vheFlat.H"
#include "volPointInterpolation.H"
#include "pointStencil.H"
#include "profiling.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::SubList<Foam::point> Foam::interfacePlanes::rowPoints
(
    const label i
) const
{
    const label end = i + 1 < xStart_.size() ? xStart_[i + 1] : x_.size();
    return SubList<point>(x_, end - xStart_[i], xStart_[i]);
}


void Foam::interfacePlanes::planeValues(const label i, const vector& n)
    const
{
    // Rises into the fraction, as the interpolated fraction does
    const point& C = mesh_.C()[cells_[i]];
    const SubList<point> x(rowPoints(i));
    fCell_.setSize(x.size());
    forAll(x, j)
    {
        fCell_[j] = -(n & (x[j] - C));
    }
}


void Foam::interfacePlanes::rdfNormals(List<vector>& nNew) const
{
    const label nCells = mesh_.nCells();
    const volVectorField& C = mesh_.C();
    const pointField& pts = mesh_.points();
    const labelListList& cellPoints = mesh_.cellPoints();
    const labelListList& pointCells = mesh_.pointCells();
    const pointStencil& stencil = pointStencil::New(mesh_);

    labelList surfIndex(nCells, -1);
    forAll(cells_, i) surfIndex[cells_[i]] = i;

    // The planes around the coupled points: normal, centre - point
    const pointStencil::records planes
    (
        stencil.gather
        (
            7,
            [&](const label k, const label q, scalar* d)
            {
                const label i = surfIndex[k];
                if (i < 0) return false;
                const vector r = centre_[i] - pts[q];
                for (direction j = 0; j < 3; ++j)
                {
                    d[j] = normal_[i][j];
                    d[3 + j] = r[j];
                }
                return true;
            }
        )
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
    stencil.markAround(planes, band);

    // The RDF: a surface cell's own distance to its plane; in the others,
    // the mean of the distances of the planes sharing a point with the
    // cell, weighted by cos^2 of the angle between the normal and the line
    // from the plane's centre
    scalarField rdf(nCells, Zero);
    List<bool> has(nCells, false);
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
        stencil.visit
        (
            c, planes, 7,
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

    // The normal: the RDF's least-squares gradient
    stencil.gradient(rdf, has, cells_, nNew);
    forAll(nNew, i)
    {
        const scalar m = mag(nNew[i]);
        nNew[i] = m > SMALL ? nNew[i]/m : normal_[i];
    }
}


void Foam::interfacePlanes::addRow(const label c)
{
    // Its points, and its faces in local point indices, flipped where the
    // cell is the face's neighbour
    const labelList& cp = mesh_.cellPoints()[c];
    xStart_.append(x_.size());
    x_.append(UIndirectList<point>(mesh_.points(), cp));
    const cell& faces = mesh_.cells()[c];
    startRow_.append(start_.size());
    ptsRow_.append(facePts_.size());
    const label p0 = facePts_.size();
    forAll(faces, k)
    {
        const label f = faces[k];
        start_.append(facePts_.size() - p0);
        flip_.append(mesh_.faceOwner()[f] != c);
        for (const label p : mesh_.faces()[f])
        {
            facePts_.append(cp.find(p));
        }
    }
    start_.append(facePts_.size() - p0);
    flip_.append(0);
}


void Foam::interfacePlanes::removeRow()
{
    x_.setSize(xStart_.remove());
    const label s = startRow_.remove();
    start_.setSize(s);
    flip_.setSize(s);
    facePts_.setSize(ptsRow_.remove());
}


bool Foam::interfacePlanes::cutCell
(
    const label i,
    const scalar alpha,
    const scalar tol,
    const scalar g,
    const scalar guess,
    vhe_cut& out
) const
{
    const label c = cells_[i];
    const label s = startRow_[i];
    const label nf =
        (i + 1 < startRow_.size() ? startRow_[i + 1] : start_.size()) - s - 1;

    vhe_cell cellC;
    const SubList<point> x(rowPoints(i));
    cellC.npoints = x.size();
    cellC.x = flat(x);
    cellC.nfaces = nf;
    cellC.face_start = start_.cdata() + s;
    cellC.face_pts = facePts_.cdata() + ptsRow_[i];
    cellC.flip = flip_.cdata() + s;
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
    vhe_cut out;
    forAll(cells_, i)
    {
        const label c = cells_[i];
        const point& C = mesh_.C()[c];
        planeValues(i, n[i]);
        // from the last plane's centre (Newton: the field is a plane)
        if (!cutCell(i, a[c], isoTol, 1, -(n[i] & (centre_[i] - C)), out))
        {
            continue;
        }
        if ((vector(out.area[0], out.area[1], out.area[2]) & n[i]) <= 0)
        {
            continue;
        }
        normal_[i] = n[i];
        centre_[i] = point(out.centre[0], out.centre[1], out.centre[2]);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::interfacePlanes::interfacePlanes
(
    const volScalarField& alpha,
    const scalar surfTol,
    const scalar isoTol,
    const label nRDF
)
:
    mesh_(alpha.mesh())
{
    const scalarField& a = alpha.primitiveField();

    // 1. isoAdvector's isosurfaces of the point-interpolated fraction (a
    //    start from the fraction's own gradient, Youngs's normal, left the
    //    translated disk 1.6 to 1.9 times further from exact)
    {
        addProfiling(iso, "interfacePlanes::isoSurface");
        const pointScalarField ap
        (
            volPointInterpolation::New(mesh_).interpolate(alpha)
        );
        const scalarField& interpolated = ap.primitiveField();
        vhe_cut out;
        forAll(a, c)
        {
            if (a[c] <= surfTol || a[c] >= 1 - surfTol) continue;
            const labelList& cp = mesh_.cellPoints()[c];
            fCell_.setSize(cp.size());
            forAll(cp, j)
            {
                fCell_[j] = interpolated[cp[j]];
            }
            cells_.append(c);
            addRow(c);
            const bool cut =
                cutCell(cells_.size() - 1, a[c], isoTol, 0, 0, out);
            const vector A(out.area[0], out.area[1], out.area[2]);
            if (!cut || mag(A) < VSMALL)
            {
                cells_.remove();
                removeRow();
                continue;
            }
            normal_.append(A/mag(A));
            centre_.append(point(out.centre[0], out.centre[1], out.centre[2]));
        }
    }

    // 2-4. RDF normals and the planes that cut the cells at their fractions
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


// ************************************************************************* //
