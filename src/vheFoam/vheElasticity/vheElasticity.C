/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the state B*: construction, transport, stretch, stress
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


// ************************************************************************* //
