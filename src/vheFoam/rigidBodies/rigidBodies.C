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
const Foam::scalar Foam::rigidBodies::tolerance = 1e-6;
const Foam::label Foam::rigidBodies::maxIter = 10;


Foam::rigidBodies::rigidBodies(const vheMixture& mixture)
:
    mixture_(mixture),
    materials_(),
    regions_(mixture.rho().mesh(), 0.5),
    nBodies_(0)
{
    DynamicList<label> rigid;
    forAll(mixture_.phases(), i)
    {
        if (mixture_.phases()[i].rigid) rigid.append(i);
    }
    materials_.transfer(rigid);
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


void Foam::rigidBodies::update()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const vectorField& C = mesh.C().primitiveField();
    const scalarField& V = mesh.V();
    const scalarField& rho = mixture_.rho().primitiveField();
    const label nCells = mesh.nCells();

    body_.setSize(nCells);
    body_ = -1;
    w_.setSize(nCells);
    w_ = 0;
    reached_.setSize(nCells);
    reached_ = 0;

    // Each cell goes to the body that moves most of it (a cell that two
    // bodies reach belongs to one only, so that each body's sums and its
    // projection see the same cells and its momentum is kept exactly)
    DynamicList<vector> X0;
    nBodies_ = 0;
    for (const label i : materials_)
    {
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
            }
        }
        X0.append(regions_.centroid());
        nBodies_ += regions_.size();
    }

    // Mass and centre of mass (relative to the region's centroid)
    M_.setSize(nBodies_);
    M_ = Zero;
    List<vector> Rm(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        const scalar m = rho[c]*w_[c]*V[c];
        M_[b] += m;
        Rm[b] += m*regions_.nearestImage(C[c] - X0[b]);
    }
    bodyRegions::sumLists(M_);
    bodyRegions::sumLists(Rm);

    r_.setSize(nCells);
    r_ = Zero;
    J_.setSize(nBodies_);
    J_ = Zero;
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        r_[c] = regions_.nearestImage(C[c] - X0[b]) - Rm[b]/max(M_[b], VSMALL);
        J_[b] += rho[c]*w_[c]*V[c]*sqr(r_[c]);
    }
    bodyRegions::sumLists(J_);
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

    // The penalty: a cell of weight w takes w U_R + (1 - w) U_free
    const volScalarField A(UEqn.A());
    volScalarField Cp
    (
        IOobject("rigidPenalty", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(A.dimensions(), Zero)
    );
    scalarField& cp = Cp.primitiveFieldRef();
    forAll(body_, c)
    {
        if (body_[c] < 0) continue;
        cp[c] = A[c]*(w_[c] < 1 ? min(penalty, w_[c]/(1 - w_[c])) : penalty);
    }

    // The preconditioner K0: each body's inertia over the step (the time
    // derivative's share of A), in translation and rotation.  The true
    // resistance K adds added mass and viscous drag, so theta = K0/K is
    // at most 1 and |K0^-1 R| bounds the velocity error
    const volScalarField Ai(fvm::ddt(mixture_.rho(), U)().A());
    scalarList KV(nBodies_, Zero);
    List<symmTensor> KJ(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        const scalar k = Ai[c]*w_[c]*V[c];
        KV[b] += k;
        KJ[b] += k*sqr(r_[c]);
    }
    bodyRegions::sumLists(KV);
    bodyRegions::sumLists(KJ);
    // Radius of gyration: a rotation's velocity scale
    scalarList Rg(nBodies_);
    forAll(Rg, b) Rg[b] = Foam::sqrt(tr(J_[b])/max(M_[b], VSMALL));

    // Start from the last projection's rigid motion
    List<vector> Ub, omega;
    rigidMotion(U.primitiveField(), Ub, omega);

    volVectorField UR
    (
        IOobject("UR", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    // The penalty raises the matrix's residual normalisation by up to P,
    // and the body's net force is P times the held cells' small velocity
    // error: U's tolerance divided by P (and no relTol), else the force
    // is the solver's noise
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

    List<vector> xV0(Ub), xW0(omega), zV0(nBodies_), zW0(nBodies_);
    // The secant factors: the last step's (they change slowly), or 1;
    // the velocity error is theta |K0^-1 R| with a secant factor of this
    // solve or the last step's, |K0^-1 R| (theta <= 1) with fresh ones
    const bool fresh = (thetaV_.size() != nBodies_);
    if (fresh)
    {
        thetaV_ = List<vector>(nBodies_, vector::one);
        thetaW_ = List<vector>(nBodies_, vector::one);
    }
    List<vector>& thV = thetaV_;
    List<vector>& thW = thetaW_;
    label iter = 0;
    scalar change = 0;
    for (iter = 1; iter <= maxIter; ++iter)
    {
        UR.primitiveFieldRef() = rigidField(Ub, omega);
        fvVectorMatrix UEqnHeld(UEqn + fvm::Sp(Cp, U) == rhs + Cp*UR);
        UEqnHeld.solve(solverDict);

        // The penalty's net force and torque on each body
        const vectorField f(cp*(UR.primitiveField() - U.primitiveField())*V);
        List<vector> F(nBodies_, Zero), T(nBodies_, Zero);
        forAll(body_, c)
        {
            const label b = body_[c];
            if (b < 0) continue;
            F[b] += f[c];
            T[b] += r_[c] ^ f[c];
        }
        bodyRegions::sumLists(F);
        bodyRegions::sumLists(T);

        // Preconditioned residuals and the secant step per component:
        // the penalty holds the body back, so the free body moves the
        // other way, x <- x - theta K0^-1 R
        const scalar Uscale = max(gMax(mag(U.primitiveField())), VSMALL);
        change = 0;
        forAll(Ub, b)
        {
            const vector zV(-F[b]/max(KV[b], VSMALL));
            vector zW(Zero);
            const vector Tb(-T[b]);
            vhe_body_omega(KJ[b].cdata(), Tb.cdata(), regions_.normal(),
                zW.data());
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (iter > 1)
                {
                    const scalar dzV = zV[d] - zV0[b][d];
                    const scalar dzW = zW[d] - zW0[b][d];
                    if (mag(dzV) > VSMALL)
                    {
                        thV[b][d] = min(max
                        (
                            -(Ub[b][d] - xV0[b][d])/dzV, 1e-4), 1.0
                        );
                    }
                    if (mag(dzW) > VSMALL)
                    {
                        thW[b][d] = min(max
                        (
                            -(omega[b][d] - xW0[b][d])/dzW, 1e-4), 1.0
                        );
                    }
                }
                xV0[b][d] = Ub[b][d];
                xW0[b][d] = omega[b][d];
                zV0[b][d] = zV[d];
                zW0[b][d] = zW[d];
                Ub[b][d] += thV[b][d]*zV[d];
                omega[b][d] += thW[b][d]*zW[d];
                const scalar tV = (fresh && iter == 1) ? 1 : thV[b][d];
                const scalar tW = (fresh && iter == 1) ? 1 : thW[b][d];
                change = max(change, mag(tV*zV[d]));
                change = max(change, mag(tW*zW[d])*Rg[b]);
            }
        }
        change /= Uscale;
        if (change < tolerance) break;
    }
    Info<< "Rigid bodies: " << nBodies_ << " held in "
        << min(iter, maxIter) << " momentum solves, velocity error below "
        << change << " of |U|max" << endl;
}


void Foam::rigidBodies::correct(volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    vectorField& u = U.primitiveFieldRef();

    List<vector> Ub, omega;
    rigidMotion(u, Ub, omega);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b >= 0) u[c] += w_[c]*(Ub[b] + (omega[b] ^ r_[c]) - u[c]);
    }
    U.correctBoundaryConditions();

    // A cell moves wholly with a body where its weight is 1 and no other
    // body reaches it: else the faces between it and the body's other
    // cells would carry a flux that is not the body's, whose divergence
    // nothing corrects (the flux correction leaves a body's inner cells
    // alone)
    labelList wholly(mesh.nCells(), -1);
    forAll(wholly, c)
    {
        if (body_[c] >= 0 && w_[c] >= 1 && reached_[c] == 1)
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
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
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


// ************************************************************************* //
