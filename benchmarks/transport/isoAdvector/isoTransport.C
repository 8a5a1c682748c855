/*---------------------------------------------------------------------------*\
  isoTransport: a solid's fraction alpha.rubber carried by OpenFOAM's
  isoAdvector (Roenby, Bredmose & Jasak 2016; v1912's isoAdvection, as
  interIsoFoam) in vheFoam's prescribed flows (PIMPLE prescribedVelocity,
  prescribedFlow).  The reference of geometric transport against
  vheFoam's MULES in benchmarks/transport (issue 25): only the fraction is
  carried, no B, no momentum.  Logs the volume, its bounds and time.
  With syncCyclic (below) the volume crossing a cyclic patch is the same
  on both sides, as v1912 makes it across processor patches.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "isoAdvection.H"
#include "cyclicFvPatch.H"
#include "prescribedFlow.H"

// v1912's isoAdvection exchanges the volume crossing a face over processor
// patches only: on a cyclic patch the outflow side gets the geometric
// volume and the inflow side keeps the upwind one, and the two disagree
// (the disk lost 2 % of its volume crossing the periodic box once at 32
// cells).  Afterwards: each inflow face takes minus its partner's
// outflow volume, and its cell's fraction the difference
void syncCyclic
(
    volScalarField& alpha,
    const surfaceScalarField& phi,
    const isoAdvection& advector
)
{
    const fvMesh& mesh = alpha.mesh();
    // getRhoPhi(1, 0): the volume that crossed each face over the step,
    // per unit time
    const dimensionedScalar one("one", dimDensity, 1.0);
    const dimensionedScalar zero("zero", dimDensity, 0.0);
    const surfaceScalarField dVf
    (
        advector.getRhoPhi(one, zero)*mesh.time().deltaT()/one
    );
    scalarField& a = alpha.primitiveFieldRef();
    forAll(mesh.boundary(), patchi)
    {
        if (!isA<cyclicFvPatch>(mesh.boundary()[patchi])) continue;
        const cyclicFvPatch& cp =
            refCast<const cyclicFvPatch>(mesh.boundary()[patchi]);
        const label nbr = cp.neighbPatchID();
        const scalarField& phiP = phi.boundaryField()[patchi];
        const scalarField& dV = dVf.boundaryField()[patchi];
        const scalarField& dVn = dVf.boundaryField()[nbr];
        const labelUList& fc = cp.faceCells();
        forAll(fc, k)
        {
            // inflow here: the partner face's outflow volume is the truth
            if (phiP[k] < 0)
            {
                a[fc[k]] += (dV[k] + dVn[k])/mesh.V()[fc[k]];
            }
        }
    }
    alpha.correctBoundaryConditions();
}

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
        syncCyclic(alpha, phi, advector);
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
