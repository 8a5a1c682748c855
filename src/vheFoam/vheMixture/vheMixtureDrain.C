/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- the fluids in a drawn
  rigid body's edge cells kept within the range of the fluids beside the
  body (C core: drain.c)
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "syncTools.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::vheMixture::drainEdges(const labelList& held)
{
    // Why: a drawn body's edge cells move wholly with it (their faces
    // carry its rigid flux), so their fluids keep their mix wherever it
    // goes, and a light box rising through a free surface floated on a
    // row of water it brought up from depth (drain.c).  An edge cell
    // whose fluids lie outside the range of those beside it is brought
    // into that range, the difference exchanged with its outside face
    // neighbours (over coupled faces too: both sides compute the same
    // volumes)
    DynamicList<label> fluids;
    forAll(phases_, j)
    {
        if (!phases_[j].solid && !held.found(j)) fluids.append(j);
    }
    const label K = fluids.size();
    if (K < 2) return;
    if (K > VHE_DRAIN_MAX)
    {
        FatalErrorInFunction
            << K << " fluids beside the drawn bodies: at most "
            << VHE_DRAIN_MAX << exit(FatalError);
    }
    // A cell moves wholly with its body, its faces carrying the rigid
    // flux, from a fraction of 1/40 (rigidBodies: weight min(1, 4 alpha)
    // from 1/10); below it, its fluids move with the flow
    const scalar lo = 0.025;

    const label nCells = mesh_.nCells();
    const label nInt = mesh_.nInternalFaces();
    scalarField sumHeld(nCells, Zero);
    for (const label k : held) sumHeld += alphas_[k].primitiveField();

    // The coupled boundary faces: their cells and the other side's values
    DynamicList<label> bFace, bCell;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (!pp.coupled()) continue;
        forAll(pp, i)
        {
            bFace.append(pp.start() - nInt + i);
            bCell.append(pp.faceCells()[i]);
        }
    }
    const label nB = bFace.size();
    auto other = [&](const scalarField& cellValues)
    {
        scalarField all;
        syncTools::swapBoundaryCellList(mesh_, cellValues, all);
        return scalarField(all, bFace);
    };
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField heldB(other(sumHeld));

    // The fluids' fractions, here and across coupled faces
    List<scalarField> aB(K);
    List<const double*> a(K), aNei(K);
    forAll(fluids, k)
    {
        aB[k] = other(alphas_[fluids[k]].primitiveField());
        a[k] = alphas_[fluids[k]].primitiveField().cdata();
        aNei[k] = aB[k].cdata();
    }
    const int* bC = bCell.cdata();

    scalarField links(nCells, Zero);
    vhe_drain_links
    (
        nInt, own.cdata(), nei.cdata(), K, a.cdata(), sumHeld.cdata(),
        nullptr, nullptr, lo, links.data()
    );
    vhe_drain_links
    (
        nB, bC, nullptr, K, a.cdata(), sumHeld.cdata(), aNei.cdata(),
        heldB.cdata(), lo, links.data()
    );
    if (returnReduce(max(links), maxOp<scalar>()) <= 0) return;

    // How far each edge cell moves towards the fluids beside it
    List<scalarField> sum(K, scalarField(nCells, Zero));
    List<scalarField> mn(K, scalarField(nCells, 2.0));
    List<scalarField> mx(K, scalarField(nCells, -1.0));
    List<double*> pSum(K), pMn(K), pMx(K);
    forAll(fluids, k)
    {
        pSum[k] = sum[k].data();
        pMn[k] = mn[k].data();
        pMx[k] = mx[k].data();
    }
    vhe_drain_range
    (
        nInt, own.cdata(), nei.cdata(), K, a.cdata(), sumHeld.cdata(),
        nullptr, nullptr, lo, pSum.data(), pMn.data(), pMx.data()
    );
    vhe_drain_range
    (
        nB, bC, nullptr, K, a.cdata(), sumHeld.cdata(), aNei.cdata(),
        heldB.cdata(), lo, pSum.data(), pMn.data(), pMx.data()
    );
    scalarField lambda(nCells, Zero);
    vhe_drain_lambda
    (
        nCells, K, a.cdata(), links.cdata(), pSum.cdata(), pMn.cdata(),
        pMx.cdata(), lambda.data()
    );

    // The exchanges, each computed alike on both sides of a coupled face
    const scalarField linksB(other(links));
    const scalarField lambdaB(other(lambda));
    const scalarField VB(other(mesh_.V()));
    List<scalarField> dInt(K, scalarField(nInt)), dB(K, scalarField(nB));
    List<double*> pInt(K), pB(K);
    forAll(fluids, k)
    {
        pInt[k] = dInt[k].data();
        pB[k] = dB[k].data();
    }
    vhe_drain_faces
    (
        nInt, own.cdata(), nei.cdata(), K, a.cdata(), sumHeld.cdata(),
        mesh_.V().cdata(), links.cdata(), lambda.cdata(), nullptr, nullptr,
        nullptr, nullptr, nullptr, lo, pInt.data()
    );
    vhe_drain_faces
    (
        nB, bC, nullptr, K, a.cdata(), sumHeld.cdata(), mesh_.V().cdata(),
        links.cdata(), lambda.cdata(), aNei.cdata(), heldB.cdata(),
        VB.cdata(), linksB.cdata(), lambdaB.cdata(), lo, pB.data()
    );

    // The volumes moved: into the owner, out of the neighbour
    const scalarField& V = mesh_.V();
    forAll(fluids, k)
    {
        scalarField& ak = alphas_[fluids[k]].primitiveFieldRef();
        forAll(nei, f)
        {
            ak[own[f]] += dInt[k][f]/V[own[f]];
            ak[nei[f]] -= dInt[k][f]/V[nei[f]];
        }
        forAll(bCell, i) ak[bCell[i]] += dB[k][i]/V[bCell[i]];
        alphas_[fluids[k]].correctBoundaryConditions();
    }
}


// ************************************************************************* //
