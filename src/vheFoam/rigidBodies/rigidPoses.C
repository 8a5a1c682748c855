/*---------------------------------------------------------------------------*\
  vheFoam: the poses of the free rigid bodies
\*---------------------------------------------------------------------------*/

#include "rigidPoses.H"
#include "volFields.H"
#include "OSspecific.H"
#include "Map.H"
#include <cmath>

// * * * * * * * * * * * * * * * Member Functions * * * * * * * * * * * * * //

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
    if (!state_.isDict("bodies")) return;

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


bool Foam::rigidPoses::fixedShape(const label i) const
{
    for (const body& o : obstacles_)
    {
        if (o.material == mixture_.phases()[i].material) return true;
    }
    return false;
}


const Foam::rigidPoses::body& Foam::rigidPoses::nearestFixed
(
    const label i,
    const vector& x
) const
{
    label nearest = -1;
    scalar d = GREAT;
    forAll(obstacles_, o)
    {
        const body& ob = obstacles_[o];
        if (ob.material != mixture_.phases()[i].material) continue;
        const scalar s = shapes_.sdf(ob.shape, ob.Q, ob.X, x);
        if (nearest < 0 || s < d)
        {
            nearest = o;
            d = s;
        }
    }
    return obstacles_[nearest];
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
            b.U0 = b.U;
            b.omega0 = b.omega;
        }
    }

    const scalarField& V = mesh.V();
    forAll(bodies_, b)
    {
        body& bd = bodies_[b];
        bd.X = bd.X0 + dt*bd.U;
        bd.Udrawn = bd.U;
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
    for (body& bd : bodies_) bd.Xdrawn = bd.X;
    forAll(bodies_, b) draw(b);

    // The fluids fill what the drawn bodies leave; the density change is a
    // mass source at the old velocity (a wood body leaving a cell of air
    // left its momentum in the air, whose velocity jumped 600-fold, and
    // the step collapsed)
    mixture.holdAsSource(phases_, fractions(), dRho_);
}


Foam::scalar Foam::rigidPoses::mass(const label b) const
{
    const vheMixture::phase& ph = mixture_.phases()[bodies_[b].phase];
    return ph.prescribed ? GREAT : ph.rho*bodies_[b].volume;
}


void Foam::rigidPoses::setMotion
(
    const List<vector>& Ub,
    const List<vector>& omega,
    const List<vector>& Xm,
    const bodyRegions& regions
)
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const bool drawn = stepIndex_ == mesh.time().timeIndex();
    const scalar dt = mesh.time().deltaTValue();
    const label normal = mesh.nSolutionD() == 2 ? vector::Z : -1;
    forAll(bodies_, b)
    {
        body& bd = bodies_[b];
        bd.omega = omega[b];
        // The velocity of the pose's point, body-fixed: its offset from
        // the centre of mass as drawn
        const vector X(drawn ? bd.Xdrawn : bd.X);
        bd.U = Ub[b] + (omega[b] ^ regions.nearestImage(X - Xm[b]));
        if (!drawn) continue;
        // The step's pose by the trapezoidal rule, from where the drawing
        // put it (contact's separation kept)
        bd.X = bd.Xdrawn + dt*(0.5*(bd.U0 + bd.U) - bd.Udrawn);
        const vector omegaMean(0.5*(bd.omega0 + bd.omega));
        bd.Q = bd.Q0;
        vhe_pose_rotate(bd.Q.data(), omegaMean.cdata(), dt);
        if (normal >= 0) bd.angle = bd.angle0 + dt*omegaMean[normal];
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
