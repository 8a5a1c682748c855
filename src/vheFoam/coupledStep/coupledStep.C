/*---------------------------------------------------------------------------*\
  vheFoam: the momentum and continuity equations of a step solved together;
  the solver loaded from its library on the first coupled solve
\*---------------------------------------------------------------------------*/

#include "coupledStep.H"
#include "Time.H"
#include "fvMesh.H"

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
    rigid_(true),
    solver_()
{
    const dictionary* d = pimpleDict.findDict("coupling");
    if (d)
    {
        options_ = d->getOrDefault<string>("petsc", options_);
        const word when(d->getOrDefault<word>("solve", "bodies"));
        if (when != "bodies" && when != "stiff" && when != "always")
        {
            FatalIOErrorInFunction(*d)
                << "coupling solve: bodies, stiff or always, got " << when
                << exit(FatalIOError);
        }
        always_ = when == "always";
        rigid_ = when != "stiff";
    }
    if (options_.empty())
    {
        options_ = coupledSolver::defaultOptions(mesh_);
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

bool Foam::coupledSolver::direct(const string& options)
{
    return
        options.find("-ksp_type preonly") != string::npos
     && options.find("-pc_type lu") != string::npos;
}


Foam::string Foam::coupledSolver::defaultOptions(const fvMesh& mesh)
{
    // The coupled fixed point needs the continuity rows solved to
    // round-off.  In 2D a direct LU (MUMPS, any number of ranks): its fill
    // grows as N log N.  In 3D it grows as N^(4/3) and its work as N^2:
    // scene B's four spheres (16,800 cells) took 18.7 s a step, so there
    // FGMRES with a Schur-complement field split (the velocity components
    // of a cell field 0, its p_rgh field 1, hypre's BoomerAMG on both, the
    // Schur complement from the velocity block's diagonal) to a relative
    // tolerance of 1e-12: 0.95 s a step (the projection 0.065).  Its
    // tolerance is relative to the whole right-hand side; at 1e-8 the
    // Couette stiff disk turned at 0.984 of the flow's rate with D 0.015
    // and 33 passes a step, at 1e-12 as with the LU (0.9638, 12.6 passes;
    // the LU 0.9638, 11.7).  The LU's ordering approximate minimum fill
    // (MUMPS ICNTL(7) 2): its analysis is redone whenever the pattern
    // changes (a rigid body's rows, a stiff body's transpose part, as the
    // bodies move: every other step in scene A), and it takes 9 ms where
    // METIS takes 55 (38 rigid disks, 4,096 cells: 6.4 s against 7.6 s to
    // t = 0.5; 13 stiff disks to t = 1: 8.1 s against 10.1 s)
    if (mesh.nSolutionD() < 3)
    {
        return
            "-ksp_type preonly -pc_type lu"
            " -pc_factor_mat_solver_type mumps -mat_mumps_icntl_7 2";
    }
    return
        "-ksp_type fgmres -ksp_rtol 1e-12 -ksp_max_it 1000"
        " -pc_type fieldsplit -pc_fieldsplit_block_size 4"
        " -pc_fieldsplit_0_fields 0,1,2 -pc_fieldsplit_1_fields 3"
        " -pc_fieldsplit_type schur"
        " -pc_fieldsplit_schur_fact_type full"
        " -pc_fieldsplit_schur_precondition selfp"
        " -fieldsplit_0_ksp_type preonly -fieldsplit_0_pc_type hypre"
        " -fieldsplit_1_ksp_type preonly -fieldsplit_1_pc_type hypre";
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
