/*---------------------------------------------------------------------------*\
  vheFoam: the poses of the free rigid bodies
\*---------------------------------------------------------------------------*/

#include "rigidPoses.H"
#include "volFields.H"
#include "OSspecific.H"
#include "emptyFvPatch.H"
#include "Map.H"
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


bool Foam::rigidPoses::stateDict::writeData(Ostream& os) const
{
    // A pose written to 6 digits would not restart exactly
    const label p = os.precision(17);
    const bool ok = IOdictionary::writeData(os);
    os.precision(p);
    return ok;
}


Foam::rigidPoses::rigidPoses
(
    const vheMixture& mixture,
    const labelList& rigidPhases
)
:
    mixture_(mixture),
    shapes_(mixture.rho().mesh()),
    state_
    (
        IOobject
        (
            "rigidBodies",
            mixture.rho().mesh().time().timeName(),
            "uniform",
            mixture.rho().mesh(),
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        )
    ),
    velocityKnown_(false),
    stepIndex_(-1),
    obstacleIndex_(-1)
{
    const fvMesh& mesh = mixture.rho().mesh();
    const List<vheMixture::phase>& phases = mixture.phases();
    if (rigidPhases.empty() || !state_.isDict("bodies")) return;

    // The bodies of the free rigid materials
    DynamicList<body> found;
    bool velocities = true;
    for (const entry& e : state_.subDict("bodies"))
    {
        if (!e.isDict()) continue;
        const dictionary& d = e.dict();
        body b;
        b.name = e.keyword();
        b.material = d.get<word>("material");
        const label colour = d.get<label>("colour");
        b.phase = -1;
        for (const label i : rigidPhases)
        {
            if
            (
                phases[i].material == b.material
             && (b.phase < 0 || phases[i].colour == colour)
            )
            {
                b.phase = i;
            }
        }
        b.shape = bodyShapes::read(d.subDict("shape"));
        b.volume = d.get<scalar>("volume");
        b.X = d.get<vector>("centre");
        b.Q = d.get<tensor>("orientation");
        if (b.phase < 0)
        {
            // A fixed body: an obstacle to the free ones
            forAll(phases, i)
            {
                if (phases[i].material == b.material && phases[i].fixed)
                {
                    b.phase = i;
                    obstacles_.append(b);
                    break;
                }
            }
            continue;
        }
        b.X0 = b.X;
        b.Q0 = b.Q;
        b.U = d.getOrDefault<vector>("velocity", Zero);
        b.omega = d.getOrDefault<vector>("angularVelocity", Zero);
        velocities = velocities && d.found("velocity");
        b.angle = d.getOrDefault<scalar>("angle", 0);
        b.angle0 = b.angle;
        found.append(b);
    }
    bodies_.transfer(found);
    cells_.setSize(bodies_.size());
    alpha_.setSize(bodies_.size());
    forAll(bodies_, b) draw(b);

    // A material is drawn from its bodies only where they are its
    // fraction as read (to the written precision)
    const scalarField& V = mesh.V();
    wordList materials;
    for (const body& b : bodies_)
    {
        if (!materials.found(b.material)) materials.append(b.material);
    }
    DynamicList<label> posed;
    DynamicList<body> kept;
    DynamicList<DynamicList<label>> keptCells;
    DynamicList<DynamicList<scalar>> keptAlpha;
    for (const word& m : materials)
    {
        scalarField drawn(mesh.nCells(), Zero), read(mesh.nCells(), Zero);
        forAll(bodies_, b)
        {
            if (bodies_[b].material != m) continue;
            forAll(cells_[b], k) drawn[cells_[b][k]] += alpha_[b][k];
        }
        labelList mine;
        for (const label i : rigidPhases)
        {
            if (phases[i].material != m) continue;
            mine.append(i);
            read += mixture.alphas()[i].primitiveField();
        }
        const scalar diff =
            gSum(mag(min(drawn, scalar(1)) - read)*V)
           /max(gSum(read*V), VSMALL);
        if (diff > 1e-3)
        {
            WarningInFunction
                << "The fraction of " << m << " differs from the bodies of "
                << state_.objectPath() << " by " << diff << " of its volume:"
                << " its bodies are carried by the phase transport, their"
                << " shapes not kept (run setBodies to place them)" << endl;
            continue;
        }
        posed.append(mine);
        forAll(bodies_, b)
        {
            if (bodies_[b].material != m) continue;
            kept.append(bodies_[b]);
            keptCells.append(cells_[b]);
            keptAlpha.append(alpha_[b]);
        }
    }
    phases_.transfer(posed);
    bodies_.transfer(kept);
    cells_.transfer(keptCells);
    alpha_.transfer(keptAlpha);
    velocityKnown_ = velocities && bodies_.size();

    if (active())
    {
        state_.writeOpt() = IOobject::AUTO_WRITE;
        Info<< "Rigid bodies: " << bodies_.size() << " carried with their"
            << " shapes (" << state_.objectPath() << ")" << nl << endl;
    }
}


