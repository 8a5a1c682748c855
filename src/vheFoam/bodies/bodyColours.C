/*---------------------------------------------------------------------------*\
  vheFoam: bodies that keep their identity
\*---------------------------------------------------------------------------*/

#include "bodyColours.H"
#include "volFields.H"
#include "syncTools.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bodyColours::bodyColours(vheMixture& mixture)
:
    mixture_(mixture),
    materials_(),
    regions_(mixture.rho().mesh(), 0.5),
    warned_(false),
    travelled_(maxTravel),
    wait_(maxTravel),
    h_(0),
    periodic_(false)
{
    const fvMesh& mesh = mixture.rho().mesh();
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        periodic_ = periodic_ || (pp.coupled() && !isA<processorPolyPatch>(pp));
    }
    reduce(periodic_, orOp<bool>());

    const List<vheMixture::phase>& ph = mixture_.phases();
    DynamicList<labelList> groups;
    forAll(ph, i)
    {
        if (!ph[i].solid || ph[i].colour != 0) continue;
        DynamicList<label> g(1, i);
        for (label j = i + 1; j < ph.size() && ph[j].material == ph[i].material; ++j)
        {
            g.append(j);
        }
        if (g.size() > 1)
        {
            groups.append(labelList(g));
        }
    }
    materials_.transfer(groups);

    for (const labelList& g : materials_)
    {
        Info<< "Body colours: " << ph[g[0]].material << " has " << g.size()
            << " colours (alpha." << ph[g[0]].name << " ... alpha."
            << ph[g.last()].name << "); bodies of one colour that come"
            << " near are given another" << nl << endl;
    }
}


// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

Foam::labelList Foam::bodyColours::grow(const labelList& lab) const
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const label nInt = mesh.nInternalFaces();
    const boolList coupled(bodyRegions::coupledFaces(mesh));

    labelList nbr;
    syncTools::swapBoundaryCellList(mesh, lab, nbr);

    // An empty cell takes the largest body label next to it (the same on
    // every processor, so the result does not depend on the decomposition)
    labelList out(lab);
    for (label f = 0; f < nInt; ++f)
    {
        if (lab[own[f]] < 0) out[own[f]] = max(out[own[f]], lab[nei[f]]);
        if (lab[nei[f]] < 0) out[nei[f]] = max(out[nei[f]], lab[own[f]]);
    }
    forAll(coupled, i)
    {
        const label c = own[nInt + i];
        if (coupled[i] && lab[c] < 0) out[c] = max(out[c], nbr[i]);
    }
    return out;
}


Foam::scalar Foam::bodyColours::nextWait
(
    const labelList& near,
    const label nB
) const
{
    if (nB < 2) return maxWait;
    if (periodic_) return maxTravel;
    const vectorField& C = mixture_.rho().mesh().C().primitiveField();
    List<vector> lo(nB, vector::uniform(GREAT));
    List<vector> hi(nB, vector::uniform(-GREAT));
    forAll(near, c)
    {
        const label b = near[c];
        if (b < 0) continue;
        lo[b] = min(lo[b], C[c]);
        hi[b] = max(hi[b], C[c]);
    }
    Pstream::listCombineGather(lo, minEqOp<vector>());
    Pstream::listCombineScatter(lo);
    Pstream::listCombineGather(hi, maxEqOp<vector>());
    Pstream::listCombineScatter(hi);

    // The gap between two boxes of cell centres: the largest separation
    // along an axis (a lower bound of the near cells' distance, less a
    // cell for the cells' halves beyond their centres)
    scalar gap = GREAT;
    for (label p = 0; p < nB; ++p)
    {
        for (label q = p + 1; q < nB; ++q)
        {
            scalar g = 0;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                g = max(g, max(lo[q][d] - hi[p][d], lo[p][d] - hi[q][d]));
            }
            gap = min(gap, g);
        }
    }
    // Both bodies closing in: the gap, less a cell and the three cells at
    // which a search must still see them apart, halved
    return max(maxTravel, min(maxWait, 0.5*(gap/h_ - 4)));
}


