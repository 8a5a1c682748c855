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
    nBodies_(0)
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
    scalarField rhoAlpha(nCells, Zero);
    reached_.setSize(nCells);
    reached_ = 0;

    // Each cell goes to the body that moves most of it (a cell that two
    // bodies reach belongs to one only, so that each body's sums and its
    // projection see the same cells and its momentum is kept exactly)
    DynamicList<vector> X0;
    DynamicList<bool> held;
    DynamicList<vector> heldU, heldW;
    const scalar t = mesh.time().value();
    // A body of phase i held to a motion (fixed or prescribed) or free
    const auto holdTo = [&](const label i)
    {
        const vheMixture::phase& ph = mixture_.phases()[i];
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
                rhoAlpha[c] = rhoS*alpha[k];
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
                rhoAlpha[c] = mixture_.phases()[i].rho*a[c];
            }
        }
        X0.append(regions_.centroid());
        for (label b = 0; b < regions_.size(); ++b) holdTo(i);
        nBodies_ += regions_.size();
    }
    held_.transfer(held);
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
            if (body_[c] >= 0) solidMass_[body_[c]] += rhoAlpha[c]*V[c];
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


void Foam::rigidBodies::solve
(
    const fvVectorMatrix& UEqn,
    const volVectorField& rhs,
    volVectorField& U
) const
{
    const fvMesh& mesh = U.mesh();
    const scalarField& V = mesh.V();

    // The penalty: a cell of weight w takes w U_R + (1 - w) U_free, U_free
    // its steady velocity without the penalty (the edge's C leaves out
    // the time derivative's rho/dt, else the blend compounds step after
    // step at small dt); a cell of weight 1 is held at P times A
    const volScalarField A(UEqn.A());
    volScalarField Cp
    (
        IOobject("rigidPenalty", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(A.dimensions(), Zero)
    );
    scalarField& cp = Cp.primitiveFieldRef();
    const scalarField Addt(fvm::ddt(mixture_.rho(), U)().A());
    forAll(body_, c)
    {
        if (body_[c] < 0) continue;
        cp[c] = w_[c] < 1
          ? min(penalty*A[c], (A[c] - Addt[c])*w_[c]/(1 - w_[c]))
          : penalty*A[c];
    }

    // Each body's inertia over the step K0 (the time derivative's share
    // of A), in translation and rotation: the preconditioner's base
    scalarList KV;
    List<symmTensor> KJ;
    moments(Addt, KV, KJ);
    // Radius of gyration: a rotation's velocity scale
    scalarList Rg(nBodies_);
    forAll(Rg, b) Rg[b] = Foam::sqrt(tr(J_[b])/max(M_[b], VSMALL));

    // The viscous drag's share of the resistance, estimated from Stokes
    // drag over a step: a body of gyration radius Rg in a liquid of
    // viscosity mu resists a change of its velocity by about
    // (1 + cV nu dt/Rg^2) its inertia, of its rotation by (1 + cW nu
    // dt/Rg^2) (cV 2, cW 6: a disk's or a sphere's within a factor of 2);
    // the preconditioner K0 (1 + c nu dt/Rg^2) leaves the coupling
    // between bodies to the acceleration.  nu is the mean over the body's
    // cells (its material's and its edge's): an estimate, as the
    // preconditioner needs
    scalarList dragV(nBodies_, Zero), dragW(nBodies_, Zero);
    {
        const scalarField& mu = mixture_.mu().primitiveField();
        const scalarField& rho = mixture_.rho().primitiveField();
        scalarList nuSum(nBodies_, Zero), wSum(nBodies_, Zero);
        forAll(body_, c)
        {
            const label b = body_[c];
            if (b < 0) continue;
            nuSum[b] += w_[c]*V[c]*mu[c]/rho[c];
            wSum[b] += w_[c]*V[c];
        }
        bodyRegions::sumLists(nuSum);
        bodyRegions::sumLists(wSum);
        const scalar dt = mesh.time().deltaTValue();
        forAll(dragV, b)
        {
            const scalar vn =
                nuSum[b]/max(wSum[b], VSMALL)*dt/max(sqr(Rg[b]), VSMALL);
            dragV[b] = 1 + 2*vn;
            dragW[b] = 1 + 6*vn;
        }
    }

    // Start from the last projection's rigid motion
    List<vector> Ub, omega;
    rigidMotion(U.primitiveField(), Ub, omega);
    holdMotion(Ub, omega);

    volVectorField UR
    (
        IOobject("UR", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    // The penalty raises the matrix's residual normalisation by up to P,
    // and the body's net force is P times the held cells' small velocity
    // error: U's tolerance divided by P (and no relTol), else the force
    // carries the solver's error times P
    dictionary solverDict
    (
        mesh.solverDict
        (
            U.select
            (
                mesh.data::template lookupOrDefault<bool>
                (
                    "finalIteration", false
                )
            )
        )
    );
    solverDict.set("tolerance", solverDict.get<scalar>("tolerance")/penalty);
    solverDict.set("relTol", scalar(0));

    // The unknowns in velocity units, 6 per body: U_b and Rg omega
    const label n = 6*nBodies_;
    scalarList x(n), f(n, Zero), xPrev(n), fPrev(n);
    forAll(Ub, b)
    {
        for (direction d = 0; d < 3; ++d)
        {
            x[6*b + d] = Ub[b][d];
            x[6*b + 3 + d] = omega[b][d]*Rg[b];
        }
    }

    // Anderson acceleration (type II, the last nHistory differences) of
    // x <- x + f(x), f = -K^-1 R with K the resistance estimated above: on
    // this linear problem it is GMRES, so bodies that move each other
    // through the liquid converge as surely as one body alone.  The error
    // is estimated by the last update |dx|, on the first iterate by f
    const label nHistory = 6;
    DynamicList<scalarList>& dX = dX_;
    DynamicList<scalarList>& dF = dF_;
    if (dX.size() && dX[0].size() != n)
    {
        dX.clear();
        dF.clear();
    }
    label iter = 0;
    scalar change = 0;
    for (iter = 1; iter <= maxIter; ++iter)
    {
        forAll(Ub, b)
        {
            for (direction d = 0; d < 3; ++d)
            {
                Ub[b][d] = x[6*b + d];
                omega[b][d] = x[6*b + 3 + d]/max(Rg[b], VSMALL);
            }
        }
        UR.primitiveFieldRef() = rigidField(Ub, omega);
        fvVectorMatrix UEqnHeld(UEqn + fvm::Sp(Cp, U) == rhs + Cp*UR);
        UEqnHeld.solve(solverDict);

        // The penalty's net force and torque on each body
        const vectorField fc
        (
            cp*(UR.primitiveField() - U.primitiveField())*V
        );
        List<vector>& F = Fpen_;
        List<vector>& T = Tpen_;
        F = List<vector>(nBodies_, Zero);
        T = List<vector>(nBodies_, Zero);
        forAll(body_, c)
        {
            const label b = body_[c];
            if (b < 0) continue;
            F[b] += fc[c];
            T[b] += r_[c] ^ fc[c];
        }
        bodyRegions::sumLists(F);
        bodyRegions::sumLists(T);

        // The preconditioned residual: the penalty holds the body back,
        // so the free body moves the other way, -K^-1 R
        forAll(Ub, b)
        {
            const vector zV(-F[b]/max(KV[b], VSMALL));
            vector zW(Zero);
            const vector Tb(-T[b]);
            vhe_body_omega(KJ[b].cdata(), Tb.cdata(), regions_.normal(),
                zW.data());
            const scalar free = held_[b] ? 0 : 1;
            for (direction d = 0; d < 3; ++d)
            {
                f[6*b + d] = free*zV[d]/dragV[b];
                f[6*b + 3 + d] = free*zW[d]*Rg[b]/dragW[b];
            }
        }
        const scalar Uscale = max(gMax(mag(U.primitiveField())), VSMALL);
        if (iter == 1)
        {
            change = 0;
            forAll(f, i) change = max(change, mag(f[i]));
            change /= Uscale;
        }
        if (change < tolerance || iter == maxIter) break;

        if (iter > 1)
        {
            scalarList ddx(n), ddf(n);
            forAll(ddx, i)
            {
                ddx[i] = x[i] - xPrev[i];
                ddf[i] = f[i] - fPrev[i];
            }
            if (dX.size() == nHistory)
            {
                for (label k = 1; k < nHistory; ++k)
                {
                    dX[k - 1] = dX[k];
                    dF[k - 1] = dF[k];
                }
                dX.resize(nHistory - 1);
                dF.resize(nHistory - 1);
            }
            dX.append(ddx);
            dF.append(ddf);
        }
        xPrev = x;
        fPrev = f;

        // gamma = argmin |f - dF gamma|: normal equations of the columns
        // scaled to unit norm, regularised
        const label m = dF.size();
        scalarList gamma(m, Zero);
        if (m > 0)
        {
            scalarList scale(m, Zero);
            for (label k = 0; k < m; ++k)
            {
                forAll(f, i) scale[k] += sqr(dF[k][i]);
                scale[k] = Foam::sqrt(scale[k]);
            }
            scalarSquareMatrix N(m, Zero);
            scalarList rhsN(m, Zero);
            for (label k = 0; k < m; ++k)
            {
                if (scale[k] <= VSMALL) { N(k, k) = 1; continue; }
                for (label l = 0; l < m; ++l)
                {
                    if (scale[l] <= VSMALL) continue;
                    forAll(f, i) N(k, l) += dF[k][i]*dF[l][i];
                    N(k, l) /= scale[k]*scale[l];
                }
                forAll(f, i) rhsN[k] += dF[k][i]*f[i];
                rhsN[k] /= scale[k];
                N(k, k) += 1e-10;
            }
            gamma = rhsN;
            Foam::solve(N, gamma);
            for (label k = 0; k < m; ++k)
            {
                gamma[k] = scale[k] > VSMALL ? gamma[k]/scale[k] : 0;
            }
        }
        change = 0;
        forAll(x, i)
        {
            scalar dx = f[i];
            for (label k = 0; k < m; ++k)
            {
                dx -= (dX[k][i] + dF[k][i])*gamma[k];
            }
            x[i] += dx;
            change = max(change, mag(dx));
        }
        change /= Uscale;
    }
    if (poses_.active())
    {
        dictionary h;
        h.add("dX", List<scalarList>(dX_));
        h.add("dF", List<scalarList>(dF_));
        poses_.setSolverState(h);
    }
    Info<< "Rigid bodies: " << nBodies_ << " held in "
        << iter << " momentum solves, velocity error below "
        << change << " of |U|max" << endl;
}


void Foam::rigidBodies::correct(volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    vectorField& u = U.primitiveFieldRef();

    List<vector>& Ub = Ub_;
    List<vector>& omega = omega_;
    rigidMotion(u, Ub, omega);
    holdMotion(Ub, omega);
    if (poses_.active())
    {
        poses_.constrain(Ub);
        poses_.setMotion(Ub, omega, Xm_, regions_);
    }
    // The force that holds each body: the penalty's in the held solve and
    // the momentum this projection takes from its cells
    const scalarField& rho = mixture_.rho().primitiveField();
    const scalarField& V = mesh.V();
    const scalar dt = mesh.time().deltaTValue();
    List<vector> Fc(nBodies_, Zero), Tc(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        const vector du(w_[c]*(Ub[b] + (omega[b] ^ r_[c]) - u[c]));
        const vector f(rho[c]*V[c]*du/dt);
        Fc[b] += f;
        Tc[b] += r_[c] ^ f;
        u[c] += du;
    }
    U.correctBoundaryConditions();
    bodyRegions::sumLists(Fc);
    bodyRegions::sumLists(Tc);
    if (Fpen_.size() == nBodies_)
    {
        forAll(Fc, b)
        {
            Fc[b] += Fpen_[b];
            Tc[b] += Tpen_[b];
        }
    }
    writeForces(Fc, Tc);

    // A cell moves wholly with a body where its weight is 1/10 or more
    // (a fraction of 1/40) and no other body reaches it: the faces between
    // two such cells of one body carry the body's rigid flux (rigidFlux),
    // so the body's diffuse edge moves with it.  (Faces between cells of
    // weight 1 only left the edge to the fluid's flux: a disk in shear
    // reached a Taylor deformation of 0.017 at 32 cells, now 0.0027; a
    // settling disk 0.052 by t = 0.28, now 0.025.  Not every cell the
    // body reaches: its tails of 1e-18 would lock liquid cells to it, and
    // the flux correction had no consistent solution.)  Else the faces
    // between it and the body's other cells would carry a flux that is
    // not the body's, whose divergence nothing corrects
    // A cell next to a cell of another body does not move wholly either:
    // where two bodies' wholly moving cells met face to face, the cells
    // on either side of that face had every other face's flux fixed, and
    // the flux correction had no solution there (two rigid disks of 1.6
    // cells' radius touching in a 32-cell channel: pcorr's DIC divided by
    // zero)
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    boolList nearOther(mesh.nCells(), false);
    {
        forAll(nei, f)
        {
            const label bo = body_[own[f]], bn = body_[nei[f]];
            if (bo >= 0 && bn >= 0 && bo != bn)
            {
                nearOther[own[f]] = true;
                nearOther[nei[f]] = true;
            }
        }
        labelList bodyNbr;
        syncTools::swapBoundaryCellList(mesh, body_, bodyNbr);
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (!pp.coupled()) continue;
            const label start = pp.start() - mesh.nInternalFaces();
            forAll(pp, i)
            {
                const label c = pp.faceCells()[i];
                const label bn = bodyNbr[start + i];
                if (body_[c] >= 0 && bn >= 0 && body_[c] != bn)
                {
                    nearOther[c] = true;
                }
            }
        }
    }
    labelList wholly(mesh.nCells(), -1);
    forAll(wholly, c)
    {
        if
        (
            body_[c] >= 0 && w_[c] >= 0.1 && reached_[c] == 1
         && !nearOther[c]
        )
        {
            wholly[c] = body_[c];
        }
    }

    // The faces whose two cells move wholly with one body.  (Two bodies
    // that touch: the faces between them are not rigid, else a cell
    // between two bodies moving apart or together could have every face's
    // flux fixed, and no pressure could make it divergence-free: the
    // flux correction diverged when rigid bodies collided.)
    if (!rigidFaces_.valid())
    {
        rigidFaces_.reset
        (
            new surfaceScalarField
            (
                IOobject("rigidFaces", mesh.time().timeName(), mesh),
                mesh,
                dimensionedScalar(dimless, Zero)
            )
        );
    }
    surfaceScalarField& rf = *rigidFaces_;
    rf = dimensionedScalar(dimless, Zero);
    forAll(nei, f)
    {
        rf[f] = (wholly[own[f]] >= 0 && wholly[own[f]] == wholly[nei[f]]);
    }
    labelList whollyNbr;
    syncTools::swapBoundaryCellList(mesh, wholly, whollyNbr);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (pp.coupled())
        {
            const label start = pp.start() - mesh.nInternalFaces();
            scalarField& rp = rf.boundaryFieldRef()[patchi];
            forAll(rp, i)
            {
                const label w = wholly[pp.faceCells()[i]];
                rp[i] = (w >= 0 && w == whollyNbr[start + i]);
            }
        }
    }

    Info<< "Rigid bodies: " << nBodies_ << " projected" << endl;
}


void Foam::rigidBodies::rigidFlux(surfaceScalarField& phi) const
{
    const fvMesh& mesh = phi.mesh();
    const surfaceScalarField& rf = *rigidFaces_;
    const vectorField& C = mesh.C().primitiveField();
    const vectorField& Cf = mesh.Cf().primitiveField();
    const vectorField& Sf = mesh.Sf().primitiveField();
    const labelUList& own = mesh.faceOwner();
    forAll(rf, f)
    {
        if (rf[f] <= 0) continue;
        const label c = own[f];
        const label b = body_[c];
        const vector r(r_[c] + Cf[f] - C[c]);
        phi[f] = (Ub_[b] + (omega_[b] ^ r)) & Sf[f];
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (!pp.coupled()) continue;
        const scalarField& rp = rf.boundaryField()[patchi];
        scalarField& pphi = phi.boundaryFieldRef()[patchi];
        const vectorField& pCf = pp.Cf();
        const vectorField& pSf = pp.Sf();
        forAll(rp, i)
        {
            if (rp[i] <= 0) continue;
            const label c = pp.faceCells()[i];
            const label b = body_[c];
            const vector r(r_[c] + pCf[i] - C[c]);
            pphi[i] = (Ub_[b] + (omega_[b] ^ r)) & pSf[i];
        }
    }
}


// ************************************************************************* //
