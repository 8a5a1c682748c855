/*---------------------------------------------------------------------------*\
  isoTransport: a solid's fraction alpha.rubber carried by OpenFOAM's
  isoAdvector (Roenby, Bredmose & Jasak 2016; v1912's isoAdvection, as
  interIsoFoam) in vheFoam's prescribed flows (PIMPLE prescribedVelocity,
  prescribedFlow).  The reference of geometric transport against
  vheFoam's MULES in benchmarks/transport (issue 25): only the fraction is
  carried, no B, no momentum.  Logs the volume, its bounds and time.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "isoAdvection.H"
#include "prescribedFlow.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Carry alpha.rubber with isoAdvector in a prescribed flow"
        " (benchmarks/transport)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    volScalarField alpha
    (
        IOobject
        (
            "alpha.rubber", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::AUTO_WRITE
        ),
        mesh
    );
    volVectorField U
    (
        IOobject
        (
            "U", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::AUTO_WRITE
        ),
        mesh
    );
    surfaceScalarField phi
    (
        IOobject
        (
            "phi", runTime.timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE
        ),
        fvc::flux(U)
    );
    const prescribedFlow flow(mesh, mesh.solutionDict().subDict("PIMPLE"));
    if (!flow.active())
    {
        FatalIOErrorInFunction(mesh.solutionDict())
            << "PIMPLE has no prescribedVelocity" << exit(FatalIOError);
    }
    flow.set(U, phi, runTime.value());
    isoAdvection advector(alpha, phi, U);
    const scalar V0 = gSum(mesh.V()*alpha.primitiveField());

    while (runTime.run())
    {
        ++runTime;
        flow.set(U, phi, runTime.value() - 0.5*runTime.deltaTValue());
        advector.advect();
        Info<< "Time = " << runTime.timeName()
            << "  volume drift " << gSum(mesh.V()*alpha.primitiveField())/V0 - 1
            << "  alpha min, max = " << gMin(alpha.primitiveField()) << ' '
            << gMax(alpha.primitiveField()) << nl;
        runTime.write();
        Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s" << nl;
    }
    Info<< "End" << endl;
    return 0;
}
