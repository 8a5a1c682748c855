/*---------------------------------------------------------------------------*\
  vheFoam: short-range contact between bodies
\*---------------------------------------------------------------------------*/

#include "bodyContact.H"
#include "bodyRegions.H"
#include "fvcGrad.H"
#include "syncTools.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyContact::bodyContact(const vheMixture& mixture)
:
    mixture_(mixture),
    range_(1.5),
    strength_(0),
    dtRef_(1),
    h_(),
    coupled_(),
    regions_(mixture.rho().mesh(), 0.5),
    force_()
{
    // Default: off.  (It was on for rigid materials while rigid bodies
    // were projected onto rigid motion after the step and closed in to
    // half a cell; held rigid inside the momentum solve they feel the
    // liquid between them and keep 0.76 cell apart in test_contact, and
    // contact at strength 0.5 made scene A's rigid suspension at area
    // fraction 0.2 2.3 times more viscous than without it: nu_m/nu0 3.0
    // against 1.31)
    const dictionary dict(mixture.subOrEmptyDict("contact"));
    range_ = dict.getOrDefault<scalar>("range", range_);
    strength_ = dict.getOrDefault<scalar>("strength", strength_);
    // Tested from 1 to 2 cells (the 40-disk channel of test_colours with
    // soft contact: 40 bodies to t = 20 with range 1.5 and 2); with range
    // 2 it once failed at t = 12.9, when shreds were still pushed
    if (range_ < 1 || range_ > 2)
    {
        FatalIOErrorInFunction(mixture)
            << "contact { range } must lie in [1, 2] cells (the range"
            << " tested), got " << range_ << exit(FatalIOError);
    }
    if (strength_ < 0 || strength_ > 2)
    {
        FatalIOErrorInFunction(mixture)
            << "contact { strength } must lie in [0, 2] (above, the"
            << " contact spring oscillates faster than the steps), got "
            << strength_ << exit(FatalIOError);
    }
    for (const entry& e : dict)
    {
        if (e.keyword() != "range" && e.keyword() != "strength")
        {
            FatalIOErrorInFunction(mixture)
                << "Unknown entry '" << e.keyword() << "' in contact of "
                << mixture.objectPath() << "; valid: range, strength"
                << exit(FatalIOError);
        }
    }
    cellSizes();

    // The reference step: the largest step the run may take (maxDeltaT
    // with an adjustable step, else deltaT), fixed for the run.  (The
    // step itself would make a potential whose depth grows as the step
    // shrinks: a body pushed out gains speed, the Courant limit shrinks
    // the step, the push grows; two disks settling on each other ran
    // away to a step of 1e-35 s.)
    const Time& runTime = mixture.rho().mesh().time();
    const dictionary& cd = runTime.controlDict();
    dtRef_ = runTime.deltaTValue();
    if (strength_ > 0 && cd.getOrDefault<bool>("adjustTimeStep", false))
    {
        dtRef_ = cd.getOrDefault<scalar>("maxDeltaT", GREAT);
        if (dtRef_ >= GREAT)
        {
            FatalIOErrorInFunction(cd)
                << "contact between bodies needs maxDeltaT in "
                << runTime.system()/"controlDict"
                << " with adjustTimeStep: its strength is strength"
                << " h/maxDeltaT^2 (or set contact { strength 0; } in"
                << " constant/vheProperties)" << exit(FatalIOError);
        }
    }

    if (mixture.hasSolids() && strength_ > 0)
    {
        Info<< "Contact: bodies of different colours or materials repel"
            << " each other within "
            << range_ << " cells of their edge (strength " << strength_
            << ", reference step " << dtRef_ << " s)" << nl << endl;
    }
}


// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

namespace
{
    //- The share of a cell that the contact pushes with its body
    inline Foam::scalar core(const Foam::scalar a)
    {
        return a >= 0.5 ? a : 0;
    }
}


void Foam::bodyContact::cellSizes()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const Vector<label>& dirs = mesh.geometricD();
    const boundBox& bb = mesh.bounds();
    scalar depth = 1;
    label nD = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (dirs[d] == -1) depth *= bb.span()[d];
        else ++nD;
    }
    h_ = pow(mesh.V().field()/depth, 1.0/max(nD, label(1)));
    coupled_ = bodyRegions::coupledFaces(mesh);
}


