/*---------------------------------------------------------------------------*\
  vheFoam: making a flux divergence-free again (after a mesh change, and
  around rigid bodies)
\*---------------------------------------------------------------------------*/

#include "fluxProjection.H"
#include "fvm.H"
#include "fvc.H"
#include "adjustPhi.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"

Foam::label Foam::fluxProjection::referenceCell(const fvMesh& mesh)
{
    const label first = returnReduce
    (
        mesh.nCells() > 0 ? Pstream::myProcNo() : Pstream::nProcs(),
        minOp<label>()
    );
    return Pstream::myProcNo() == first ? 0 : -1;
}


void Foam::fluxProjection::project
(
    surfaceScalarField& phi,
    const volVectorField& U,
    const volScalarField& p_rgh,
    const surfaceScalarField& rAUf,
    const label nNonOrthCorr
)
{
    const fvMesh& mesh = phi.mesh();

    wordList pcorrTypes
    (
        p_rgh.boundaryField().size(),
        zeroGradientFvPatchScalarField::typeName
    );
    forAll(p_rgh.boundaryField(), patchi)
    {
        if (p_rgh.boundaryField()[patchi].fixesValue())
        {
            pcorrTypes[patchi] = fixedValueFvPatchScalarField::typeName;
        }
    }
    volScalarField pcorr
    (
        IOobject("pcorr", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(p_rgh.dimensions(), Zero),
        pcorrTypes
    );
    mesh.setFluxRequired(pcorr.name());
    if (pcorr.needReference())
    {
        adjustPhi(phi, U, pcorr);
    }

    dictionary controls;
    if (mesh.solutionDict().subDict("solvers").found("pcorr"))
    {
        controls = mesh.solver("pcorr");
    }
    else
    {
        // p_rgh's solver to p_rgh's tolerance.  GAMG by itself stalls on
        // this matrix (a settling disk on 196,608 cells: 1000 iterations,
        // residual 1e-6; the closed cells' rows are decoupled), PCG with
        // DIC needs about 950 iterations there: GAMG as the preconditioner
        // of PCG takes 60 to 90
        const dictionary& pd = mesh.solver(p_rgh.select(true));
        if (pd.get<word>("solver") == "GAMG")
        {
            dictionary gamg(pd);
            gamg.set("preconditioner", "GAMG");
            gamg.remove("solver");
            controls.add("preconditioner", gamg);
        }
        else
        {
            controls.add("preconditioner", "DIC");
        }
        controls.add("solver", "PCG");
        controls.add("tolerance", pd.get<scalar>("tolerance"));
        controls.add("relTol", scalar(0));
    }

    const label refCell = referenceCell(mesh);
    for (label corr = 0; corr <= nNonOrthCorr; ++corr)
    {
        fvScalarMatrix pcorrEqn(fvm::laplacian(rAUf, pcorr) == fvc::div(phi));

        // Cells without an open face: pcorr = 0.  A face on a processor or
        // cyclic patch counts: its coefficient is not in the diagonal
        scalarField& diag = pcorrEqn.diag();
        scalarField open(mag(diag));
        forAll(rAUf.boundaryField(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (!pp.coupled()) continue;
            const scalarField& rp = rAUf.boundaryField()[patchi];
            forAll(rp, i) open[pp.faceCells()[i]] += mag(rp[i]);
        }
        const scalar dMax = gMax(mag(diag));
        forAll(diag, celli)
        {
            if (open[celli] == 0)
            {
                diag[celli] = -dMax;
                pcorrEqn.source()[celli] = 0;
            }
        }
        pcorrEqn.setReference(refCell, 0);
        pcorrEqn.solve(controls);
        if (corr == nNonOrthCorr)
        {
            phi -= pcorrEqn.flux();
        }
    }
}


// ************************************************************************* //
