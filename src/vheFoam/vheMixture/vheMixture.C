/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- construction, the
  mixture's properties and the log (reading the phases: vheMixtureRead.C)
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "syncTools.H"
#include "fvc.H"
#include "IOmanip.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::vheMixture::vheMixture
(
    const volVectorField& U,
    const surfaceScalarField& phi
)
:
    IOdictionary
    (
        IOobject
        (
            "vheProperties",
            U.time().constant(),
            U.db(),
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    mesh_(U.mesh()),
    U_(U),
    phi_(phi),
    phases_(),
    nSolids_(0),
    nRigid_(0),
    alphas_(),
    fixedAlphas_(),
    fixedDRho_(),
    fixedStep_(-1),
    rho_
    (
        IOobject("rho", mesh_.time().timeName(), mesh_,
                 IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedScalar(dimDensity, Zero)
    ),
    mu_
    (
        IOobject("mu", mesh_.time().timeName(), mesh_,
                 IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedScalar(dimDynamicViscosity, Zero)
    ),
    rhoPhi_
    (
        IOobject("rhoPhi", mesh_.time().timeName(), mesh_,
                 IOobject::NO_READ, IOobject::NO_WRITE),
        mesh_,
        dimensionedScalar(dimMass/dimTime, Zero)
    ),
    bodyForce_
    (
        dimensionedVector::getOrDefault
        (
            "bodyForce", *this, dimAcceleration, Zero
        )
    ),
    solidFractionMin_(getOrDefault<scalar>("solidFractionMin", 1e-6)),
    deltaN_
    (
        "deltaN",
        1e-8/pow(average(mesh_.V()), 1.0/3.0)
    )
{
    if (!found("fluids") || !isDict("fluids") || subDict("fluids").empty())
    {
        FatalIOErrorInFunction(*this)
            << "No 'fluids' sub-dictionary with at least one fluid phase"
            << exit(FatalIOError);
    }
    if (found("solids") && !isDict("solids"))
    {
        FatalIOErrorInFunction(*this)
            << "'solids' must be a sub-dictionary of solid materials"
            << exit(FatalIOError);
    }
    // Unknown top-level entries are only warned about: cases commonly
    // #include a parameter file here.  Phase entries are checked strictly.
    {
        const wordList known
        ({"fluids", "solids", "bodyForce", "solidFractionMin", "contact",
          "sigmas"});
        for (const entry& e : *this)
        {
            if (!known.found(e.keyword()) && e.keyword() != "FoamFile"
             && e.isDict())
            {
                WarningInFunction
                    << "Ignoring sub-dictionary '" << e.keyword() << "' in "
                    << objectPath() << "; valid entries: " << known << endl;
            }
        }
    }
    if (solidFractionMin_ <= 0 || solidFractionMin_ >= 0.5)
    {
        FatalIOErrorInFunction(*this)
            << "solidFractionMin must lie in (0, 0.5), got "
            << solidFractionMin_ << exit(FatalIOError);
    }

    readPhases(subDict("fluids"), false);
    if (found("solids"))
    {
        readPhases(subDict("solids"), true);
    }

    const label n = phases_.size();
    rhoK_.setSize(n); muK_.setSize(n); GK_.setSize(n); isSolid_.setSize(n);
    isRigid_.setSize(n);
    forAll(phases_, i)
    {
        rhoK_[i] = phases_[i].rho;
        muK_[i] = phases_[i].mu;
        GK_[i] = phases_[i].G;
        // The elastic solids: phi_s, Ghat, B* (a rigid material is a
        // fluid to them)
        isSolid_[i] = phases_[i].solid && !phases_[i].rigid;
        nSolids_ += isSolid_[i];
        isRigid_[i] = phases_[i].rigid;
        nRigid_ += phases_[i].rigid;
    }

    Info<< "Phases:";
    for (const phase& p : phases_)
    {
        Info<< ' ' << p.name
            << (p.fixed ? " (fixed rigid solid"
              : p.prescribed ? " (prescribed rigid solid"
              : p.rigid ? " (rigid solid" : p.solid ? " (solid" : " (fluid")
            << ", rho " << p.rho;
        if (!p.rigid) Info<< ", mu " << p.mu;
        if (p.solid && !p.rigid) Info<< ", G " << p.G;
        Info<< ')';
    }
    Info<< nl;
    if (mag(bodyForce_.value()) > 0)
    {
        Info<< "Body force per unit mass " << bodyForce_.value() << nl;
    }
    Info<< endl;

    readAlphas();
    checkAlphas();
    fixedAlphas_.setSize(alphas_.size());
    forAll(phases_, i)
    {
        if (phases_[i].fixed && alphas_.size() > 1)
        {
            fixedAlphas_.set
            (
                i,
                new volScalarField
                (
                    IOobject
                    (
                        alphas_[i].name() + ".fixed",
                        mesh_.time().timeName(), mesh_,
                        IOobject::NO_READ, IOobject::NO_WRITE
                    ),
                    alphas_[i]
                )
            );
        }
    }
    if (alphas_.size() > 1)
    {
        checkSchemes();
        geometricSolids();
    }

    if (nSolids_)
    {
        phis_.reset
        (
            new volScalarField
            (
                IOobject("phis", mesh_.time().timeName(), mesh_,
                         IOobject::NO_READ, IOobject::AUTO_WRITE),
                mesh_,
                dimensionedScalar(dimless, Zero)
            )
        );
        alphaPhiSolid_.reset
        (
            new surfaceScalarField
            (
                IOobject("alphaPhiSolid", mesh_.time().timeName(), mesh_,
                         IOobject::NO_READ, IOobject::NO_WRITE),
                mesh_,
                dimensionedScalar(dimVolume/dimTime, Zero)
            )
        );
        Ghat_.reset
        (
            new volScalarField
            (
                IOobject("Ghat", mesh_.time().timeName(), mesh_,
                         IOobject::NO_READ, IOobject::NO_WRITE),
                mesh_,
                dimensionedScalar(dimPressure, Zero)
            )
        );
    }

    correct();
    rho_.oldTime();
    if (nSolids_) phis_->oldTime();

    // Initial mass flux consistent with the fractions
    rhoPhi_ = fvc::interpolate(rho_)*phi_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::vheMixture::correct()
{
    const label n = phases_.size();
    List<const scalar*> a(n);

    // The same kernel serves the cells and every patch
    const auto kernel = [&](label size, scalar* rho, scalar* mu,
                            scalar* phis, scalar* Ghat)
    {
        if (alphas_.empty())
        {
            // Single phase: alpha = 1 everywhere
            for (label c = 0; c < size; ++c)
            {
                rho[c] = rhoK_[0];
                mu[c] = muK_[0];
            }
            return;
        }
        vhe_mixture
        (
            size, n, a.cdata(), rhoK_.cdata(), muK_.cdata(), GK_.cdata(),
            isSolid_.cdata(), isRigid_.cdata(), solidFractionMin_, rho, mu,
            phis, Ghat
        );
    };

    forAll(alphas_, i) a[i] = alphas_[i].primitiveField().cdata();
    kernel
    (
        mesh_.nCells(),
        rho_.primitiveFieldRef().data(),
        mu_.primitiveFieldRef().data(),
        nSolids_ ? phis_->primitiveFieldRef().data() : nullptr,
        nSolids_ ? Ghat_->primitiveFieldRef().data() : nullptr
    );

    forAll(mesh_.boundary(), patchi)
    {
        forAll(alphas_, i)
        {
            a[i] = alphas_[i].boundaryField()[patchi].cdata();
        }
        kernel
        (
            rho_.boundaryField()[patchi].size(),
            rho_.boundaryFieldRef()[patchi].data(),
            mu_.boundaryFieldRef()[patchi].data(),
            nSolids_ ? phis_->boundaryFieldRef()[patchi].data() : nullptr,
            nSolids_ ? Ghat_->boundaryFieldRef()[patchi].data() : nullptr
        );
    }
    if (nRigid_)
    {
        rigidViscosity();
    }
}


void Foam::vheMixture::rigidViscosity()
{
    // The cells the fluids leave (the C core's -1: inside a rigid body)
    // take the smallest viscosity of their face neighbours, layer by layer
    // from the body's surface inwards, so that a face between a body and
    // a fluid has at most that fluid's viscosity on the body's side; what
    // no layer reaches (deep inside a large body, where its rigid motion
    // makes the viscosity idle) takes the smallest of all.  Across
    // processor and cyclic faces as across internal ones.  *Why the
    // smallest:* with the neighbours' mean, a fixed box whose top the
    // water of a dam break ran over put the water's viscosity on the
    // faces of the air cells at its corner (10 Pa s beside air of 1e-4),
    // and their explicit transpose stress blew the air up (test_rigid's
    // fixedDam at t = 0.54).
    scalarField& mu = mu_.primitiveFieldRef();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInt = mesh_.nInternalFaces();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (label layer = 0; layer < 4; ++layer)
    {
        if (!returnReduce(min(mu) < 0, orOp<bool>())) break;
        scalarField least(mu.size(), GREAT);
        const auto take = [&](const label c, const scalar m)
        {
            if (mu[c] < 0 && m >= 0) least[c] = min(least[c], m);
        };
        forAll(own, f)
        {
            take(own[f], mu[nei[f]]);
            take(nei[f], mu[own[f]]);
        }
        scalarField other;
        syncTools::swapBoundaryCellList(mesh_, mu, other);
        for (const polyPatch& pp : pbm)
        {
            if (!pp.coupled()) continue;
            forAll(pp, i)
            {
                take(pp.faceCells()[i], other[pp.start() - nInt + i]);
            }
        }
        forAll(mu, c)
        {
            if (least[c] < GREAT) mu[c] = least[c];
        }
    }
    if (returnReduce(min(mu) < 0, orOp<bool>()))
    {
        scalar smallest = GREAT;
        forAll(mu, c)
        {
            if (mu[c] >= 0) smallest = min(smallest, mu[c]);
        }
        reduce(smallest, minOp<scalar>());
        if (smallest == GREAT)
        {
            // no cell has one (a mesh the bodies fill): the fluids'
            forAll(muK_, k)
            {
                if (!isRigid_[k]) smallest = min(smallest, muK_[k]);
            }
        }
        forAll(mu, c)
        {
            if (mu[c] < 0) mu[c] = smallest;
        }
    }
    // The patches: a coupled patch the other side's cells, the others the
    // cell beside them where the C core left -1
    mu_.correctBoundaryConditions();
    forAll(mu_.boundaryField(), patchi)
    {
        fvPatchScalarField& mp = mu_.boundaryFieldRef()[patchi];
        if (mp.coupled()) continue;
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        forAll(mp, i)
        {
            if (mp[i] < 0) mp[i] = mu[fc[i]];
        }
    }
}



Foam::tmp<Foam::volScalarField> Foam::vheMixture::nearInterface() const
{
    tmp<volScalarField> tnear
    (
        new volScalarField
        (
            IOobject("nearInterface", mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedScalar(dimless, Zero)
        )
    );
    // 1 where some fraction is in [0.01, 0.99] (one pass per phase: the
    // field expression made five temporaries of every phase, a run's
    // spare colours included)
    const auto mark = [](scalarField& near, const scalarField& a)
    {
        forAll(near, i)
        {
            if (a[i] >= 0.01 && a[i] <= 0.99) near[i] = 1;
        }
    };
    volScalarField& near = tnear.ref();
    for (const volScalarField& a : alphas_)
    {
        mark(near.primitiveFieldRef(), a.primitiveField());
        forAll(near.boundaryField(), patchi)
        {
            mark(near.boundaryFieldRef()[patchi], a.boundaryField()[patchi]);
        }
    }
    return tnear;
}


Foam::tmp<Foam::volScalarField> Foam::vheMixture::interfaceIndicator() const
{
    tmp<volScalarField> tind
    (
        new volScalarField
        (
            IOobject
            (
                "interfaceIndicator", mesh_.time().timeName(), mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_,
            dimensionedScalar(dimless, Zero)
        )
    );
    for (const volScalarField& a : alphas_)
    {
        tind.ref() = max(tind(), 4*a*(1 - a));
    }
    return tind;
}


void Foam::vheMixture::report() const
{
    const scalarField& V = mesh_.V();
    forAll(alphas_, i)
    {
        // volume, min and max in one pass
        const scalarField& a = alphas_[i].primitiveField();
        scalar vol = 0, lo = VGREAT, hi = -VGREAT;
        forAll(a, c)
        {
            vol += V[c]*a[c];
            lo = min(lo, a[c]);
            hi = max(hi, a[c]);
        }
        reduce(vol, sumOp<scalar>());
        reduce(lo, minOp<scalar>());
        reduce(hi, maxOp<scalar>());
        // Volumes to 15 digits: conservation is checked to 1e-6 and below
        Info<< "Phase " << phases_[i].name
            << " volume " << setprecision(15) << vol
            << setprecision(IOstream::defaultPrecision())
            << "  fraction min, max = " << lo << ' ' << hi << nl;
    }
}


// ************************************************************************* //
