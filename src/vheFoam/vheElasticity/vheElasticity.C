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

// OpenFOAM's VectorSpace types are contiguous doubles (checked by the
// layout tests of the C core): view a field as the flat array it is.
namespace
{
template<class T>
inline const double* flat(const Foam::UList<T>& f)
{
    return reinterpret_cast<const double*>(f.cdata());
}
template<class T>
inline double* flat(Foam::UList<T>& f)
{
    return reinterpret_cast<double*>(f.data());
}
}


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
    Info<< "Elastic stress: " << variant << endl;

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


void Foam::vheElasticity::advect(scalar deltaT)
{
    const volScalarField& phis = mixture_.phis();
    const volScalarField& phis0 = phis.oldTime();
    const scalar phisMin = mixture_.solidFractionMin();
    const label nCells = mesh_.nCells();

    // Old B of the solid; I where there is none
    volSymmTensorField B0
    (
        IOobject("B", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedSymmTensor(dimless, Zero),
        patchTypes(mesh_)
    );
    vhe_b_from_bstar
    (
        nCells, phis0.primitiveField().cdata(),
        flat(Bstar_.oldTime().primitiveField()), phisMin,
        flat(B0.primitiveFieldRef())
    );
    B0.correctBoundaryConditions();

    // Solid volume crossing each face over the step [m^3]
    const surfaceScalarField& aPhi = mixture_.alphaPhiSolid();
    const scalarField a(deltaT*aPhi.primitiveField());

    scalarField out(nCells, 0), W(nCells, 0);
    symmTensorField S(nCells, Zero);

    vhe_bdonor_internal
    (
        mesh_.nInternalFaces(), mesh_.owner().cdata(),
        mesh_.neighbour().cdata(), a.cdata(), flat(B0.primitiveField()),
        out.data(), W.data(), flat(S)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchSymmTensorField& Bp = B0.boundaryField()[patchi];
        if (Bp.empty()) continue;
        // Across a coupled patch the donor is the neighbour cell; at any
        // other boundary, the boundary value
        const symmTensorField Bnb
        (
            Bp.coupled() ? Bp.patchNeighbourField()() : symmTensorField(Bp)
        );
        const scalarField ap(deltaT*aPhi.boundaryField()[patchi]);
        vhe_bdonor_boundary
        (
            ap.size(), mesh_.boundary()[patchi].faceCells().cdata(),
            ap.cdata(), flat(Bnb), out.data(), W.data(), flat(S)
        );
    }

    const size_t flushed = vhe_bdonor_finish
    (
        nCells, mesh_.V().cdata(), phis0.primitiveField().cdata(),
        phis.primitiveField().cdata(), flat(B0.primitiveField()),
        out.cdata(), W.cdata(), flat(S), phisMin,
        flat(Bstar_.primitiveFieldRef())
    );
    const label nFlushed = returnReduce(label(flushed), sumOp<label>());
    if (nFlushed)
    {
        Info<< "B advection: " << nFlushed << " solid cells renewed entirely"
            << " in one step (reduce maxAlphaCo if this persists)" << endl;
    }
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
    vhe_stretch
    (
        mesh_.nCells(), deltaT, flat(gradU.primitiveField()),
        flat(Bstar_.primitiveFieldRef())
    );
}


Foam::tmp<Foam::volTensorField> Foam::vheElasticity::velocityGradient
(
    const volVectorField& U,
    scalar deltaT
) const
{
    if (stabilisation_ <= 0)
    {
        return fvc::grad(U);
    }
    return
        fvc::grad(U)
      + fvc::surfaceIntegrate(mesh_.Sf()*faceVelocityCorrection(U, deltaT, true));
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

    surfaceVectorField du
    (
        IOobject("du", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    if (bulk)
    {
        const surfaceSymmTensorField sigf(faceStress(sig, muEff));
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
    forAll(own, facei)
    {
        const label P = own[facei], N = nei[facei];
        const scalar jump = mag(phis[P] - phis[N]);
        if (jump < SMALL) continue;
        const scalar mP = muEff[P] + ROOTVSMALL, mN = muEff[N] + ROOTVSMALL;
        const vector uLin = lw[facei]*U[P] + (1 - lw[facei])*U[N];
        const vector uCons =
        (
            mP*U[P] + mN*U[N] + 0.5/dc[facei]*((sig[N] - sig[P]) & nf[facei])
        )/(mP + mN);
        du[facei] += jump*(uCons - uLin);
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
    // Each side's stress weighted by the other side's viscosity: the
    // traction that is continuous across a face between a solid and a
    // fluid cell (the linear interpolation where the viscosities are equal)
    const volScalarField m
    (
        muEff + dimensionedScalar("small", muEff.dimensions(), ROOTVSMALL)
    );
    return fvc::interpolate(sig/m)/fvc::interpolate(1/m);
}


Foam::tmp<Foam::fvVectorMatrix> Foam::vheElasticity::stabilisation
(
    const volVectorField& U,
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
            mesh_.Sf()*faceVelocityCorrection(U, deltaT, false)
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
        flat(Bstar_.primitiveField()), phisMin, flat(s.primitiveFieldRef())
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
            dimensionedScalar("deltaT", dimTime, deltaT)
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
        const scalar muP = deltaT*Ghat[P]*phis[P];
        const scalar muN = deltaT*Ghat[N]*phis[N];
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
            const scalar muP = deltaT*Ghat[P]*phis[P];
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
    const volScalarField& muEff
) const
{
    if (stabilisation_ <= 0)
    {
        return fvc::div(sigma(), "div(sigma)");
    }
    return fvc::surfaceIntegrate(mesh_.Sf() & faceStress(sigma(), muEff));
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
