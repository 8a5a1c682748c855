/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the compact-minus-wide stabilisation and the stretch's velocity gradient
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "vhe.h"
#include "vheFlat.H"

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


// ************************************************************************* //
