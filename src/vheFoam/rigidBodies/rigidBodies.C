/*---------------------------------------------------------------------------*\
  vheFoam: rigid bodies
\*---------------------------------------------------------------------------*/

#include "rigidBodies.H"
#include "syncTools.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "vhe.h"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "fvcSup.H"
#include "fvmDdt.H"
#include "scalarMatrices.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"

namespace
{
    //- How much of a cell moves with the body: all of it where its
    //  fraction is 1/4 or more, in proportion below
    inline Foam::scalar weight(const Foam::scalar alpha)
    {
        return Foam::min(1.0, 4.0*alpha);
    }
}

const Foam::scalar Foam::rigidBodies::penalty = 1e3;
const Foam::scalar Foam::rigidBodies::tolerance = 1e-5;
const Foam::label Foam::rigidBodies::maxIter = 10;


Foam::rigidBodies::rigidBodies(const vheMixture& mixture)
:
    mixture_(mixture),
    materials_(),
    regions_(mixture.rho().mesh(), 0.5),
    poses_
    (
        mixture,
        [&mixture]()
        {
            DynamicList<label> free;
            forAll(mixture.phases(), i)
            {
                const vheMixture::phase& ph = mixture.phases()[i];
                if (ph.rigid && !ph.fixed) free.append(i);
            }
            return labelList(free);
        }()
    ),
    nBodies_(0),
    updated_(-1)
{
    DynamicList<label> rigid;
    const label nPhases = mixture_.phases().size();
    velocity_.setSize(nPhases);
    angularVelocity_.setSize(nPhases);
    forAll(mixture_.phases(), i)
    {
        const vheMixture::phase& ph = mixture_.phases()[i];
        if (!ph.rigid) continue;
        rigid.append(i);
        if (!ph.prescribed) continue;
        const dictionary& d =
            mixture_.subDict("solids").subDict(ph.material);
        for (const word k : {"velocity", "angularVelocity"})
        {
            PtrList<Function1<vector>>& f =
                k == "velocity" ? velocity_ : angularVelocity_;
            if (d.found(k))
            {
                f.set(i, Function1<vector>::New(k, d));
            }
            else
            {
                f.set
                (
                    i,
                    new Function1Types::Constant<vector>(k, Zero)
                );
            }
        }
    }
    materials_.transfer(rigid);

    // The fixed point's history, as the run that wrote the start time left
    // it (a restart continues exactly)
    if (poses_.active())
    {
        const dictionary& h = poses_.solverState();
        List<scalarList> dX(h.getOrDefault<List<scalarList>>("dX", {}));
        List<scalarList> dF(h.getOrDefault<List<scalarList>>("dF", {}));
        dX_.clear();
        dF_.clear();
        forAll(dX, k)
        {
            dX_.append(dX[k]);
            dF_.append(dF[k]);
        }
    }
    if (active())
    {
        Info<< "Rigid bodies: the velocity of each body of";
        for (const label i : materials_)
        {
            Info<< ' ' << mixture_.phases()[i].name;
        }
        Info<< " held rigid in the momentum solve and projected onto"
            << " rigid motion every step" << nl << endl;
    }
}


void Foam::rigidBodies::move(vheMixture& mixture, const volVectorField& U)
{
    if (!poses_.active()) return;
    if (!poses_.velocityKnown())
    {
        // The first step of a case as placed: the bodies' motion is the
        // one of the initial velocity field
        update();
        List<vector> Ub, omega;
        rigidMotion(U.primitiveField(), Ub, omega);
        holdMotion(Ub, omega);
        poses_.setMotion(Ub, omega, Xm_, regions_);
    }
    poses_.move(mixture);
}


