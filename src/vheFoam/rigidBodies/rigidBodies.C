/*---------------------------------------------------------------------------*\
  vheFoam: rigid bodies
\*---------------------------------------------------------------------------*/

#include "rigidBodies.H"
#include "syncTools.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "vhe.h"

namespace
{
    //- How much of a cell moves with the body: all of it where its
    //  fraction is above one half, in proportion below
    inline Foam::scalar weight(const Foam::scalar alpha)
    {
        return Foam::min(1.0, 4.0*alpha);
    }
}

Foam::rigidBodies::rigidBodies(const vheMixture& mixture)
:
    mixture_(mixture),
    materials_(),
    regions_(mixture.rho().mesh(), 0.5)
{
    DynamicList<label> rigid;
    forAll(mixture_.phases(), i)
    {
        if (mixture_.phases()[i].rigid) rigid.append(i);
    }
    materials_.transfer(rigid);
    if (active())
    {
        Info<< "Rigid bodies: the velocity of each body of";
        for (const label i : materials_)
        {
            Info<< ' ' << mixture_.phases()[i].name;
        }
        Info<< " projected onto rigid motion every step" << nl << endl;
    }
}


void Foam::rigidBodies::correct(volVectorField& U)
{
    const fvMesh& mesh = U.mesh();
    const vectorField& C = mesh.C().primitiveField();
    const scalarField& V = mesh.V();
    const scalarField& rho = mixture_.rho().primitiveField();
    vectorField& u = U.primitiveFieldRef();

    // Which body moves each cell wholly (-1: none), numbered over all
    // rigid phases: a face is rigid only between two cells of one body
    labelList wholly(mesh.nCells(), -1);
    // How many bodies reach each cell: a cell that two bodies reach has
    // the velocity of neither (the second's projection blends the first's)
    labelList reached(mesh.nCells(), 0);

    label nBodies = 0;
    for (const label i : materials_)
    {
        const scalarField& a = mixture_.alphas()[i].primitiveField();
        if (gMax(a) <= 0) continue;      // a spare colour: no body
        regions_.find(a);
        const label nB = regions_.size();
        const labelList& lab = regions_.cellBody();
        const List<vector>& X0 = regions_.centroid();
        const label first = nBodies;
        nBodies += nB;

        // Mass, momentum and centre of mass (relative to the centroid)
        scalarList M(nB, Zero);
        List<vector> P(nB, Zero), Rm(nB, Zero);
        forAll(lab, c)
        {
            const label b = lab[c];
            if (b < 0) continue;
            const scalar m = rho[c]*weight(a[c])*V[c];
            M[b] += m;
            P[b] += m*u[c];
            Rm[b] += m*regions_.nearestImage(C[c] - X0[b]);
        }
        bodyRegions::sumLists(M);
        bodyRegions::sumLists(P);
        bodyRegions::sumLists(Rm);
        List<vector> Ub(nB), Xm(nB);
        forAll(Ub, b)
        {
            Ub[b] = P[b]/max(M[b], VSMALL);
            Xm[b] = Rm[b]/max(M[b], VSMALL);
        }

        // Angular momentum and second moment about the centre of mass
        List<symmTensor> J(nB, Zero);
        List<vector> L(nB, Zero);
        forAll(lab, c)
        {
            const label b = lab[c];
            if (b < 0) continue;
            const scalar m = rho[c]*weight(a[c])*V[c];
            const vector r(regions_.nearestImage(C[c] - X0[b]) - Xm[b]);
            J[b] += m*sqr(r);
            L[b] += m*(r ^ (u[c] - Ub[b]));
        }
        bodyRegions::sumLists(J);
        bodyRegions::sumLists(L);
        List<vector> omega(nB);
        forAll(omega, b)
        {
            vhe_body_omega
            (
                J[b].cdata(), L[b].cdata(), regions_.normal(),
                omega[b].data()
            );
        }

        // The projection onto rigid motion, weighted by the fraction
        forAll(lab, c)
        {
            const label b = lab[c];
            if (b < 0) continue;
            const vector r(regions_.nearestImage(C[c] - X0[b]) - Xm[b]);
            u[c] += weight(a[c])*(Ub[b] + (omega[b] ^ r) - u[c]);
            if (weight(a[c]) >= 1) wholly[c] = first + b;
            if (weight(a[c]) > 0) ++reached[c];
        }
    }
    // A cell is rigid with a body only if no other body reaches it: else
    // the faces between it and the body's other cells would carry a flux
    // that is not the body's, whose divergence nothing corrects (the
    // flux correction leaves a body's inner cells alone)
    forAll(wholly, c)
    {
        if (reached[c] > 1) wholly[c] = -1;
    }
    U.correctBoundaryConditions();

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
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
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

    Info<< "Rigid bodies: " << nBodies << " projected" << endl;
}


// ************************************************************************* //
