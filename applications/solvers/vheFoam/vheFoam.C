/*---------------------------------------------------------------------------*\
Application
    vheFoam

Description
    Incompressible flow of any number of fluid phases carrying any number of
    visco-hyperelastic bodies on one fixed Eulerian mesh (phase-averaged
    full Eulerian model of Sugiyama et al. and the Ushijima group).

    Phases by VOF (MULES, limitSum), B* = phi_s^(1/2) B transported with the
    upper-convected equation, elastic stress Ghat phi_s^(1/2) dev(B*) in the
    momentum equation, and an incremental pressure-correction projection
    of the predicted velocity with the coefficient dt/rho (p_rgh and its
    boundary conditions as interFoam), stable at any viscous number; the
    steps with stiff bodies iterated to their coupled solution, each pass
    momentum and continuity in one PETSc matrix (coupledStep).
    The mesh may be refined and unrefined at run time (dynamicRefineFvMesh,
    constant/dynamicMeshDict) near every interface between phases.
    A case with one fluid and no solid is plain incompressible flow: the
    phase fractions, B* and the elastic term are not built at all.

\*---------------------------------------------------------------------------*/

#include <malloc.h>
#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "vheRefineFvMesh.H"
#include "fluxProjection.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "clockTime.H"
#include "profiling.H"
#include "linear.H"
#include "vheMixture.H"
#include "vheElasticity.H"
#include "wallShearCorrection.H"
#include "prescribedFlow.H"
#include "rigidBodies.H"
#include "bodyColours.H"
#include "bodyContact.H"
#include "surfaceTension.H"
#include "stepCoupling.H"
#include "coupledStep.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Incompressible multiphase flow carrying visco-hyperelastic bodies"
        " (phase-averaged full Eulerian model) on a fixed mesh."
    );

    #include "mallocTuning.H"
    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createVheMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "initContinuityErrs.H"
    #include "createFields.H"
    #include "createRefinement.H"

    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    Info<< "\nStarting time loop\n" << endl;
    clockTime wallClock;
    const scalar startTime = runTime.value();

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "vheCourantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "updateMesh.H"

        if (flow.active())
        {
            flow.set(U, phi, runTime.value() - 0.5*runTime.deltaTValue());
        }

        while (pimple.loop())
        {
            #include "alphaEqn.H"
            #include "BEqn.H"

            if (!flow.active())
            {
                contact.correct();
                #include "startCoupling.H"
                for (label attempt = 0; attempt < 2; ++attempt)
                {
                    do
                    {
                        #include "UEqn.H"

                        if (coupledSolve)
                        {
                            #include "UpEqn.H"
                        }
                        else
                        {
                            while (pimple.correct())
                            {
                                #include "pEqn.H"
                            }
                        }

                        #include "rigidProjection.H"
                    } while (coupling.loop(U, accelerationFlux, acceleration));

                    if (!coupledSolve || coupling.converged()) break;
                    #include "coupledFallback.H"
                }
            }

            #include "BStretch.H"
        }

        if (colours.active()) colours.correct(CoNum);

        runTime.write();

        runTime.printExecutionTime(Info);
        #include "progress.H"
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
