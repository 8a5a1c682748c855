/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

Foam::wordList Foam::vheElasticity::patchTypes(const fvMesh& mesh)
{
    // Constraint patches (cyclic, empty, processor, symmetry, wedge) keep
    // their type; B* is extrapolated at every other boundary.
    wordList types
    (
        mesh.boundary().size(),
        zeroGradientFvPatchField<symmTensor>::typeName
    );
    forAll(mesh.boundaryMesh(), patchi)
    {
        const word& pt = mesh.boundaryMesh()[patchi].type();
        if (polyPatch::constraintType(pt)) types[patchi] = pt;
    }
    return types;
}


Foam::vheElasticity::vheElasticity(const vheMixture& mixture)
:
    mixture_(mixture),
    mesh_(mixture.rho().mesh()),
    Bstar_
    (
        IOobject
        (
            "Bstar",
            mesh_.time().timeName(),
            mesh_,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedSymmTensor(dimless, Zero),
        patchTypes(mesh_)
    ),
    semiImplicit_(true),
    backward_(false),
    transport_(mixture, mesh_.solutionDict().subDict("PIMPLE")),
    stabilisation_(0)
{
    const dictionary& pimple = mesh_.solutionDict().subDict("PIMPLE");
    const word variant
    (
        pimple.getOrDefault<word>("elasticity", "semiImplicit")
    );
    if (variant != "semiImplicit" && variant != "explicit")
    {
        FatalIOErrorInFunction(pimple)
            << "Unknown elasticity '" << variant << "'" << nl
            << "    Valid: (semiImplicit explicit)" << exit(FatalIOError);
    }
    semiImplicit_ = variant == "semiImplicit";
    stabilisation_ =
        pimple.getOrDefault<scalar>("elasticStabilisation", stabilisation_);
    if (stabilisation_ < 0)
    {
        FatalIOErrorInFunction(pimple)
            << "elasticStabilisation must be >= 0, got " << stabilisation_
            << exit(FatalIOError);
    }
    // Time integration follows the momentum equation's: Euler, or the
    // second-order backward (BDF2) scheme, whose stress of the new step
    // needs B* of the new step to second order too (see stretch)
    {
        ITstream& is = mesh_.ddtScheme("ddt(rho,U)");
        const word scheme(is);
        if (scheme != "Euler" && scheme != "backward")
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "ddt(rho,U) scheme '" << scheme << "' is not supported"
                << " with elastic bodies" << nl
                << "    Valid: (Euler backward)" << exit(FatalIOError);
        }
        backward_ = scheme == "backward";
        if (backward_ && !semiImplicit_)
        {
            FatalIOErrorInFunction(mesh_.schemesDict())
                << "ddt(rho,U) backward needs PIMPLE { elasticity"
                << " semiImplicit; } in " << mesh_.solutionDict().name()
                << " (an explicit stress is not second order in time)"
                << exit(FatalIOError);
        }
    }
    Info<< "Elastic stress: " << variant
        << (backward_ ? ", second order in time (backward, BDF2)" : "")
        << "; B carried as " << transport_.scheme()
        << endl;
    if (backward_)
    {
        // The increment of B* over the last step's stretch, carried by
        // BDF2 into the next.  Not written: a restart restarts the history
        // with a zero increment, as OpenFOAM's backward scheme does for U
        // (its old-old field starts as a copy of the old one).
        increment_.reset
        (
            new volSymmTensorField
            (
                IOobject
                (
                    "BstarIncrement", mesh_.time().timeName(), mesh_,
                    IOobject::NO_READ, IOobject::NO_WRITE
                ),
                mesh_,
                dimensionedSymmTensor(dimless, Zero),
                patchTypes(mesh_)
            )
        );
        increment_->oldTime();
    }

    if (Bstar_.headerOk())
    {
        Info<< "Read Bstar from " << Bstar_.objectPath() << endl;
        // A state that is not positive semi-definite has no meaning
        // (B = F F^T); stop rather than run on it.
        double diag[3];
        vhe_solid_diagnostics
        (
            mesh_.nCells(), mixture.phis().primitiveField().cdata(),
            flat(Bstar_.primitiveField()), 0.5, diag
        );
        const scalar minEig = returnReduce(diag[0], minOp<scalar>());
        if (minEig < -1e-9)
        {
            vheFieldFatalError(Bstar_.objectPath())
                << "Field " << Bstar_.objectPath()
                << " is not positive semi-definite: smallest eigenvalue "
                << minEig << exit(FatalIOError);
        }
        // The incompressible solid has det B = 1; a written field holds
        // it to its digits only (8 digits: det B to ~3e-8), and the
        // transport keeps whatever det it starts from.  Take B to its
        // unimodular part once, here.
        const scalar removed = returnReduce
        (
            vhe_bstar_unimodular
            (
                mesh_.nCells(), mixture.phis().primitiveField().cdata(),
                mixture.solidFractionMin(), 0.5,
                flat(Bstar_.primitiveFieldRef())
            ),
            maxOp<scalar>()
        );
        Bstar_.correctBoundaryConditions();
        Info<< "Bstar taken to det B = 1 (largest |det B - 1| read: "
            << removed << ")" << endl;
        if (removed > 1e-6)
        {
            WarningInFunction
                << Bstar_.objectPath() << " is not isochoric: |det B - 1|"
                << " up to " << removed << " (the solid is incompressible)"
                << endl;
        }
    }
    else
    {
        Info<< "No Bstar field: starting undeformed, B* = phi_s^(1/2) I"
            << endl;
        vhe_bstar_undeformed
        (
            mesh_.nCells(), mixture.phis().primitiveField().cdata(),
            flat(Bstar_.primitiveFieldRef())
        );
        Bstar_.correctBoundaryConditions();
    }
    Bstar_.oldTime();
}


