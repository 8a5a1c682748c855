/*---------------------------------------------------------------------------*\
  vheFoam: the momentum and continuity equations of a step solved together;
  the solver loaded from its library on the first coupled solve
\*---------------------------------------------------------------------------*/

#include "coupledStep.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(coupledSolver, 0);
    defineRunTimeSelectionTable(coupledSolver, mesh);
}

namespace
{
    // The library and the solver's type in its table
    const Foam::word libName("libvheCoupled.so");
    const Foam::word solverType("PETSc");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledStep::coupledStep
(
    const fvMesh& mesh,
    const dictionary& pimpleDict
)
:
    mesh_(mesh),
    options_(),
    always_(false),
    solver_()
{
    const dictionary* d = pimpleDict.findDict("coupling");
    if (d)
    {
        options_ = d->getOrDefault<string>("petsc", options_);
        const word when(d->getOrDefault<word>("solve", "stiff"));
        if (when != "stiff" && when != "always")
        {
            FatalIOErrorInFunction(*d)
                << "coupling solve: stiff or always, got " << when
                << exit(FatalIOError);
        }
        always_ = when == "always";
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::coupledSolver& Foam::coupledStep::solver()
{
    if (!solver_.valid())
    {
        // PETSc and the solvers it links are mapped in only here, in the
        // runs that solve coupled
        Time& runTime = const_cast<Time&>(mesh_.time());
        if (!runTime.libs().open(fileName(libName), false))
        {
            FatalErrorInFunction
                << "cannot load " << libName << " (the coupled step's "
                << "PETSc solver): build it with ./Allwmake"
                << exit(FatalError);
        }
        const auto* table = coupledSolver::meshConstructorTablePtr_;
        if (!table || !table->found(solverType))
        {
            FatalErrorInFunction
                << libName << " has no coupled solver " << solverType
                << exit(FatalError);
        }
        solver_ = (*table)[solverType](mesh_, options_);
    }
    return *solver_;
}


// ************************************************************************* //