void Foam::rigidPoses::drawObstacles()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    if
    (
        obstacleIndex_ >= 0
     && (obstacleIndex_ == mesh.time().timeIndex() || !mesh.changing())
    )
    {
        return;
    }
    obstacleIndex_ = mesh.time().timeIndex();
    obstacleCells_.setSize(obstacles_.size());
    forAll(obstacles_, o)
    {
        DynamicList<scalar> frac;
        obstacleCells_[o].clear();
        shapes_.draw
        (
            obstacles_[o].shape, obstacles_[o].Q, obstacles_[o].X,
            obstacleCells_[o], frac
        );
    }
}


void Foam::rigidPoses::draw(const label b)
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const body& bd = bodies_[b];
    DynamicList<label> cells;
    DynamicList<scalar> frac;
    shapes_.draw(bd.shape, bd.Q, bd.X, cells, frac);

    // A cell reached by two periodic images counts once, summed
    Map<label> slot(2*cells.size());
    DynamicList<label>& c = cells_[b];
    DynamicList<scalar>& a = alpha_[b];
    c.clear();
    a.clear();
    forAll(cells, k)
    {
        const auto iter = slot.cfind(cells[k]);
        if (iter.found())
        {
            a[*iter] += frac[k];
        }
        else
        {
            slot.insert(cells[k], c.size());
            c.append(cells[k]);
            a.append(frac[k]);
        }
    }
    scalarField V(c.size());
    forAll(c, k)
    {
        a[k] = min(a[k], scalar(1));
        V[k] = mesh.V()[c[k]];
    }

    double sums[2];
    vhe_volume_sums(a.size(), a.cdata(), V.cdata(), sums);
    reduce(sums[0], sumOp<scalar>());
    reduce(sums[1], sumOp<scalar>());
    vhe_volume_shift(a.size(), a.data(), sums, bd.volume);
}


Foam::List<Foam::scalarField> Foam::rigidPoses::fractions() const
{
    const label nCells = mixture_.rho().mesh().nCells();
    List<scalarField> f(phases_.size(), scalarField(nCells, Zero));
    forAll(bodies_, b)
    {
        scalarField& fb = f[phases_.find(bodies_[b].phase)];
        forAll(cells_[b], k) fb[cells_[b][k]] += alpha_[b][k];
    }
    for (scalarField& fi : f) fi = min(fi, scalar(1));
    return f;
}


