/*---------------------------------------------------------------------------*\
  vheFoam: the poses of the free rigid bodies -- kept apart: the gap
  between two bodies and between a body and a wall, the poses separated
  where a gap closes, the velocities constrained at a contact
\*---------------------------------------------------------------------------*/

#include "rigidPoses.H"
#include "volFields.H"
#include "emptyFvPatch.H"
#include <cmath>
#include <functional>

namespace Foam
{
namespace
{
    //- The least g over all processors and the x that goes with it (the
    //  x of the processor holding the least; ties: the largest
    //  components)
    scalar globalMin(const scalar g, vector& x)
    {
        const scalar gMin = returnReduce(g, minOp<scalar>());
        if (g > gMin) x = vector::uniform(-GREAT);
        reduce(x, maxOp<vector>());
        return gMin;
    }
}
}


Foam::scalar Foam::rigidPoses::gap
(
    const body& A,
    const DynamicList<label>& cellsA,
    const body& B,
    const DynamicList<label>& cellsB,
    const scalar h,
    vector& n
) const
{
    const vectorField& C = mixture_.rho().mesh().C();
    typedef std::function<scalar(const vector&)> distance;
    const distance fa = [&](const vector& x)
    {
        return shapes_.sdf(A.shape, A.Q, A.X, x);
    };
    const distance fb = [&](const vector& x)
    {
        return shapes_.sdf(B.shape, B.Q, B.X, x);
    };
    // A distance's gradient, by central differences
    const scalar e = 1e-3*h;
    const auto grad = [&](const distance& f, const vector& x)
    {
        vector g(Zero);
        for (label k = 0; k < shapes_.nDim(); ++k)
        {
            vector d(Zero);
            d[k] = e;
            g[k] = (f(x + d) - f(x - d))/(2*e);
        }
        return g/max(mag(g), SMALL);
    };

    // The cell centre nearest the middle of the gap: least max(sdf_a,
    // sdf_b) over the cells the two reached at their last drawing
    scalar g = GREAT;
    vector x0(vector::uniform(-GREAT));
    for (const DynamicList<label>* cells : {&cellsA, &cellsB})
    {
        for (const label c : *cells)
        {
            const scalar v = max(fa(C[c]), fb(C[c]));
            if (v < g)
            {
                g = v;
                x0 = C[c];
            }
        }
    }
    const scalar gMin = globalMin(g, x0);
    if (gMin >= GREAT) return GREAT;

    // Overlapping: half the sampled depth, along the distances' gradients
    if (gMin <= 0)
    {
        n = grad(fb, x0) - grad(fa, x0);
        n = -n/max(mag(n), SMALL);
        return 2*gMin;
    }

    // Apart: the nearest points by alternating projections onto the two
    // surfaces (convex shapes), from the sampled middle: the gap to a
    // fraction of a cell's sampling error, not half a cell
    vector p(x0), q(x0);
    for (label it = 0; it < 20; ++it)
    {
        p = q - fa(q)*grad(fa, q);
        q = p - fb(p)*grad(fb, p);
    }
    const vector d(q - p);
    n = d/max(mag(d), SMALL);
    return max(fb(p), scalar(0));
}