Foam::tmp<Foam::volScalarField> Foam::bodyContact::proximity
(
    const scalarField& start
) const
{
    const fvMesh& mesh = mixture_.rho().mesh();
    tmp<volScalarField> tpsi
    (
        new volScalarField
        (
            IOobject("proximity", mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar(dimless, Zero),
            "zeroGradient"
        )
    );
    scalarField& psi = tpsi.ref().primitiveFieldRef();
    psi = start;

    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const label nInt = mesh.nInternalFaces();
    const boolList& coupled = coupled_;
    const scalar step = 1/range_;
    for (label layer = 0; layer < std::ceil(range_); ++layer)
    {
        const scalarField last(psi);
        vhe_proximity_layer
        (
            nInt, own.cdata(), nei.cdata(), last.cdata(), step, psi.data()
        );
        scalarField nbr;
        syncTools::swapBoundaryCellList(mesh, last, nbr);
        forAll(coupled, i)
        {
            if (coupled[i])
            {
                const label c = own[nInt + i];
                psi[c] = max(psi[c], nbr[i] - step);
            }
        }
    }
    tpsi.ref().correctBoundaryConditions();
    return tpsi;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyContact::correct()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const PtrList<volScalarField>& alphas = mixture_.alphas();

    // The solid phases with content
    DynamicList<label> solids;
    forAll(alphas, i)
    {
        if
        (
            mixture_.phases()[i].solid
         && gMax(alphas[i].primitiveField()) > 0
        )
        {
            solids.append(i);
        }
    }
    if (solids.size() < 2 || strength_ <= 0)
    {
        force_.clear();
        return;
    }

    if (!force_.valid() || force_->size() != mesh.nCells())
    {
        force_.reset
        (
            new volVectorField
            (
                IOobject("contactForce", mesh.time().timeName(), mesh),
                mesh,
                dimensionedVector(dimForce/dimVolume, Zero),
                "zeroGradient"
            )
        );
    }
    volVectorField& f = *force_;
    f == dimensionedVector(f.dimensions(), Zero);
    vectorField& fc = f.primitiveFieldRef();

    // The proximity of every body and its gradient
    PtrList<volScalarField> psi(solids.size());
    PtrList<volVectorField> gradPsi(solids.size());
    forAll(solids, k)
    {
        scalarField start(mesh.nCells());
        vhe_proximity_start
        (
            start.size(), alphas[solids[k]].primitiveField().cdata(),
            start.data()
        );
        psi.set(k, proximity(start).ptr());
        gradPsi.set(k, new volVectorField(fvc::grad(psi[k])));
    }

    // The local force's direction and distribution: -alpha_p psi_q
    // grad(psi_q) (its scale is set per body below)
    const scalarField& rho = mixture_.rho().primitiveField();
    const scalarField coef(rho.size(), 1.0);
    const scalarField& V = mesh.V().field();

    label nTouching = 0;
    forAll(solids, kp)
    {
        const scalarField& a = alphas[solids[kp]].primitiveField();

        // The local force on this phase's material near the others, and
        // how deep the material reaches into another body's range
        vectorField g(a.size(), Zero);
        scalarField depth(a.size(), Zero);
        forAll(solids, kq)
        {
            if (kq == kp) continue;
            vhe_contact_add
            (
                g.size(), coef.cdata(), a.cdata(),
                psi[kq].primitiveField().cdata(),
                gradPsi[kq].primitiveField().cdata()->v_, g.data()->v_
            );
            depth = max(depth, min(2*a, scalar(1))*psi[kq].primitiveField());
        }
        if (gMax(depth) <= 0)
        {
            continue;
        }

        // Each body of the phase takes the force and torque of its local
        // contact forces as a whole, as a rigid body's acceleration
        // (Glowinski's collision force on a particle): a force applied
        // where it acts, at the contact, would be nearly a gradient,
        // which the pressure takes up without moving the bodies
        // (measured: the same smallest gap with and without it).  Only
        // its core (fraction >= 1/2) is pushed: pushed in its diffuse
        // edge too, where the other body is pushed the other way, the
        // edges were sheared into shreds (seen in the 40-disk channel: a
        // cell's worth of a disk torn off for a write)
        regions_.find(a);
        const label nB = regions_.size();
        const labelList& lab = regions_.cellBody();
        // A shred (a piece of a few cells torn off a body) is not pushed:
        // pushed as a body, at an acceleration that does not depend on
        // its mass, it was flung through the soft body it sat on, and the
        // velocity gradient broke the stretch (two disks settling on each
        // other at a wall: a floating point exception at t = 1.9)
        const scalar minVolume = regions_.minBodyVolume();
        const scalarList& vol = regions_.volume();
        const List<vector>& X0 = regions_.centroid();
        // Mass, centre of mass, positions and second moment of the core
        // (bodyRegions), and the sums of contact's own
        scalarList M;
        List<vector> Xm;
        vectorField r;
        List<symmTensor> J;
        scalarField m(a.size());
        forAll(m, c) m[c] = rho[c]*core(a[c])*V[c];
        regions_.moments(lab, X0, m, M, Xm, r, J);
        scalarList H(nB, Zero), D(nB, Zero);
        List<vector> F(nB, Zero), T(nB, Zero);
        forAll(lab, c)
        {
            const label b = lab[c];
            if (b < 0) continue;
            H[b] += m[c]*h_[c];
            D[b] = max(D[b], depth[c]);
            F[b] += g[c]*V[c];
            T[b] += r[c] ^ (g[c]*V[c]);
        }
        bodyRegions::sumLists(H);
        bodyRegions::sumLists(F);
        bodyRegions::sumLists(T);
        Pstream::listCombineGather(D, maxEqOp<scalar>());
        Pstream::listCombineScatter(D);
        // The body's acceleration: strength depth h/dtRef^2 along F, and the
        // angular acceleration of the torque scaled alike
        List<vector> acc(nB, Zero), dOmega(nB, Zero);
        forAll(acc, b)
        {
            if (mag(F[b]) <= 0 || M[b] <= 0 || vol[b] < minVolume) continue;
            const scalar hb = H[b]/M[b];
            const scalar scale =
                strength_*D[b]*hb/sqr(dtRef_)*M[b]/mag(F[b]);
            acc[b] = scale*F[b]/M[b];
            const vector Tb(scale*T[b]);
            vhe_body_omega
            (
                J[b].cdata(), Tb.cdata(), regions_.normal(),
                dOmega[b].data()
            );
            ++nTouching;
        }
        forAll(lab, c)
        {
            const label b = lab[c];
            if (b < 0) continue;
            fc[c] += rho[c]*core(a[c])*(acc[b] + (dOmega[b] ^ r[c]));
        }
    }
    if (!nTouching)
    {
        force_.clear();
        return;
    }
    f.correctBoundaryConditions();
    Info<< "Contact: " << nTouching << " bodies in contact" << endl;
}


// ************************************************************************* //
