/*---------------------------------------------------------------------------*\
  vheFoam: the momentum and continuity equations of a step solved together,
  assembled into one PETSc matrix (libvheCoupled, loaded by coupledStep on
  the first coupled solve; the equations are described in coupledStep.H)
\*---------------------------------------------------------------------------*/

#include "coupledStepPETSc.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "globalIndex.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "calculatedFvPatchFields.H"
#include "linear.H"
#include "transposeRows.H"
#include "rigidBodyRows.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

void check(PetscErrorCode ierr, const char* what)
{
    if (ierr)
    {
        FatalErrorInFunction
            << "PETSc error " << ierr << " in " << what
            << Foam::exit(Foam::FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(coupledStepPETSc, 0);
    addNamedToRunTimeSelectionTable
    (
        coupledSolver,
        coupledStepPETSc,
        mesh,
        PETSc
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledStepPETSc::coupledStepPETSc
(
    const fvMesh& mesh,
    const string& options
)
:
    mesh_(mesh),
    options_(options),
    started_(false),
    A_(nullptr),
    ksp_(nullptr)
{
    start();
}


Foam::coupledStepPETSc::~coupledStepPETSc()
{
    if (ksp_) KSPDestroy(&ksp_);
    if (A_) MatDestroy(&A_);
    if (started_)
    {
        PetscFinalize();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coupledStepPETSc::start()
{
    // The options as coupledStep gives them: the case's, else
    // coupledSolver::defaultOptions
    PetscBool initialised = PETSC_FALSE;
    PetscInitialized(&initialised);
    if (!initialised)
    {
        check(PetscInitializeNoArguments(), "PetscInitialize");
        started_ = true;
    }
    check
    (
        PetscOptionsInsertString(nullptr, options_.c_str()),
        "PetscOptionsInsertString"
    );
    Info<< "Coupled step: PETSc " << options_.c_str() << endl;
}


void Foam::coupledStepPETSc::solve
(
    const fvMatrix<vector>& UEqn,
    const volScalarField& rho,
    const surfaceScalarField& faceForces,
    volVectorField& U,
    volScalarField& p_rgh,
    surfaceScalarField& phi,
    surfaceScalarField& accelerationFlux,
    volVectorField& acceleration,
    label pRefCell,
    const volScalarField* muT,
    coupledRigidRows* rigid
)
{
    const label nC = mesh_.nCells();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const fvBoundaryMesh& patches = mesh_.boundary();

    // The solved velocity components, then p_rgh: nb unknowns a cell
    labelList cmpts;
    forAll(mesh_.solutionD(), c)
    {
        if (mesh_.solutionD()[c] > 0) cmpts.append(c);
    }
    const label nd = cmpts.size();
    const label nb = nd + 1;

    const globalIndex cellsG(nC);
    const label start0 = cellsG.offset(Pstream::myProcNo());
    auto row = [&](label celli, label k) -> PetscInt
    {
        return PetscInt((start0 + celli)*nb + k);
    };

    // Rigid bodies' unknowns (coupledRigidRows): after every cell's, on
    // the last rank
    const rigidBodyRows bodies(mesh_, rigid, cmpts, cellsG.size());

    // Global ids of the cells across coupled patches
    volScalarField ids
    (
        IOobject
        (
            "coupledStep:ids", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero),
        calculatedFvPatchScalarField::typeName
    );
    forAll(ids, i)
    {
        ids[i] = start0 + i;
    }
    ids.correctBoundaryConditions();

    // Face quantities
    const surfaceScalarField rhof(fvc::interpolate(rho));
    const volScalarField rAU("rAU", rho/UEqn.A());
    const surfaceScalarField Df(fvc::interpolate(rAU));
    // the wide part D a_c interpolated as one (interFoam's flux(rAU H)):
    // where rho/A jumps, at a light or held body's edge, the product of
    // the two interpolations took the body's large acceleration at the
    // liquid's coefficient
    const surfaceVectorField DaInterp(linearInterpolate(rAU*acceleration));
    const surfaceScalarField& w = mesh_.weights();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceScalarField& delta = mesh_.deltaCoeffs();
    const surfaceVectorField SfHat(Sf/magSf);

    // reconstruct's inverse: rho V inv(sum SfHat Sf) per cell
    const volTensorField Minv(inv(fvc::surfaceSum(SfHat*Sf)));
    const scalarField rhoV(rho.primitiveField()*mesh_.V());

    // fixedFluxPressure: the gradient that balances the face forces, so
    // that a wall's face acceleration is zero, as the projection's
    // constrainPressure makes it
    forAll(patches, patchi)
    {
        fvPatchScalarField& pp = p_rgh.boundaryFieldRef()[patchi];
        if (isA<fixedFluxPressureFvPatchScalarField>(pp))
        {
            const scalarField snGradp
            (
                faceForces.boundaryField()[patchi]
               /magSf.boundaryField()[patchi]
            );
            refCast<fixedFluxPressureFvPatchScalarField>(pp).updateSnGrad
            (
                snGradp
            );
        }
    }

    // The matrix, unless it is the kept one (the passes of a step): then
    // the right-hand side alone
    const bool keep = sameMatrix(UEqn, rho, muT, rigid);
    Mat A = nullptr;
    const PetscInt nLocal = nC*nb + bodies.nLocal();
    if (!keep)
    {
        // A row's cells: the cell and its face neighbours (and theirs
        // where the transpose part acts, transposeRows)
        labelList nnz(nLocal, Zero);
        const cellList& cells = mesh_.cells();
        forAll(cells, i)
        {
            const label n =
                muT
              ? transposeRows::width(mesh_, muT->primitiveField(), i)
              : cells[i].size() + 1;
            for (label k = 0; k < nb; ++k)
            {
                nnz[i*nb + k] = nb*n + bodies.cellWidth(i);
            }
        }
        const labelList bw(bodies.widths());
        forAll(bw, r)
        {
            nnz[nC*nb + r] = bw[r];
        }
        List<PetscInt> dnz(nLocal), onz(nLocal);
        forAll(nnz, r)
        {
            dnz[r] = min(nnz[r], nLocal);
            onz[r] = Pstream::parRun() ? nnz[r] : 0;
        }
        check
        (
            MatCreateAIJ
            (
                PETSC_COMM_WORLD, nLocal, nLocal, PETSC_DETERMINE,
                PETSC_DETERMINE, 0, dnz.cdata(), 0, onz.cdata(), &A
            ),
            "MatCreateAIJ"
        );
        MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE);
        // nb unknowns a cell, interleaved (a field split takes them with
        // -pc_fieldsplit_block_size nb)
    }
    Vec b, x;
    check(MatCreateVecs(keep ? A_ : A, &x, &b), "MatCreateVecs");

    auto add = [&](PetscInt r, PetscInt c, scalar v)
    {
        if (keep) return;
        PetscScalar val = v;
        MatSetValues(A, 1, &r, 1, &c, &val, ADD_VALUES);
    };
    auto addB = [&](PetscInt r, scalar v)
    {
        PetscScalar val = v;
        VecSetValues(b, 1, &r, &val, ADD_VALUES);
    };

    // Momentum: UEqn's rows
    const scalarField& diag = UEqn.diag();
    const scalarField& upper = UEqn.upper();
    const scalarField& lower = UEqn.lower();
    vectorField source(UEqn.source());
    vectorField diagV(nC, Zero);
    forAll(diagV, i)
    {
        diagV[i] = vector::one*diag[i];
    }
    forAll(patches, patchi)
    {
        const labelUList& fc = patches[patchi].faceCells();
        const vectorField& ic = UEqn.internalCoeffs()[patchi];
        const vectorField& bc = UEqn.boundaryCoeffs()[patchi];
        forAll(fc, j)
        {
            diagV[fc[j]] += ic[j];
        }
        if (patches[patchi].coupled())
        {
            const scalarField nbr
            (
                ids.boundaryField()[patchi].patchNeighbourField()
            );
            forAll(fc, j)
            {
                for (label k = 0; k < nd; ++k)
                {
                    add
                    (
                        row(fc[j], k), PetscInt(nbr[j])*nb + k,
                        -bc[j][cmpts[k]]
                    );
                }
            }
        }
        else
        {
            forAll(fc, j)
            {
                source[fc[j]] += bc[j];
            }
        }
    }
    for (label i = 0; i < nC; ++i)
    {
        for (label k = 0; k < nd; ++k)
        {
            add(row(i, k), row(i, k), diagV[i][cmpts[k]]);
            addB(row(i, k), source[i][cmpts[k]]);
        }
    }
    forAll(own, f)
    {
        for (label k = 0; k < nd; ++k)
        {
            add(row(own[f], k), row(nei[f], k), upper[f]);
            add(row(nei[f], k), row(own[f], k), lower[f]);
        }
    }

    // The semi-implicit increment's transpose part (muT the elastic
    // viscosity): its internal-face part in the matrix, the rest (boundary
    // and coupled faces) explicit, as the difference between the whole
    // term and that part at the current U
    if (muT)
    {
        transposeRows::add(mesh_, *muT, U, cmpts, start0, A, b);
    }

    // A face's terms in the rows of cell X (owner O, neighbour N): the
    // momentum rows take -rho V reconstruct(a_f), a_f = ff/rho_f - g (p_N
    // - p_O); the continuity rows s phi_f (s = +1 owner, -1 neighbour),
    // phi_f = w U_O.S + (1 - w) U_N.S + D a_f - (D a)_f.S
    auto faceTerms = [&]
    (
        label X, scalar s, PetscInt rO, PetscInt rN,
        scalar wf, const vector& S, const vector& Shat, scalar g,
        scalar ffByRho, scalar D, const vector& aI
    )
    {
        const vector v(rhoV[X]*(Minv[X] & Shat));
        for (label k = 0; k < nd; ++k)
        {
            const scalar vk = v[cmpts[k]];
            add(row(X, k), rN*nb + nd, vk*g);
            add(row(X, k), rO*nb + nd, -vk*g);
            addB(row(X, k), vk*ffByRho);
            add(row(X, nd), rO*nb + k, s*wf*S[cmpts[k]]);
            add(row(X, nd), rN*nb + k, s*(1 - wf)*S[cmpts[k]]);
        }
        add(row(X, nd), rN*nb + nd, -s*D*g);
        add(row(X, nd), rO*nb + nd, s*D*g);
        addB(row(X, nd), -s*(D*ffByRho - (aI & S)));
    };

    forAll(own, f)
    {
        const label O = own[f], N = nei[f];
        const scalar g = delta[f]*magSf[f]/rhof[f];
        const scalar ffr = faceForces[f]/rhof[f];
        for (const label X : {O, N})
        {
            faceTerms
            (
                X, X == O ? 1 : -1, start0 + O, start0 + N, w[f], Sf[f],
                SfHat[f], g, ffr, Df[f], DaInterp[f]
            );
        }
    }

    forAll(patches, patchi)
    {
        const fvPatch& pp = patches[patchi];
        const labelUList& fc = pp.faceCells();
        const scalarField& magSb = magSf.boundaryField()[patchi];
        const vectorField& Sb = Sf.boundaryField()[patchi];
        const vectorField& Shat = SfHat.boundaryField()[patchi];
        const scalarField& ffb = faceForces.boundaryField()[patchi];
        const scalarField& rhob = rhof.boundaryField()[patchi];
        if (pp.coupled())
        {
            const scalarField nbr
            (
                ids.boundaryField()[patchi].patchNeighbourField()
            );
            const scalarField& wb = w.boundaryField()[patchi];
            const scalarField& db = delta.boundaryField()[patchi];
            forAll(fc, j)
            {
                faceTerms
                (
                    fc[j], 1, start0 + fc[j], PetscInt(nbr[j]), wb[j],
                    Sb[j], Shat[j], db[j]*magSb[j]/rhob[j],
                    ffb[j]/rhob[j], Df.boundaryField()[patchi][j],
                    DaInterp.boundaryField()[patchi][j]
                );
            }
            continue;
        }

        // p_rgh's boundary condition: snGrad = gIC p_P + gBC
        const fvPatchScalarField& pb = p_rgh.boundaryField()[patchi];
        const scalarField gIC(pb.gradientInternalCoeffs());
        const scalarField gBC(pb.gradientBoundaryCoeffs());
        // U's: U_b = vIC U_P + vBC (component-wise)
        const fvPatchVectorField& Ub = U.boundaryField()[patchi];
        const scalarField wb(pp.weights());
        const vectorField vIC(Ub.valueInternalCoeffs(wb));
        const vectorField vBC(Ub.valueBoundaryCoeffs(wb));
        forAll(fc, j)
        {
            const label P = fc[j];
            const vector v(rhoV[P]*(Minv[P] & Shat[j]));
            const scalar m = magSb[j]/rhob[j];
            for (label k = 0; k < nd; ++k)
            {
                const scalar vk = v[cmpts[k]];
                // a_b = ff/rho - m (gIC p_P + gBC)
                add(row(P, k), row(P, nd), vk*m*gIC[j]);
                addB(row(P, k), vk*(ffb[j]/rhob[j] - m*gBC[j]));
                add(row(P, nd), row(P, k), vIC[j][cmpts[k]]*Sb[j][cmpts[k]]);
            }
            addB(row(P, nd), -(vBC[j] & Sb[j]));
        }
    }

    // The pressure level of a closed domain: p_rgh kept at its value in
    // the reference cell (as the projection's setReference)
    if (p_rgh.needReference() && pRefCell >= 0)
    {
        const scalar c = sum(Df.primitiveField())/max(Df.size(), 1)
           *delta[0]*magSf[0]/rhof[0];
        add(row(pRefCell, nd), row(pRefCell, nd), c);
        addB(row(pRefCell, nd), c*p_rgh[pRefCell]);
    }

    // The rigid bodies' rows and columns (rigidBodyRows)
    bodies.add(A, b, start0);

    if (!keep)
    {
        check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
        check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    }
    check(VecAssemblyBegin(b), "VecAssemblyBegin");
    check(VecAssemblyEnd(b), "VecAssemblyEnd");

    // Initial guess: the current U and p_rgh
    {
        PetscScalar* xa;
        VecGetArray(x, &xa);
        for (label i = 0; i < nC; ++i)
        {
            for (label k = 0; k < nd; ++k)
            {
                xa[i*nb + k] = U[i][cmpts[k]];
            }
            xa[i*nb + nd] = p_rgh[i];
        }
        bodies.guess(xa + nC*nb);
        VecRestoreArray(x, &xa);
    }

    // The kept solver as it is for the kept matrix (its factorisation
    // reused); where the pattern is the same, the new values copied into
    // the kept matrix (its nonzero state unchanged, so the LU's setup is
    // numeric only)
    if (keep)
    {}
    else if (samePattern(A))
    {
        check(MatCopy(A, A_, SAME_NONZERO_PATTERN), "MatCopy");
        MatDestroy(&A);
    }
    else
    {
        if (ksp_) KSPDestroy(&ksp_);
        if (A_) MatDestroy(&A_);
        A_ = A;
        check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "KSPCreate");
        check(KSPSetOperators(ksp_, A_, A_), "KSPSetOperators");
        check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
        KSPType type;
        KSPGetType(ksp_, &type);
        if (std::string(type) != KSPPREONLY)
        {
            KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE);
        }
    }
    check(KSPSolve(ksp_, b, x), "KSPSolve");
    KSPConvergedReason reason;
    KSPGetConvergedReason(ksp_, &reason);
    if (reason < 0)
    {
        WarningInFunction
            << "PETSc did not converge (reason " << int(reason) << ")"
            << endl;
    }

    {
        const PetscScalar* xa;
        VecGetArrayRead(x, &xa);
        for (label i = 0; i < nC; ++i)
        {
            for (label k = 0; k < nd; ++k)
            {
                U[i][cmpts[k]] = xa[i*nb + k];
            }
            p_rgh[i] = xa[i*nb + nd];
        }
        bodies.read(xa + nC*nb);
        VecRestoreArrayRead(x, &xa);
    }
    VecDestroy(&x);
    VecDestroy(&b);

    U.correctBoundaryConditions();
    p_rgh.correctBoundaryConditions();

    // The face flux and the accelerations as the projection leaves them
    accelerationFlux =
        (faceForces - fvc::snGrad(p_rgh)*magSf)/rhof;
    surfaceScalarField damping(Df*accelerationFlux - (DaInterp & Sf));
    forAll(patches, patchi)
    {
        if (!patches[patchi].coupled())
        {
            damping.boundaryFieldRef()[patchi] = Zero;
        }
    }
    phi = fvc::flux(U) + damping;
    acceleration = fvc::reconstruct(accelerationFlux);
}


// ************************************************************************* //