Foam::scalar Foam::bodyColours::correct(const labelList& phases)
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const label nInt = mesh.nInternalFaces();
    const boolList coupled(bodyRegions::coupledFaces(mesh));
    PtrList<volScalarField>& alphas = mixture_.alphasRef();
    const label nc = phases.size();
    label nMoved = 0, nCrowded = 0;

    // Per colour: each cell's body (edge included), and the body's near
    // cells (fraction above edgeFraction, grown by one layer)
    List<labelList> body(nc), near(nc);
    List<scalarList> volume(nc);
    // Bodies smaller than a few cells are not kept apart: a shred torn
    // off a body (seen: a cell of fraction 0.9 split from a disk pressed
    // on a wall, then decaying) would be counted as a second body of its
    // colour, and the disk moved away from it, its shred left behind
    const scalar minVolume = regions_.minBodyVolume();
    labelList nBodies(nc, 0);
    forAll(phases, k)
    {
        const scalarField& a = alphas[phases[k]].primitiveField();
        if (gMax(a) <= 0)
        {
            // A spare colour: no body, no search
            body[k].setSize(a.size(), -1);
            near[k] = body[k];
            continue;
        }
        regions_.find(a);
        body[k] = regions_.cellBody();
        nBodies[k] = regions_.size();
        volume[k] = regions_.volume();
        labelList edge(body[k]);
        forAll(edge, c)
        {
            if (a[c] <= edgeFraction) edge[c] = -1;
        }
        near[k] = grow(edge);
    }
    scalar wait = maxWait;
    forAll(phases, k)
    {
        wait = min(wait, nextWait(near[k], nBodies[k]));
    }

    // Which cells are near a body of each colour, kept up to date as
    // bodies move
    List<boolList> taken(nc);
    forAll(taken, k)
    {
        taken[k].setSize(near[k].size());
        forAll(near[k], c) taken[k][c] = near[k][c] >= 0;
    }

    for (label k = 0; k < nc; ++k)
    {
        const label nB = nBodies[k];
        if (nB < 2) continue;

        // Bodies of colour k whose near cells touch: a face between two
        // cells near different bodies
        const labelList& nk = near[k];
        labelList nbr;
        syncTools::swapBoundaryCellList(mesh, nk, nbr);
        labelList closeTo(nB, -1);
        auto pairUp = [&](const label p, const label q)
        {
            if
            (
                p >= 0 && q >= 0 && p != q
             && volume[k][p] >= minVolume && volume[k][q] >= minVolume
            )
            {
                const label hi = max(p, q), lo = min(p, q);
                closeTo[hi] = max(closeTo[hi], lo);
            }
        };
        for (label f = 0; f < nInt; ++f)
        {
            pairUp(nk[own[f]], nk[nei[f]]);
        }
        forAll(coupled, i)
        {
            if (coupled[i]) pairUp(nk[own[nInt + i]], nbr[i]);
        }
        Pstream::listCombineGather(closeTo, maxEqOp<label>());
        Pstream::listCombineScatter(closeTo);

        // The body of the larger label moves (once); its near cells'
        // overlap with every other colour's decides where to
        boolList moved(nB, false);
        for (label b = 0; b < nB; ++b)
        {
            if (closeTo[b] < 0 || moved[closeTo[b]]) continue;

            scalarList crowd(nc, scalar(0));
            forAll(nk, c)
            {
                if (nk[c] != b) continue;
                forAll(taken, j)
                {
                    if (j != k && taken[j][c]) crowd[j] += 1;
                }
            }
            bodyRegions::sumLists(crowd);
            label to = -1;
            forAll(crowd, j)
            {
                if (j != k && (to < 0 || crowd[j] < crowd[to])) to = j;
            }
            nCrowded += crowd[to] > 0;

            // Move the body, edge and all; its near cells now count as
            // colour to's
            volScalarField& from = alphas[phases[k]];
            volScalarField& into = alphas[phases[to]];
            scalarField& af = from.primitiveFieldRef();
            scalarField& ai = into.primitiveFieldRef();
            forAll(af, c)
            {
                if (body[k][c] == b)
                {
                    ai[c] += af[c];
                    af[c] = 0;
                }
                if (nk[c] == b) taken[to][c] = true;
            }
            from.correctBoundaryConditions();
            into.correctBoundaryConditions();
            moved[b] = true;
            ++nMoved;
        }
    }

    if (nMoved)
    {
        wait = maxTravel;
        Info<< "Body colours: " << nMoved << " bodies of "
            << mixture_.phases()[phases[0]].material
            << " moved to another colour";
        if (nCrowded)
        {
            Info<< " (" << nCrowded << " with no colour free near them)";
        }
        Info<< endl;
    }
    if (nCrowded && !warned_)
    {
        WarningInFunction
            << "Body colours: bodies of "
            << mixture_.phases()[phases[0]].material << " near bodies of"
            << " all its " << nc << " colours; bodies of one colour may"
            << " come near enough to merge.  More colours (the material's"
            << " entry colours) prevent it" << endl;
        warned_ = true;
    }
    return wait;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bodyColours::correct(const scalar CoNum)
{
    // How far the fastest material point moved this step, in cells: the
    // flow Courant number of the step (CourantNo.H's)
    const fvMesh& mesh = mixture_.rho().mesh();
    travelled_ += CoNum;
    if (travelled_ < wait_ && !mesh.changing())
    {
        return;
    }
    travelled_ = 0;
    if (h_ == 0 || mesh.changing())
    {
        h_ = gMax(mag(mesh.delta())().primitiveField());
    }

    wait_ = maxWait;
    for (const labelList& g : materials_)
    {
        wait_ = min(wait_, correct(g));
    }
}


// ************************************************************************* //