void Foam::vheElasticity::advect(const volVectorField& U, scalar deltaT)
{
    transport_.advect(Bstar_, U, deltaT);
}


void Foam::vheElasticity::stretch(const volVectorField& U, scalar deltaT)
{
    // The flow is incompressible, but the cell gradient of U (interpolated
    // from cell values) is not exactly traceless, least of all where the
    // velocity changes fast (a heavy body hitting a wall): stretch with its
    // deviatoric part, so that det(F) = 1 and det B stays 1.  (dev, not the
    // trace over the solved directions only: the stress increment that the
    // semi-implicit momentum equation takes, Ghat phi_s dt (L + L^T -
    // 2/3 tr(L) I), is then exactly the increment of the stretched B*.)
    volTensorField gradU(velocityGradient(U, deltaT));
    gradU.primitiveFieldRef() = dev(gradU.primitiveField());
    if (!backward_)
    {
        vhe_stretch
        (
            mesh_.nCells(), deltaT, flat(gradU.primitiveField()),
            flat(Bstar_.primitiveFieldRef())
        );
        return;
    }
    // BDF2: B* - tau (L B* + B* L^T) = B*_advected + carry x the last
    // step's increment (the constant-step form: 3 B^(n+1) - 4 B^n +
    // B^(n-1) = 2 dt (L B + B L^T)^(n+1), B^n here already advected)
    const symmTensorField advected(Bstar_.primitiveField());
    const symmTensorField Bhat(predictorBstar());
    const size_t singular = vhe_stretch_implicit
    (
        mesh_.nCells(), stressStep(deltaT), flat(gradU.primitiveField()),
        flat(Bhat), flat(Bstar_.primitiveFieldRef())
    );
    const label nSingular = returnReduce(label(singular), sumOp<label>());
    if (nSingular)
    {
        WarningInFunction
            << nSingular << " cells with a singular BDF2 stretch (velocity"
            << " gradient x time step too large): B* kept" << endl;
    }
    increment_->primitiveFieldRef() = Bstar_.primitiveField() - advected;
}


Foam::scalar Foam::vheElasticity::backwardCoefficients
(
    scalar& carry
) const
{
    // OpenFOAM's backward scheme, coefft B^(n+1) - coefft0 B^n + coefft00
    // B^(n-1) = dt S^(n+1), as B^(n+1) - B^n = carry (B^n - B^(n-1)) +
    // (dt/coefft) S^(n+1), carry = coefft00/coefft.  Its first step (time
    // index < 2), and the Euler scheme: coefft 1, carry 0.
    carry = 0;
    if (!backward_ || mesh_.time().timeIndex() < 2)
    {
        return 1;
    }
    const scalar dt = mesh_.time().deltaTValue();
    const scalar dt0 = mesh_.time().deltaT0Value();
    const scalar coefft = 1 + dt/(dt + dt0);
    carry = dt*dt/(dt0*(dt + dt0))/coefft;
    return coefft;
}