void Foam::rigidBodies::update()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const scalarField& V = mesh.V();
    const scalarField& rho = mixture_.rho().primitiveField();
    const label nCells = mesh.nCells();

    body_.setSize(nCells);
    body_ = -1;
    w_.setSize(nCells);
    w_ = 0;
    rhoAlpha_.setSize(nCells);
    rhoAlpha_ = 0;
    reached_.setSize(nCells);
    reached_ = 0;

    // Each cell goes to the body that moves most of it (a cell that two
    // bodies reach belongs to one only, so that each body's sums and its
    // projection see the same cells and its momentum is kept exactly)
    DynamicList<vector> X0;
    DynamicList<bool> held;
    DynamicList<label> phaseOf;
    DynamicList<vector> heldU, heldW;
    const scalar t = mesh.time().value();
    // A body of phase i held to a motion (fixed or prescribed) or free
    const auto holdTo = [&](const label i)
    {
        const vheMixture::phase& ph = mixture_.phases()[i];
        phaseOf.append(i);
        held.append(ph.fixed || ph.prescribed);
        heldU.append(ph.prescribed ? velocity_[i].value(t) : Zero);
        heldW.append(ph.prescribed ? angularVelocity_[i].value(t) : Zero);
    };
    nBodies_ = 0;

    // The bodies drawn from their poses
    for (label b = 0; b < poses_.size(); ++b)
    {
        const scalar rhoS = mixture_.phases()[poses_[b].phase].rho;
        const DynamicList<label>& cells = poses_.cells(b);
        const DynamicList<scalar>& alpha = poses_.alpha(b);
        forAll(cells, k)
        {
            const label c = cells[k];
            const scalar wc = weight(alpha[k]);
            if (wc <= 0) continue;
            ++reached_[c];
            if (wc > w_[c])
            {
                w_[c] = wc;
                body_[c] = b;
                rhoAlpha_[c] = rhoS*alpha[k];
            }
        }
        X0.append(poses_[b].X);
        holdTo(poses_[b].phase);
    }
    nBodies_ = poses_.size();

    // The bodies of the materials carried by the phase transport
    for (const label i : materials_)
    {
        if (poses_.posed(i)) continue;
        const scalarField& a = mixture_.alphas()[i].primitiveField();
        if (gMax(a) <= 0) continue;      // a spare colour: no body
        regions_.find(a);
        const labelList& lab = regions_.cellBody();
        forAll(lab, c)
        {
            if (lab[c] < 0) continue;
            const scalar wc = weight(a[c]);
            if (wc <= 0) continue;
            ++reached_[c];
            if (wc > w_[c])
            {
                w_[c] = wc;
                body_[c] = nBodies_ + lab[c];
                rhoAlpha_[c] = mixture_.phases()[i].rho*a[c];
            }
        }
        X0.append(regions_.centroid());
        for (label b = 0; b < regions_.size(); ++b) holdTo(i);
        nBodies_ += regions_.size();
    }
    held_.transfer(held);
    bodyPhase_.transfer(phaseOf);
    updated_ = mesh.time().timeIndex();
    shaped_.setSize(nBodies_);
    // The wall edge (edge()) for the bodies whose shapes setBodies placed:
    // those drawn from their poses (free or prescribed) and those of
    // fixed materials
    forAll(shaped_, b)
    {
        shaped_[b] = b < poses_.size() || poses_.fixedShape(bodyPhase_[b]);
    }
    flowW_ = w_;
    edge();
    heldU_.transfer(heldU);
    heldW_.transfer(heldW);

    // Mass, centre of mass, positions and second moment (bodyRegions)
    regions_.moments(body_, X0, rho*w_*V, M_, Xm_, r_, J_);

    // The solid's mass of each body, for the held bodies' forces only
    solidMass_ = scalarList(nBodies_, Zero);
    if (held_.found(true))
    {
        forAll(body_, c)
        {
            if (body_[c] >= 0) solidMass_[body_[c]] += rhoAlpha_[c]*V[c];
        }
        bodyRegions::sumLists(solidMass_);
    }
}


void Foam::rigidBodies::moments
(
    const scalarField& k,
    scalarList& S0,
    List<symmTensor>& S2
) const
{
    bodyRegions::sums
    (
        body_, nBodies_, k*w_*mixture_.rho().mesh().V(), r_, S0, S2
    );
}


