/*---------------------------------------------------------------------------*\
  vheFoam: rigid bodies -- after the projection: each body's velocity and
  flux made rigid
\*---------------------------------------------------------------------------*/

#include "rigidBodies.H"
#include "syncTools.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "vhe.h"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "fvcSup.H"
#include "fvmDdt.H"
#include "scalarMatrices.H"
#include "uniformDimensionedFields.H"
#include "OSspecific.H"

void Foam::rigidBodies::correct(volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    vectorField& u = U.primitiveFieldRef();

    List<vector>& Ub = Ub_;
    List<vector>& omega = omega_;
    rigidMotion(u, Ub, omega);
    holdMotion(Ub, omega);
    if (poses_.active())
    {
        poses_.constrain(Ub);
        poses_.setMotion(Ub, omega, Xm_, regions_);
    }
    // The force that holds each body: the penalty's in the held solve and
    // the momentum this projection takes from its cells, at the rate the
    // time scheme gives a change of the new velocity (its coefficient of
    // U^(n+1): rho/dt with Euler, 3 rho/(2 dt) with backward; with rho/dt
    // a cylinder moved through still liquid felt 2.4 % to 8.8 % too little
    // drag under backward at Courant numbers 0.25 to 0.06)
    const scalarField Addt(timeCoefficient(U));
    const scalarField& V = mesh.V();
    List<vector> Fc(nBodies_, Zero), Tc(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0) continue;
        const vector du(hold_[c]*(Ub[b] + (omega[b] ^ r_[c]) - u[c]));
        const vector f(Addt[c]*V[c]*du);
        Fc[b] += f;
        Tc[b] += r_[c] ^ f;
        u[c] += du;
    }
    U.correctBoundaryConditions();
    bodyRegions::sumLists(Fc);
    bodyRegions::sumLists(Tc);
    if (Fpen_.size() == nBodies_)
    {
        forAll(Fc, b)
        {
            Fc[b] += Fpen_[b];
            Tc[b] += Tpen_[b];
        }
    }
    writeForces(Fc, Tc);

    // A cell moves wholly with a body where its weight is 1/10 or more
    // (a fraction of 1/40) and no other body reaches it: the faces between
    // two such cells of one body carry the body's rigid flux (rigidFlux),
    // so the body's diffuse edge moves with it.  (So too where the edge is
    // a wall, edge(): with only the held cells' faces rigid, a cylinder
    // moved through still liquid felt 1.10 % more drag than held in a
    // stream, 0.36 % with these; galilean.sh at 10 cells, Re 100.)
    // (Faces between cells of weight 1 only left the edge to the fluid's
    // flux: a disk in shear reached a Taylor deformation of 0.017 at 32
    // cells, now 0.0027; a
    // settling disk 0.052 by t = 0.28, now 0.025.  Not every cell the
    // body reaches: its tails of 1e-18 would lock liquid cells to it, and
    // the flux correction had no consistent solution.)  Else the faces
    // between it and the body's other cells would carry a flux that is
    // not the body's, whose divergence nothing corrects
    // A cell next to a cell of another body does not move wholly either:
    // where two bodies' wholly moving cells met face to face, the cells
    // on either side of that face had every other face's flux fixed, and
    // the flux correction had no solution there (two rigid disks of 1.6
    // cells' radius touching in a 32-cell channel: pcorr's DIC divided by
    // zero)
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    boolList nearOther(mesh.nCells(), false);
    {
        forAll(nei, f)
        {
            const label bo = body_[own[f]], bn = body_[nei[f]];
            if (bo >= 0 && bn >= 0 && bo != bn)
            {
                nearOther[own[f]] = true;
                nearOther[nei[f]] = true;
            }
        }
        labelList bodyNbr;
        syncTools::swapBoundaryCellList(mesh, body_, bodyNbr);
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (!pp.coupled()) continue;
            const label start = pp.start() - mesh.nInternalFaces();
            forAll(pp, i)
            {
                const label c = pp.faceCells()[i];
                const label bn = bodyNbr[start + i];
                if (body_[c] >= 0 && bn >= 0 && body_[c] != bn)
                {
                    nearOther[c] = true;
                }
            }
        }
    }
    labelList wholly(mesh.nCells(), -1);
    forAll(wholly, c)
    {
        if
        (
            body_[c] >= 0 && flowW_[c] >= 0.1 && reached_[c] == 1
         && !nearOther[c]
        )
        {
            wholly[c] = body_[c];
        }
    }

    // The faces whose two cells move wholly with one body.  (Two bodies
    // that touch: the faces between them are not rigid, else a cell
    // between two bodies moving apart or together could have every face's
    // flux fixed, and no pressure could make it divergence-free: the
    // flux correction diverged when rigid bodies collided.)
    if (!rigidFaces_.valid())
    {
        rigidFaces_.reset
        (
            new surfaceScalarField
            (
                IOobject("rigidFaces", mesh.time().timeName(), mesh),
                mesh,
                dimensionedScalar(dimless, Zero)
            )
        );
    }
    surfaceScalarField& rf = *rigidFaces_;
    rf = dimensionedScalar(dimless, Zero);
    forAll(nei, f)
    {
        rf[f] = (wholly[own[f]] >= 0 && wholly[own[f]] == wholly[nei[f]]);
    }
    labelList whollyNbr;
    syncTools::swapBoundaryCellList(mesh, wholly, whollyNbr);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (pp.coupled())
        {
            const label start = pp.start() - mesh.nInternalFaces();
            scalarField& rp = rf.boundaryFieldRef()[patchi];
            forAll(rp, i)
            {
                const label w = wholly[pp.faceCells()[i]];
                rp[i] = (w >= 0 && w == whollyNbr[start + i]);
            }
        }
    }

    Info<< "Rigid bodies: " << nBodies_ << " projected" << endl;
}


void Foam::rigidBodies::rigidFlux(surfaceScalarField& phi) const
{
    const fvMesh& mesh = phi.mesh();
    const surfaceScalarField& rf = *rigidFaces_;
    const vectorField& C = mesh.C().primitiveField();
    const vectorField& Cf = mesh.Cf().primitiveField();
    const vectorField& Sf = mesh.Sf().primitiveField();
    const labelUList& own = mesh.faceOwner();
    forAll(rf, f)
    {
        if (rf[f] <= 0) continue;
        const label c = own[f];
        const label b = body_[c];
        const vector r(r_[c] + Cf[f] - C[c]);
        phi[f] = (Ub_[b] + (omega_[b] ^ r)) & Sf[f];
    }
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (!pp.coupled()) continue;
        const scalarField& rp = rf.boundaryField()[patchi];
        scalarField& pphi = phi.boundaryFieldRef()[patchi];
        const vectorField& pCf = pp.Cf();
        const vectorField& pSf = pp.Sf();
        forAll(rp, i)
        {
            if (rp[i] <= 0) continue;
            const label c = pp.faceCells()[i];
            const label b = body_[c];
            const vector r(r_[c] + pCf[i] - C[c]);
            pphi[i] = (Ub_[b] + (omega_[b] ^ r)) & pSf[i];
        }
    }
}

// ************************************************************************* //