Foam::scalar Foam::vheElasticity::stressStep(scalar deltaT) const
{
    scalar carry;
    return deltaT/backwardCoefficients(carry);
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::explicitVelocity
(
    const volVectorField& U,
    bool firstIter
) const
{
    if (!backward_ || !firstIter || mesh_.time().timeIndex() < 2)
    {
        return U;
    }
    // U^n + dt/dt0 (U^n - U^(n-1)): second-order at the new time
    const scalar ratio =
        mesh_.time().deltaTValue()/mesh_.time().deltaT0Value();
    const volVectorField& U0 = U.oldTime();
    return tmp<volVectorField>
    (
        new volVectorField("Uexplicit", U0 + ratio*(U0 - U0.oldTime()))
    );
}


Foam::tmp<Foam::symmTensorField> Foam::vheElasticity::predictorBstar() const
{
    tmp<symmTensorField> tB(new symmTensorField(Bstar_.primitiveField()));
    scalar carry;
    backwardCoefficients(carry);
    if (carry > 0)
    {
        tB.ref() += carry*increment_->oldTime().primitiveField();
    }
    return tB;
}


Foam::tmp<Foam::volTensorField> Foam::vheElasticity::velocityGradient
(
    const volVectorField& U,
    scalar deltaT
) const
{
    // Gauss gradient of face velocities whose normal component is the
    // conservative flux phi/|S_f|, not the interpolated cell velocity.
    // The two differ where the explicit elastic force jumps (a body's
    // surface): the pressure balances that force at the faces, but the
    // cell velocity, reconstructed from the faces, keeps a spurious normal
    // velocity there (+-2.6e-4 in the interface cells of the oscillating
    // Couette case, where the exact one is 0).  Its gradient stretched B*
    // along the normal (B_yy 1.026 at the interface, 2.5 % extra shear
    // rate), an O(1) error in one cell that left the velocity error of
    // first order.  With the flux, tr(grad U) = div(phi) = 0 to solver
    // tolerance and B* sees only the divergence-free motion.
    surfaceVectorField Uf(fvc::interpolate(U));
    if (stabilisation_ > 0)
    {
        Uf += faceVelocityCorrection(U, deltaT, true);
    }
    const surfaceScalarField& phi = mixture_.phi();
    auto toFlux = []
    (
        vectorField& uf,
        const vectorField& Sf,
        const scalarField& phif
    )
    {
        forAll(uf, facei)
        {
            const vector& S = Sf[facei];
            uf[facei] += (phif[facei] - (S & uf[facei]))/magSqr(S)*S;
        }
    };
    toFlux(Uf.primitiveFieldRef(), mesh_.Sf(), phi);
    forAll(Uf.boundaryField(), patchi)
    {
        toFlux
        (
            Uf.boundaryFieldRef()[patchi],
            mesh_.Sf().boundaryField()[patchi],
            phi.boundaryField()[patchi]
        );
    }
    return fvc::surfaceIntegrate(mesh_.Sf()*Uf);
}


Foam::tmp<Foam::surfaceScalarField> Foam::vheElasticity::bulkWeight() const
{
    // phi_s,P phi_s,N: 1 between solid cells, 0 at a sharp interface and
    // at non-coupled boundaries
    const volScalarField& phis = mixture_.phis();
    tmp<surfaceScalarField> tw
    (
        new surfaceScalarField
        (
            IOobject("bulkWeight", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedScalar(dimless, Zero)
        )
    );
    surfaceScalarField& w = tw.ref();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(own, facei)
    {
        w[facei] = phis[own[facei]]*phis[nei[facei]];
    }
    forAll(w.boundaryField(), patchi)
    {
        const fvPatchScalarField& pp = phis.boundaryField()[patchi];
        if (pp.coupled())
        {
            w.boundaryFieldRef()[patchi] =
                pp.patchInternalField()*pp.patchNeighbourField();
        }
    }
    return tw;
}


Foam::tmp<Foam::surfaceVectorField>
Foam::vheElasticity::faceVelocityCorrection
(
    const volVectorField& U,
    scalar deltaT,
    bool bulk
) const
{
    const volScalarField muEff(this->muEff(deltaT));
    // Correction to the linear face velocity of the stretch's gradient:
    // - between solid cells, the compact-minus-wide difference of the
    //   elastic traction over twice the impedance (Rhie-Chow's device for
    //   the (u, sigma) wave system): O(dx^3) on smooth fields, it damps the
    //   odd-even mode of B* that the face stress cannot see;
    // - at an interface (phi_s jumping), the face velocity that makes the
    //   traction continuous, as the face stress of divSigma does.
    const volSymmTensorField sig(sigma());
    const surfaceVectorField nf(mesh_.Sf()/mesh_.magSf());
    surfaceSymmTensorField sigOwn(fvc::interpolate(sig));
    surfaceSymmTensorField sigNei(sigOwn);
    interfaceSideStress(sig, sigOwn, sigNei);

    surfaceVectorField du
    (
        IOobject("du", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    if (bulk)
    {
        const surfaceSymmTensorField sigf
        (
            faceStress(sig, muEff, sigOwn, sigNei)
        );
        const volVectorField divSig(fvc::surfaceIntegrate(mesh_.Sf() & sigf));
        const surfaceScalarField Zf(fvc::interpolate(impedance()));
        du =
            stabilisation_*bulkWeight()
           /(2*Zf + dimensionedScalar("small", Zf.dimensions(), ROOTVSMALL))
           *((fvc::snGrad(sig) & nf) - fvc::interpolate(divSig))
           /mesh_.deltaCoeffs();
    }

    const volScalarField& phis = mixture_.phis();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& lw = mesh_.weights();
    const scalarField& dc = mesh_.deltaCoeffs();
    // The traction-continuous face velocity minus the linear one, from
    // the two sides' velocities, viscosities and stresses
    auto consistentMinusLinear = []
    (
        scalar w, scalar dcf, const vector& n,
        const vector& UP, const vector& UN,
        scalar muP, scalar muN,
        const symmTensor& sP, const symmTensor& sN
    )
    {
        const scalar mP = muP + ROOTVSMALL, mN = muN + ROOTVSMALL;
        const vector uCons =
            (mP*UP + mN*UN + 0.5/dcf*((sN - sP) & n))/(mP + mN);
        return vector(uCons - (w*UP + (1 - w)*UN));
    };
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        const scalar jump = mag(phis[P] - phis[N]);
        if (jump < SMALL) continue;
        du[facei] += jump*consistentMinusLinear
        (
            lw[facei], dc[facei], nf[facei], U[P], U[N], muEff[P], muEff[N],
            sigOwn[facei], sigNei[facei]
        );
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const labelUList& fc = p.faceCells();
        const scalarField& w = p.weights();
        const scalarField& pdc = p.deltaCoeffs();
        const vectorField n(p.nf());
        const scalarField phisN
        (
            phis.boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField mN
        (
            muEff.boundaryField()[patchi].patchNeighbourField()
        );
        const vectorField UN(U.boundaryField()[patchi].patchNeighbourField());
        const symmTensorField& sO = sigOwn.boundaryField()[patchi];
        const symmTensorField& sN = sigNei.boundaryField()[patchi];
        vectorField& dub = du.boundaryFieldRef()[patchi];
        forAll(fc, i)
        {
            const label P = fc[i];
            const scalar jump = mag(phis[P] - phisN[i]);
            if (jump < SMALL) continue;
            dub[i] += jump*consistentMinusLinear
            (
                w[i], pdc[i], n[i], U[P], UN[i], muEff[P], mN[i], sO[i], sN[i]
            );
        }
    }
    return tmp<surfaceVectorField>(new surfaceVectorField(du));
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::impedance() const
{
    return sqrt
    (
        max(mixture_.rho(), dimensionedScalar(dimDensity, Zero))
       *mixture_.Ghat()*mixture_.phis()
    );
}


Foam::tmp<Foam::surfaceScalarField> Foam::vheElasticity::faceViscosity
(
    const volScalarField& muEff
) const
{
    const dimensionedScalar small("small", muEff.dimensions(), ROOTVSMALL);
    return 1/fvc::interpolate(1/(muEff + small));
}


void Foam::vheElasticity::interfaceSideStress
(
    const volSymmTensorField& sig,
    surfaceSymmTensorField& sigOwn,
    surfaceSymmTensorField& sigNei
) const
{
    // At a face where phi_s jumps, the stress of the solid side is its
    // value at the face, not at its cell centre: taking the cell-centre
    // stress is an O(dx) traction error at the interface (removing it
    // cut the oscillating Couette error 1.4-1.7x).  The solid side is
    // extrapolated to the face with the least-squares gradient of the
    // stress over its solid neighbours (phi_s >= 0.5), exact for linear
    // stress, blended by the jump of phi_s; a cell with too few solid
    // neighbours to fix a gradient keeps its cell-centre value.  On a
    // coupled patch (processor, cyclic) "own" is this side, "nei" the
    // other, whose gradient comes across with the patch.
    const volScalarField& phis = mixture_.phis();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Cf = mesh_.Cf().primitiveField();
    const label nCells = mesh_.nCells();
    const scalar solid = 0.5;

    // Normal matrix M = sum w d d^T and right sides r_i = sum w d_i dsigma
    symmTensorField M(nCells, Zero);
    symmTensorField rx(nCells, Zero), ry(nCells, Zero), rz(nCells, Zero);
    auto add = [&](label P, const vector& d, const symmTensor& ds)
    {
        const scalar w = 1/magSqr(d);
        M[P] += w*sqr(d);
        rx[P] += (w*d.x())*ds;
        ry[P] += (w*d.y())*ds;
        rz[P] += (w*d.z())*ds;
    };
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        if (phis[P] < solid || phis[N] < solid) continue;
        const vector d(C[N] - C[P]);
        add(P, d, sig[N] - sig[P]);
        add(N, -d, sig[P] - sig[N]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const labelUList& fc = p.faceCells();
        const vectorField d(p.delta());
        const scalarField phisN
        (
            phis.boundaryField()[patchi].patchNeighbourField()
        );
        const symmTensorField sigN
        (
            sig.boundaryField()[patchi].patchNeighbourField()
        );
        forAll(fc, i)
        {
            const label P = fc[i];
            if (phis[P] < solid || phisN[i] < solid) continue;
            add(P, d[i], sigN[i] - sig[P]);
        }
    }

    // The least-squares gradient of sig along x, y and z per cell (zero
    // where M is singular), with coupled patches for the other side's
    const Vector<label> solD(mesh_.solutionD());
    PtrList<volSymmTensorField> g(3);
    forAll(g, d)
    {
        g.set
        (
            d,
            new volSymmTensorField
            (
                IOobject
                (
                    "sigmaGrad" + Foam::name(d), mesh_.time().timeName(), mesh_
                ),
                mesh_,
                dimensionedSymmTensor(dimPressure/dimLength, Zero),
                patchTypes(mesh_)
            )
        );
    }
    forAll(M, P)
    {
        symmTensor m(M[P]);
        const scalar scale = tr(m)/3;
        if (scale <= 0) continue;
        // empty directions: no neighbours, no extrapolation
        if (solD.x() < 0) { m.xx() = scale; m.xy() = m.xz() = 0; }
        if (solD.y() < 0) { m.yy() = scale; m.xy() = m.yz() = 0; }
        if (solD.z() < 0) { m.zz() = scale; m.xz() = m.yz() = 0; }
        if (det(m) < 1e-6*pow3(scale)) continue;
        const symmTensor iM(inv(m));
        g[0][P] = iM.xx()*rx[P] + iM.xy()*ry[P] + iM.xz()*rz[P];
        g[1][P] = iM.xy()*rx[P] + iM.yy()*ry[P] + iM.yz()*rz[P];
        g[2][P] = iM.xz()*rx[P] + iM.yz()*ry[P] + iM.zz()*rz[P];
    }
    forAll(g, d)
    {
        g[d].correctBoundaryConditions();
    }
    // The change of sig over dx with the gradients g0, g1, g2 along x, y, z
    auto along = []
    (
        const symmTensor& g0,
        const symmTensor& g1,
        const symmTensor& g2,
        const vector& dx
    )
    {
        return symmTensor(dx.x()*g0 + dx.y()*g1 + dx.z()*g2);
    };

    sigOwn.primitiveFieldRef() = symmTensorField(sig.primitiveField(), own);
    sigNei.primitiveFieldRef() = symmTensorField(sig.primitiveField(), nei);
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        const scalar jump = phis[P] - phis[N];
        if (mag(jump) < SMALL) continue;
        // the solid side: the owner if its phi_s is higher
        const label S = jump > 0 ? P : N;
        if (phis[S] < solid) continue;
        symmTensor& s = (S == P) ? sigOwn[facei] : sigNei[facei];
        s += mag(jump)*along(g[0][S], g[1][S], g[2][S], Cf[facei] - C[S]);
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const labelUList& fc = p.faceCells();
        const vectorField dP(p.Cf() - p.Cn());
        const vectorField dN(dP - p.delta());
        const scalarField phisN
        (
            phis.boundaryField()[patchi].patchNeighbourField()
        );
        symmTensorField& sO = sigOwn.boundaryFieldRef()[patchi];
        symmTensorField& sN = sigNei.boundaryFieldRef()[patchi];
        sO = sig.boundaryField()[patchi].patchInternalField();
        sN = sig.boundaryField()[patchi].patchNeighbourField();
        // the other side's gradients
        PtrList<symmTensorField> gN(3);
        forAll(gN, d)
        {
            gN.set(d, g[d].boundaryField()[patchi].patchNeighbourField());
        }
        forAll(fc, i)
        {
            const label P = fc[i];
            const scalar jump = phis[P] - phisN[i];
            if (mag(jump) < SMALL) continue;
            if (jump > 0 && phis[P] >= solid)
            {
                sO[i] += mag(jump)*along(g[0][P], g[1][P], g[2][P], dP[i]);
            }
            else if (jump < 0 && phisN[i] >= solid)
            {
                sN[i] += mag(jump)*along(gN[0][i], gN[1][i], gN[2][i], dN[i]);
            }
        }
    }
}


Foam::tmp<Foam::surfaceSymmTensorField> Foam::vheElasticity::faceStress
(
    const volSymmTensorField& sig,
    const volScalarField& muEff
) const
{
    if (stabilisation_ <= 0)
    {
        return fvc::interpolate(sig);
    }
    surfaceSymmTensorField sigOwn(fvc::interpolate(sig));
    surfaceSymmTensorField sigNei(sigOwn);
    interfaceSideStress(sig, sigOwn, sigNei);
    return faceStress(sig, muEff, sigOwn, sigNei);
}


Foam::tmp<Foam::surfaceSymmTensorField> Foam::vheElasticity::faceStress
(
    const volSymmTensorField& sig,
    const volScalarField& muEff,
    const surfaceSymmTensorField& sigOwn,
    const surfaceSymmTensorField& sigNei
) const
{
    // Each side's stress weighted by the other side's viscosity: the
    // traction that is continuous across a face between a solid and a
    // fluid cell (the linear interpolation where the viscosities are
    // equal), with the solid side's stress taken at the face
    const volScalarField m
    (
        muEff + dimensionedScalar("small", muEff.dimensions(), ROOTVSMALL)
    );
    tmp<surfaceSymmTensorField> tsf
    (
        fvc::interpolate(sig/m)/fvc::interpolate(1/m)
    );
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& lw = mesh_.weights();
    // each side's stress weighted by (its interpolation weight)/(its
    // viscosity)
    auto weighted = []
    (
        scalar w, scalar mP, scalar mN,
        const symmTensor& sP, const symmTensor& sN
    )
    {
        const scalar wP = w/mP, wN = (1 - w)/mN;
        return symmTensor((wP*sP + wN*sN)/(wP + wN));
    };
    symmTensorField& sf = tsf.ref().primitiveFieldRef();
    forAll(own, facei)
    {
        sf[facei] = weighted
        (
            lw[facei], m[own[facei]], m[nei[facei]],
            sigOwn[facei], sigNei[facei]
        );
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled()) continue;
        const scalarField& w = p.weights();
        const scalarField mP(m.boundaryField()[patchi].patchInternalField());
        const scalarField mN(m.boundaryField()[patchi].patchNeighbourField());
        const symmTensorField& sO = sigOwn.boundaryField()[patchi];
        const symmTensorField& sN = sigNei.boundaryField()[patchi];
        symmTensorField& sb = tsf.ref().boundaryFieldRef()[patchi];
        forAll(sb, i)
        {
            sb[i] = weighted(w[i], mP[i], mN[i], sO[i], sN[i]);
        }
    }
    return tsf;
}


Foam::tmp<Foam::fvVectorMatrix> Foam::vheElasticity::stabilisation
(
    const volVectorField& U,
    const volVectorField& Uexplicit,
    const volTensorField& gradU,
    scalar deltaT
) const
{
    // The wide part with the interface-consistent face velocities only
    const volTensorField gradUc
    (
        gradU
      + fvc::surfaceIntegrate
        (
            mesh_.Sf()*faceVelocityCorrection(Uexplicit, deltaT, false)
        )
    );
    // Compact minus wide Laplacian of U with the viscosity
    // stabilisation x impedance x cell size, between solid cells only:
    // O(dx^3) on smooth fields, it damps the odd-even mode of U that the
    // wide elastic operator (grad U, then the linear face stress) cannot see
    const surfaceScalarField muSf
    (
        "muStabilisation",
        stabilisation_*bulkWeight()*fvc::interpolate(impedance())
       /mesh_.deltaCoeffs()
    );
    return
        fvm::laplacian(muSf, U, "laplacian(muStabilisation,U)")
      - fvc::div(muSf*(mesh_.Sf() & fvc::interpolate(gradUc)));
}


void Foam::vheElasticity::clip()
{
    vhe_clip_fluid
    (
        mesh_.nCells(), mixture_.phis().primitiveField().cdata(),
        mixture_.solidFractionMin(), flat(Bstar_.primitiveFieldRef())
    );
    Bstar_.correctBoundaryConditions();
}


Foam::tmp<Foam::volSymmTensorField> Foam::vheElasticity::sigma() const
{
    return stressOf(Bstar_.primitiveField());
}


Foam::tmp<Foam::volSymmTensorField> Foam::vheElasticity::stressOf
(
    const symmTensorField& Bs
) const
{
    tmp<volSymmTensorField> tsigma
    (
        new volSymmTensorField
        (
            IOobject("sigmaElastic", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedSymmTensor(dimPressure, Zero),
            patchTypes(mesh_)
        )
    );
    volSymmTensorField& s = tsigma.ref();
    const scalar phisMin = mixture_.solidFractionMin();

    vhe_elastic_stress
    (
        mesh_.nCells(), mixture_.Ghat().primitiveField().cdata(),
        mixture_.phis().primitiveField().cdata(),
        flat(Bs), phisMin, flat(s.primitiveFieldRef())
    );
    s.correctBoundaryConditions();
    return tsigma;
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muElastic
(
    scalar deltaT
) const
{
    return tmp<volScalarField>
    (
        new volScalarField
        (
            "muElastic",
            dimensionedScalar("deltaT", dimTime, stressStep(deltaT))
           *mixture_.Ghat()*mixture_.phis()
        )
    );
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::gasFaceTranspose
(
    const volTensorField& gradU,
    scalar deltaT
) const
{
    tmp<volVectorField> tsource
    (
        new volVectorField
        (
            IOobject("gasFaceTranspose", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedVector(dimForce/dimVolume, Zero)
        )
    );
    vectorField& source = tsource.ref().primitiveFieldRef();
    const scalar tau = stressStep(deltaT);

    const scalarField& rho = mixture_.rho().primitiveField();
    const scalarField& phis = mixture_.phis().primitiveField();
    const scalarField& Ghat = mixture_.Ghat().primitiveField();
    const tensorField& L = gradU.primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& w = mesh_.weights().primitiveField();

    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        const scalar muP = tau*Ghat[P]*phis[P];
        const scalar muN = tau*Ghat[N]*phis[N];
        if (muP <= 0 && muN <= 0) continue;
        const scalar share = 1 - min(rho[P], rho[N])/max(rho[P], rho[N]);
        if (share <= 0) continue;

        // Linear interpolation of muElastic dev2(grad U^T), as fvc::div
        const tensor tP(muP*dev2(L[P].T()));
        const tensor tN(muN*dev2(L[N].T()));
        const vector flux
        (
            share*(Sf[facei] & (w[facei]*tP + (1 - w[facei])*tN))
        );
        source[P] += flux;
        source[N] -= flux;
    }

    // Processor and cyclic faces: the cell across from the neighbour side
    forAll(mesh_.boundary(), patchi)
    {
        if (!mesh_.boundary()[patchi].coupled()) continue;
        const labelUList& cells = mesh_.boundary()[patchi].faceCells();
        const scalarField rhoN
        (
            mixture_.rho().boundaryField()[patchi].patchNeighbourField()
        );
        const scalarField muNs
        (
            deltaT
           *mixture_.Ghat().boundaryField()[patchi].patchNeighbourField()
           *mixture_.phis().boundaryField()[patchi].patchNeighbourField()
        );
        const tensorField LN
        (
            gradU.boundaryField()[patchi].patchNeighbourField()
        );
        const vectorField& Sfp = mesh_.Sf().boundaryField()[patchi];
        const scalarField& wp = mesh_.weights().boundaryField()[patchi];
        forAll(cells, i)
        {
            const label P = cells[i];
            const scalar muP = tau*Ghat[P]*phis[P];
            if (muP <= 0 && muNs[i] <= 0) continue;
            const scalar share =
                1 - min(rho[P], rhoN[i])/max(rho[P], rhoN[i]);
            if (share <= 0) continue;
            const tensor tP(muP*dev2(L[P].T()));
            const tensor tN(muNs[i]*dev2(LN[i].T()));
            source[P] += share*(Sfp[i] & (wp[i]*tP + (1 - wp[i])*tN));
        }
    }

    source /= mesh_.V();
    return tsource;
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muEff
(
    scalar deltaT
) const
{
    if (semiImplicit_)
    {
        return mixture_.mu() + muElastic(deltaT);
    }
    return tmp<volScalarField>(new volScalarField("muEff", mixture_.mu()));
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::divSigma
(
    const volVectorField& U,
    const volScalarField& muEff,
    scalar deltaT
) const
{
    tmp<volSymmTensorField> sig;
    if (backward_)
    {
        // The stress of the new step's B*, B*^(n+1) = Bhat + tau (L B* +
        // B* L^T): the part linear about phi_s^(1/2) I is the implicit
        // viscosity muElastic, the rest, tau (L A + A L^T) with A = Bhat -
        // phi_s^(1/2) I, is taken with the current velocity gradient (an
        // O(dt^2) error per step, where linearising about I would leave
        // O(dt) at finite strain)
        symmTensorField Bs(predictorBstar());
        const tensorField gradU
        (
            dev(velocityGradient(U, deltaT)().primitiveField())
        );
        const tensorField L(gradU.T());
        const scalarField& phis = mixture_.phis().primitiveField();
        const scalar tau = stressStep(deltaT);
        forAll(Bs, celli)
        {
            if (phis[celli] <= mixture_.solidFractionMin()) continue;
            const symmTensor A(Bs[celli] - sqrt(phis[celli])*I);
            Bs[celli] += tau*twoSymm(L[celli] & A);
        }
        sig = stressOf(Bs);
    }
    else
    {
        sig = sigma();
    }
    if (stabilisation_ <= 0)
    {
        return fvc::div(sig, "div(sigma)");
    }
    return fvc::surfaceIntegrate(mesh_.Sf() & faceStress(sig(), muEff));
}


Foam::tmp<Foam::scalarField> Foam::vheElasticity::sumMagSfByV() const
{
    return fvc::surfaceSum(mesh_.magSf())().primitiveField()/mesh_.V();
}


Foam::scalar Foam::vheElasticity::courantNo(scalar deltaT) const
{
    double co = 0;
    vhe_elastic_dt
    (
        mesh_.nCells(), mixture_.Ghat().primitiveField().cdata(),
        mixture_.phis().primitiveField().cdata(),
        mixture_.rho().primitiveField().cdata(), sumMagSfByV()().cdata(),
        1, deltaT, &co
    );
    return returnReduce(scalar(co), maxOp<scalar>());
}


Foam::scalar Foam::vheElasticity::maxDeltaT(scalar maxCo) const
{
    const double dt = vhe_elastic_dt
    (
        mesh_.nCells(), mixture_.Ghat().primitiveField().cdata(),
        mixture_.phis().primitiveField().cdata(),
        mixture_.rho().primitiveField().cdata(), sumMagSfByV()().cdata(),
        maxCo, 1, nullptr
    );
    return returnReduce(scalar(dt < VGREAT ? dt : VGREAT), minOp<scalar>());
}


// ************************************************************************* //