void Foam::rigidBodies::rigidMotion
(
    const vectorField& u,
    List<vector>& Ub,
    List<vector>& omega
) const
{
    const scalarField& V = mixture_.rho().mesh().V();
    const scalarField& rho = mixture_.rho().primitiveField();
    List<vector> P(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b >= 0) P[b] += rho[c]*w_[c]*V[c]*u[c];
    }
    bodyRegions::sumLists(P);
    Ub.setSize(nBodies_);
    forAll(Ub, b) Ub[b] = P[b]/max(M_[b], VSMALL);

    List<vector> L(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b >= 0) L[b] += rho[c]*w_[c]*V[c]*(r_[c] ^ (u[c] - Ub[b]));
    }
    bodyRegions::sumLists(L);
    omega.setSize(nBodies_);
    forAll(omega, b)
    {
        vhe_body_omega
        (
            J_[b].cdata(), L[b].cdata(), regions_.normal(), omega[b].data()
        );
    }
}


void Foam::rigidBodies::writeForces
(
    const List<vector>& Fc,
    const List<vector>& Tc
)
{
    // The fluid's force on a fixed body: what holds it, less the body
    // force on its own mass (gravity and bodyForce on sum rho_s alpha V,
    // the solid's mass: the rest of its edge cells is fluid): the drag
    // and lift of an obstacle, about its centre of mass.  (In a steady
    // flow driven by a body force f, the forces on the fixed bodies sum
    // to f times the fluid's mass exactly)
    if (!held_.found(true)) return;

    const fvMesh& mesh = mixture_.rho().mesh();
    // g is registered with the mesh or (v1912's gravity) with the time
    vector gb(mixture_.bodyForce().value());
    for (const objectRegistry* db : {&mesh.thisDb(), &mesh.time().db()})
    {
        if (db->foundObject<uniformDimensionedVectorField>("g"))
        {
            gb += db->lookupObject<uniformDimensionedVectorField>("g").value();
            break;
        }
    }

    if (Pstream::master() && !forceFile_.valid())
    {
        const fileName dir
        (
            mesh.time().globalPath()/"postProcessing"/"fixedBodies"
           /mesh.time().timeName(mesh.time().startTime().value())
        );
        mkDir(dir);
        forceFile_.reset(new OFstream(dir/"forces.dat"));
        forceFile_()
            << "# The fluid's force and torque (about the centre of mass)"
            << " on each fixed or prescribed rigid body [N, N m]" << nl
            << "# time body Fx Fy Fz Tx Ty Tz" << endl;
    }
    if (Pstream::master())
    {
        OFstream& os = forceFile_();
        os.precision(10);
        forAll(held_, b)
        {
            if (!held_[b]) continue;
            const vector F(-Fc[b] - solidMass_[b]*gb);
            const vector T(-Tc[b]);
            os  << mesh.time().value() << ' ' << b << ' '
                << F.x() << ' ' << F.y() << ' ' << F.z() << ' '
                << T.x() << ' ' << T.y() << ' ' << T.z() << nl;
        }
        os.flush();
    }
}


void Foam::rigidBodies::holdMotion
(
    List<vector>& Ub,
    List<vector>& omega
) const
{
    forAll(held_, b)
    {
        if (held_[b])
        {
            Ub[b] = heldU_[b];
            omega[b] = heldW_[b];
        }
    }
}


Foam::tmp<Foam::vectorField> Foam::rigidBodies::rigidField
(
    const List<vector>& Ub,
    const List<vector>& omega
) const
{
    tmp<vectorField> tUR(new vectorField(body_.size(), Zero));
    vectorField& UR = tUR.ref();
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b >= 0) UR[c] = Ub[b] + (omega[b] ^ r_[c]);
    }
    return tUR;
}


Foam::tmp<Foam::scalarField> Foam::rigidBodies::timeCoefficient
(
    const volVectorField& U
) const
{
    return tmp<scalarField>
    (
        new scalarField(fvm::ddt(mixture_.rho(), U)().A())
    );
}


Foam::scalar Foam::rigidBodies::viscousNumber(const scalar dt) const
{
    const scalarField& mu = mixture_.mu().primitiveField();
    const scalarField& rho = mixture_.rho().primitiveField();
    const bodyShapes& shapes = poses_.shapes();
    scalar vn = 0;
    for (const label i : materials_)
    {
        const scalarField& a = mixture_.alphas()[i].primitiveField();
        forAll(a, c)
        {
            if (a[c] <= 0 || a[c] >= 1) continue;
            vn = max(vn, mu[c]/rho[c]*dt/sqr(shapes.cellSize(c)));
        }
    }
    return returnReduce(vn, maxOp<scalar>());
}


// ************************************************************************* //
