/*---------------------------------------------------------------------------*\
  vheFoam: per-body output function object
  the bodies' ids from write to write, and the gaps between them
\*---------------------------------------------------------------------------*/

#include "bodies.H"
#include "volFields.H"
#include "ListOps.H"
#include "mathematicalConstants.H"

namespace
{
    //- Order of the bodies for new ids: by material, then z, y, x
    //  (quantised to 1e-6 of the domain, so that the round-off of a
    //  parallel sum does not reorder a row of a packing)
    Foam::labelList spatialOrder
    (
        const Foam::List<Foam::functionObjects::bodies::body>& bs,
        const Foam::labelList& which,
        const Foam::boundBox& bb
    )
    {
        using namespace Foam;
        const scalar q = 1e-6*max(bb.mag(), SMALL);
        auto key = [&](label i, direction d)
        {
            return std::llround((bs[i].centroid[d] - bb.min()[d])/q);
        };
        labelList order(which);
        std::stable_sort
        (
            order.begin(), order.end(),
            [&](label i, label j)
            {
                if (bs[i].material != bs[j].material)
                {
                    return bs[i].material < bs[j].material;
                }
                for (const direction d : {2, 1, 0})
                {
                    if (key(i, d) != key(j, d)) return key(i, d) < key(j, d);
                }
                return false;
            }
        );
        return order;
    }
}


void Foam::functionObjects::bodies::number(List<body>& found)
{
    const scalar dt = time_.value() - lastTime_;
    const scalar pi = constant::mathematical::pi;

    // Equivalent radius of each body found (2D: per unit depth)
    scalar depth = 1;
    if (mesh_.nGeometricD() == 2)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh_.geometricD()[d] == -1) depth = mesh_.bounds().span()[d];
        }
    }
    auto radius = [&](const body& b)
    {
        return mesh_.nGeometricD() == 2
            ? std::sqrt(b.volume/(pi*depth))
            : std::cbrt(3*b.volume/(4*pi));
    };

    // Pairs (new, last) of one material closer than the new body's
    // radius, nearest first, each body taken once
    struct pair { scalar d; label i, j; };
    DynamicList<pair> pairs;
    forAll(found, i)
    {
        forAll(last_, j)
        {
            if (found[i].material != last_[j].material) continue;
            const scalar d = mag
            (
                regions_.nearestImage
                (
                    found[i].centroid - last_[j].centroid - dt*last_[j].U
                )
            );
            if (d < radius(found[i])) pairs.append({d, i, j});
        }
    }
    std::stable_sort
    (
        pairs.begin(), pairs.end(),
        [](const pair& x, const pair& y) { return x.d < y.d; }
    );
    boolList taken(last_.size(), false);
    for (const pair& p : pairs)
    {
        if (found[p.i].id < 0 && !taken[p.j])
        {
            found[p.i].id = last_[p.j].id;
            taken[p.j] = true;
        }
    }

    // New bodies: the next ids in spatial order
    DynamicList<label> unnamed;
    forAll(found, i)
    {
        if (found[i].id < 0) unnamed.append(i);
    }
    for (const label i : spatialOrder(found, unnamed, mesh_.bounds()))
    {
        found[i].id = nextId_++;
    }
}


void Foam::functionObjects::bodies::gaps
(
    List<body>& found,
    const List<List<point>>& surface
) const
{
    // On the master, which holds every body's surface points; each pair
    // of bodies is skipped when their bounding spheres are farther apart
    // than the gaps already found
    if (!Pstream::master()) return;

    scalarList rad(found.size(), Zero);
    forAll(found, i)
    {
        for (const point& p : surface[i])
        {
            rad[i] = max(rad[i], mag(regions_.nearestImage(p - found[i].centroid)));
        }
    }
    scalarList gap(found.size(), GREAT);
    forAll(found, i)
    {
        for (label j = i + 1; j < found.size(); ++j)
        {
            const scalar lower =
                mag(regions_.nearestImage(found[i].centroid - found[j].centroid))
              - rad[i] - rad[j];
            if (lower >= gap[i] && lower >= gap[j]) continue;
            scalar g = GREAT;
            for (const point& p : surface[i])
            {
                for (const point& q : surface[j])
                {
                    g = min(g, magSqr(regions_.nearestImage(p - q)));
                }
            }
            g = std::sqrt(g);
            gap[i] = min(gap[i], g);
            gap[j] = min(gap[j], g);
        }
    }
    forAll(found, i)
    {
        found[i].gap = gap[i] < GREAT ? gap[i] : -1;
    }
}


// ************************************************************************* //