void Foam::rigidPoses::move(vheMixture& mixture)
{
    if (!active()) return;
    const fvMesh& mesh = mixture.rho().mesh();
    const scalar dt = mesh.time().deltaTValue();
    const label normal = mesh.nSolutionD() == 2 ? vector::Z : -1;

    // Every outer iteration moves from the step's start
    if (stepIndex_ != mesh.time().timeIndex())
    {
        stepIndex_ = mesh.time().timeIndex();
        dRho_ = scalarField(mesh.nCells(), Zero);
        for (body& b : bodies_)
        {
            b.X0 = b.X;
            b.Q0 = b.Q;
            b.angle0 = b.angle;
        }
    }

    const scalarField& V = mesh.V();
    forAll(bodies_, b)
    {
        body& bd = bodies_[b];
        bd.X = bd.X0 + dt*bd.U;
        bd.Q = bd.Q0;
        vhe_pose_rotate(bd.Q.data(), bd.omega.cdata(), dt);
        if (normal >= 0) bd.angle = bd.angle0 + dt*bd.omega[normal];
        // The rest of a body's edge wraps into the mesh: its centre too
        for (direction k = 0; k < 3; ++k)
        {
            if (!shapes_.periodic()[k]) continue;
            const scalar lo = shapes_.bounds().min()[k];
            const scalar L = shapes_.bounds().span()[k];
            const scalar shift = L*std::floor((bd.X[k] - lo)/L);
            bd.X[k] -= shift;
            bd.X0[k] -= shift;
        }

        // The phase (colour) holding most of the body now
        const word& material = mixture.phases()[bd.phase].material;
        scalar best = 0;
        label pick = bd.phase;
        for (const label i : phases_)
        {
            if (mixture.phases()[i].material != material) continue;
            const scalarField& ai = mixture.alphas()[i].primitiveField();
            scalar s = 0;
            forAll(cells_[b], k)
            {
                const label c = cells_[b][k];
                s += alpha_[b][k]*ai[c]*V[c];
            }
            reduce(s, sumOp<scalar>());
            if (s > best)
            {
                best = s;
                pick = i;
            }
        }
        bd.phase = pick;
    }

    // No body comes nearer another, a fixed body or a wall than half a
    // cell
    drawObstacles();
    separate();
    forAll(bodies_, b) draw(b);

    // The fluids fill what the drawn bodies leave; the density change is a
    // mass source at the old velocity (a wood body leaving a cell of air
    // left its momentum in the air, whose velocity jumped 600-fold, and
    // the step collapsed)
    const scalarField rho0(mixture.rho().primitiveField());
    mixture.hold(phases_, fractions());
    mixture.correct();
    const scalarField dRho(mixture.rho().primitiveField() - rho0);
    if (dRho_.size() != dRho.size()) dRho_ = scalarField(dRho.size(), Zero);
    mixture.addToOldDensity(dRho - dRho_);
    dRho_ = dRho;
}


Foam::scalar Foam::rigidPoses::mass(const label b) const
{
    const vheMixture::phase& ph = mixture_.phases()[bodies_[b].phase];
    return ph.prescribed ? GREAT : ph.rho*bodies_[b].volume;
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


void Foam::rigidPoses::setMotion
(
    const List<vector>& Ub,
    const List<vector>& omega,
    const List<vector>& Xm,
    const bodyRegions& regions
)
{
    forAll(bodies_, b)
    {
        body& bd = bodies_[b];
        bd.omega = omega[b];
        bd.U = Ub[b] + (omega[b] ^ regions.nearestImage(bd.X - Xm[b]));
    }
    velocityKnown_ = true;
    writeState();
}


const Foam::dictionary& Foam::rigidPoses::solverState() const
{
    return state_.optionalSubDict("solver");
}


void Foam::rigidPoses::setSolverState(const dictionary& d) const
{
    const unsigned precision = IOstream::defaultPrecision(17);
    state_.set("solver", d);
    IOstream::defaultPrecision(precision);
}


void Foam::rigidPoses::writeState()
{
    const Time& time = mixture_.rho().mesh().time();
    // Vectors and tensors become tokens as they are added, at the default
    // precision: a pose to 6 digits would not restart exactly
    const unsigned precision = IOstream::defaultPrecision(17);
    dictionary all;
    for (const body& bd : bodies_)
    {
        const vheMixture::phase& ph = mixture_.phases()[bd.phase];
        dictionary d;
        d.add("material", bd.material);
        d.add("colour", ph.colour);
        d.add("shape", bodyShapes::write(bd.shape));
        d.add("volume", bd.volume);
        d.add("centre", bd.X);
        d.add("orientation", bd.Q);
        d.add("velocity", bd.U);
        d.add("angularVelocity", bd.omega);
        d.add("angle", bd.angle);
        all.add(bd.name, d);
    }
    state_.set("bodies", all);
    IOstream::defaultPrecision(precision);

    if (!Pstream::master()) return;
    if (!file_.valid())
    {
        const fileName dir
        (
            time.globalPath()/"postProcessing"/"rigidBodies"
           /time.timeName(time.startTime().value())
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"poses.dat"));
        file_()
            << "# Each free rigid body's pose and motion: the centre of its"
            << " shape X [m], its velocity U [m/s], angular velocity omega"
            << " [rad/s] and (2D) the angle turned [rad]" << nl
            << "# time body X Y Z Ux Uy Uz omegax omegay omegaz angle" << endl;
    }
    OFstream& os = file_();
    os.precision(10);
    forAll(bodies_, b)
    {
        const body& bd = bodies_[b];
        os  << time.value() << ' ' << b;
        for (const vector& v : {bd.X, bd.U, bd.omega})
        {
            os << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
        }
        os << ' ' << bd.angle << nl;
    }
    os.flush();
}


// ************************************************************************* //
