/*---------------------------------------------------------------------------*\
  vheFoam: rigid bodies -- the fixed point that holds the bodies inside
  the momentum solve
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

void Foam::rigidBodies::penaltyForces
(
    const scalarField& cp,
    const vectorField& UR,
    const vectorField& U,
    const scalarField& V
) const
{
    const vectorField fc(cp*(UR - U)*V);
    Fpen_ = List<vector>(nBodies_, Zero);
    Tpen_ = List<vector>(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        Fpen_[b] += fc[c];
        Tpen_[b] += r_[c] ^ fc[c];
    }
    bodyRegions::sumLists(Fpen_);
    bodyRegions::sumLists(Tpen_);
}


void Foam::rigidBodies::solve
(
    const fvVectorMatrix& UEqn,
    const volVectorField& rhs,
    volVectorField& U,
    const std::function<void(fvVectorMatrix&, coupledRigidRows*)>&
        coupledSolve,
    bool rigidRows
) const
{
    const fvMesh& mesh = U.mesh();
    const scalarField& V = mesh.V();

    // The penalty: a held cell (hold 1) at P times A; a fluid cell beside
    // a known surface at the wall's missing viscous stress, mu wallK/V
    // (edge()); a cell of a body whose shape is not known, of hold w in
    // (0, 1), takes w U_R + (1 - w) U_free, U_free its steady velocity
    // without the penalty (that C leaves out the time derivative's
    // rho/dt, else the blend compounds step after step at small dt)
    const volScalarField A(UEqn.A());
    volScalarField Cp
    (
        IOobject("rigidPenalty", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(A.dimensions(), Zero)
    );
    scalarField& cp = Cp.primitiveFieldRef();
    const scalarField Addt(timeCoefficient(U));
    const scalarField& mu = mixture_.mu().primitiveField();
    forAll(body_, c)
    {
        if (body_[c] < 0) continue;
        const scalar h = hold_[c];
        const scalar k =
            h < 1
          ? (A[c] - Addt[c])*h/(1 - h) + mu[c]*wallK_[c]/V[c]
          : penalty*A[c];
        cp[c] = min(penalty*A[c], k);
    }

    // Start from the last projection's rigid motion
    List<vector> Ub, omega;
    rigidMotion(U.primitiveField(), Ub, omega);
    holdMotion(Ub, omega);

    // The bodies' velocities solved with the flow, in one matrix (none
    // of the fixed point's preconditioner below is needed)
    if (coupledSolve && rigidRows)
    {
        const scalarField cpV(cp*V);
        coupledRigidRows rows{body_, cpV, r_, held_, Ub, omega};
        fvVectorMatrix UEqnHeld(UEqn + fvm::Sp(Cp, U));
        coupledSolve(UEqnHeld, &rows);
        penaltyForces(cp, rigidField(Ub, omega), U.primitiveField(), V);
        Info<< "Rigid bodies: " << nBodies_
            << " held in 1 solve with the flow" << endl;
        return;
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
        if (coupledSolve)
        {
            fvVectorMatrix UEqnHeld(UEqn + fvm::Sp(Cp, U) == Cp*UR);
            coupledSolve(UEqnHeld, nullptr);
        }
        else
        {
            fvVectorMatrix UEqnHeld(UEqn + fvm::Sp(Cp, U) == rhs + Cp*UR);
            UEqnHeld.solve(solverDict);
        }

        // The penalty's net force and torque on each body
        penaltyForces(cp, UR.primitiveField(), U.primitiveField(), V);
        const List<vector>& F = Fpen_;
        const List<vector>& T = Tpen_;

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

// ************************************************************************* //