void Foam::rigidPoses::separate()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const label n = bodies_.size();
    contacts_.clear();

    // A shape's bounding radius in the case's directions, and the smallest
    // cell a body reaches (on this processor)
    const auto radius = [&](const vhe_shape& shape)
    {
        double lo[3], hi[3];
        vhe_shape_bounds(&shape, lo, hi);
        scalar r2 = 0;
        for (label k = 0; k < shapes_.nDim(); ++k)
        {
            r2 += sqr(0.5*(hi[k] - lo[k]));
        }
        return Foam::sqrt(r2);
    };
    const auto smallest = [&](const DynamicList<label>& cells)
    {
        scalar h = GREAT;
        for (const label c : cells) h = min(h, shapes_.cellSize(c));
        return h;
    };

    // Each body's cell size (its smallest cell) and bounding radius
    scalarList h(n, GREAT), R(n, Zero);
    forAll(bodies_, b)
    {
        h[b] = smallest(cells_[b]);
        R[b] = radius(bodies_[b].shape);
    }
    Pstream::listCombineGather(h, minEqOp<scalar>());
    Pstream::listCombineScatter(h);

    scalar push = 0;

    // Body a and body B (body b, or a fixed body: b = -1, mass GREAT) of
    // cell size hB and radius RB: where nearer than half their cells, a
    // moves away from B, and B from a, in inverse proportion to their
    // masses; the contact noted if asked.  Whether they moved
    const auto collide = [&]
    (
        const label a,
        const body& B,
        const DynamicList<label>& cellsB,
        const scalar hB,
        const scalar RB,
        const scalar mb,
        const label b,
        const bool note
    )
    {
        if (h[a] >= GREAT || hB >= GREAT) return false;
        const scalar margin = 0.5*(h[a] + hB);
        const scalar dist = mag(shapes_.nearestImage(B.X - bodies_[a].X));
        if (dist > R[a] + RB + margin) return false;
        const scalar ma = mass(a);
        if (ma >= GREAT && mb >= GREAT) return false;
        vector nab;
        const scalar g =
            gap(bodies_[a], cells_[a], B, cellsB, min(h[a], hB), nab);
        if (g >= margin) return false;
        const scalar wa = ma >= GREAT ? 0 : mb >= GREAT ? 1 : mb/(ma + mb);
        push = max(push, (margin - g)/margin);
        bodies_[a].X -= wa*(margin - g)*nab;
        if (b >= 0) bodies_[b].X += (1 - wa)*(margin - g)*nab;
        if (note) contacts_.append({a, b, nab});
        return true;
    };

    // Body pairs, a few sweeps (a body may touch several)
    for (label sweep = 0; sweep < 3; ++sweep)
    {
        bool moved = false;
        for (label a = 0; a < n; ++a)
        {
            for (label b = a + 1; b < n; ++b)
            {
                moved =
                    collide
                    (
                        a, bodies_[b], cells_[b], h[b], R[b], mass(b), b,
                        sweep == 0
                    )
                 || moved;
            }
        }
        if (!moved) break;
    }

    // The fixed bodies placed by setBodies: obstacles that do not move
    forAll(obstacles_, o)
    {
        const scalar ho =
            returnReduce(smallest(obstacleCells_[o]), minOp<scalar>());
        const scalar Ro = radius(obstacles_[o].shape);
        forAll(bodies_, a)
        {
            collide
            (
                a, obstacles_[o], obstacleCells_[o], ho, Ro, GREAT, -1, true
            );
        }
    }

    // Walls: the faces of the mesh's boundary that are neither coupled nor
    // empty
    forAll(bodies_, b)
    {
        if (mass(b) >= GREAT || h[b] >= GREAT) continue;
        body& B = bodies_[b];
        scalar g = GREAT;
        vector nw(Zero);
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (pp.coupled() || pp.size() == 0 || isA<emptyFvPatch>(pp))
            {
                continue;
            }
            const vectorField& Cf = pp.Cf();
            const vectorField nf(pp.nf());
            forAll(Cf, i)
            {
                if (mag(shapes_.nearestImage(Cf[i] - B.X)) > R[b] + h[b])
                {
                    continue;
                }
                const scalar v = shapes_.sdf(B.shape, B.Q, B.X, Cf[i]);
                if (v < g)
                {
                    g = v;
                    nw = nf[i];
                }
            }
        }
        const scalar gMin = globalMin(g, nw);
        const scalar margin = 0.5*h[b];
        if (gMin >= margin) continue;
        push = max(push, (margin - gMin)/margin);
        B.X -= (margin - gMin)*nw;
        contacts_.append({b, -1, nw});
    }
    if (contacts_.size())
    {
        Info<< "Rigid bodies: " << contacts_.size() << " contacts, moved"
            << " apart by up to " << push << " of their margin" << endl;
    }
}


void Foam::rigidPoses::constrain(List<vector>& Ub) const
{
    for (const contact& k : contacts_)
    {
        if (k.b < 0)
        {
            // Into the wall (nw points out of the mesh)
            if (mass(k.a) >= GREAT) continue;
            const scalar un = Ub[k.a] & k.n;
            if (un > 0) Ub[k.a] -= un*k.n;
            continue;
        }
        const scalar vn = (Ub[k.b] - Ub[k.a]) & k.n;
        if (vn >= 0) continue;
        const scalar ma = mass(k.a), mb = mass(k.b);
        const scalar wa = ma >= GREAT ? 0 : mb >= GREAT ? 1 : mb/(ma + mb);
        Ub[k.a] += wa*vn*k.n;
        Ub[k.b] -= (1 - wa)*vn*k.n;
    }
}


// ************************************************************************* //
