/*---------------------------------------------------------------------------*\
  vheFoam: the bodies of one material's phase fraction
\*---------------------------------------------------------------------------*/

#include "bodyRegions.H"
#include "volFields.H"
#include "regionSplit.H"
#include "syncTools.H"
#include "coupledPolyPatch.H"
#include "mathematicalConstants.H"

namespace
{
    //- Appends the other processor's list
    struct appendEqOp
    {
        void operator()
        (
            Foam::List<Foam::point>& x,
            const Foam::List<Foam::point>& y
        ) const
        {
            x.append(y);
        }
    };
}


Foam::boolList Foam::bodyRegions::coupledFaces(const fvMesh& mesh)
{
    Foam::boolList coupled(mesh.nBoundaryFaces(), false);
    for (const Foam::polyPatch& pp : mesh.boundaryMesh())
    {
        if (pp.coupled())
        {
            Foam::SubList<bool>
            (
                coupled, pp.size(), pp.start() - mesh.nInternalFaces()
            ) = true;
        }
    }
    return coupled;
}


Foam::scalar Foam::bodyRegions::minBodyVolume() const
{
    return minBodyCells*gSum(mesh_.V().field())
       /returnReduce(mesh_.nCells(), sumOp<label>());
}


Foam::bodyRegions::bodyRegions(const fvMesh& mesh, const scalar threshold)
:
    mesh_(mesh),
    threshold_(threshold),
    period_(Zero),
    normal_(-1)
{
    // Translational cyclics: the period along each direction
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<coupledPolyPatch>(pp))
        {
            const coupledPolyPatch& cpp = refCast<const coupledPolyPatch>(pp);
            if (cpp.separated() && cpp.separation().size())
            {
                period_ = max(period_, cmptMag(cpp.separation()[0]));
            }
        }
    }
    reduce(period_, maxOp<vector>());

    if (mesh_.nGeometricD() == 2)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh_.geometricD()[d] == -1) normal_ = d;
        }
    }
}


void Foam::bodyRegions::moments
(
    const labelList& body,
    const List<vector>& X0,
    const scalarField& m,
    scalarList& M,
    List<vector>& X,
    vectorField& r,
    List<symmTensor>& J
) const
{
    const vectorField& C = mesh_.C().primitiveField();
    const label nB = X0.size();
    M = scalarList(nB, Zero);
    List<vector> Mx(nB, Zero);
    forAll(body, c)
    {
        const label b = body[c];
        if (b < 0) continue;
        M[b] += m[c];
        Mx[b] += m[c]*nearestImage(C[c] - X0[b]);
    }
    sumLists(M);
    sumLists(Mx);
    X.setSize(nB);
    forAll(X, b) X[b] = X0[b] + Mx[b]/max(M[b], VSMALL);

    r.setSize(body.size());
    r = Zero;
    forAll(body, c)
    {
        const label b = body[c];
        if (b >= 0) r[c] = nearestImage(C[c] - X[b]);
    }
    scalarList S0;
    sums(body, nB, m, r, S0, J);
}


void Foam::bodyRegions::sums
(
    const labelList& body,
    const label nBodies,
    const scalarField& m,
    const vectorField& r,
    scalarList& S0,
    List<symmTensor>& S2
)
{
    S0 = scalarList(nBodies, Zero);
    S2 = List<symmTensor>(nBodies, Zero);
    forAll(body, c)
    {
        const label b = body[c];
        if (b < 0) continue;
        S0[b] += m[c];
        S2[b] += m[c]*sqr(r[c]);
    }
    sumLists(S0);
    sumLists(S2);
}


Foam::vector Foam::bodyRegions::nearestImage(const vector& d) const
{
    vector r(d);
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (period_[i] > 0)
        {
            r[i] -= period_[i]*std::floor(r[i]/period_[i] + 0.5);
        }
    }
    return r;
}


void Foam::bodyRegions::find(const scalarField& a)
{
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const label nInt = mesh_.nInternalFaces();
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();
    const boolList coupled(coupledFaces(mesh_));

    scalarField aNbr;
    syncTools::swapBoundaryCellList(mesh_, a, aNbr);

    // Regions of the cells above threshold, cut off from the rest
    boolList blocked(mesh_.nFaces(), false);
    for (label f = 0; f < nInt; ++f)
    {
        blocked[f] = (a[own[f]] > threshold_) != (a[nei[f]] > threshold_);
    }
    forAll(coupled, i)
    {
        const label f = nInt + i;
        blocked[f] =
            coupled[i] && (a[own[f]] > threshold_) != (aNbr[i] > threshold_);
    }
    const regionSplit regions(mesh_, blocked);

    // Regions that are bodies, numbered 0.. in region order
    labelList bodyOf(regions.nRegions(), 0);
    forAll(a, c)
    {
        if (a[c] > threshold_) bodyOf[regions[c]] = 1;
    }
    Pstream::listCombineGather(bodyOf, maxEqOp<label>());
    Pstream::listCombineScatter(bodyOf);
    label nB = 0;
    forAll(bodyOf, r)
    {
        bodyOf[r] = bodyOf[r] ? nB++ : -1;
    }

    // Each cell's body: the core cells', then the cells of smaller
    // fraction layer by layer, each to the body of its neighbour with the
    // larger fraction, until no cell of nonzero fraction touches a body
    // (up to 64 layers): the thin tails that a shear flow draws out of a
    // body belong to it, for its volume and for a move to another colour
    // (with 8 layers, 6e-5 of a disk's volume in shear was left out)
    cellBody_.setSize(a.size());
    cellBody_ = -1;
    forAll(a, c)
    {
        if (a[c] > threshold_) cellBody_[c] = bodyOf[regions[c]];
    }
    // Layer by layer from the cells labelled in the previous one (the
    // front): a cell of the next layer has all its labelled neighbours in
    // the front, so only the front's neighbours are looked at (a pass
    // over the whole mesh per layer was 2 % of scene B's run).  Each
    // candidate takes the label of its neighbour of largest fraction, the
    // first in face order on a tie
    labelList& lab = cellBody_;
    const cellList& cells = mesh_.cells();
    DynamicList<label> front;
    forAll(lab, c)
    {
        if (lab[c] >= 0) front.append(c);
    }
    labelList seen(a.size(), -1);
    DynamicList<label> next, nextLab;
    labelList fs;
    for (label layer = 0; nB && layer < 64; ++layer)
    {
        labelList labNbr;
        syncTools::swapBoundaryCellList(mesh_, lab, labNbr);
        next.clear();
        const auto candidate = [&](label c)
        {
            if (lab[c] < 0 && a[c] > 0 && seen[c] != layer)
            {
                seen[c] = layer;
                next.append(c);
            }
        };
        for (const label c : front)
        {
            for (const label f : cells[c])
            {
                if (f < nInt) candidate(own[f] == c ? nei[f] : own[f]);
            }
        }
        forAll(coupled, i)
        {
            if (coupled[i] && labNbr[i] >= 0) candidate(own[nInt + i]);
        }
        nextLab.setSize(next.size());
        forAll(next, k)
        {
            const label c = next[k];
            fs = cells[c];
            Foam::sort(fs);
            scalar best = -1;
            label l = -1;
            for (const label f : fs)
            {
                label ln = -1;
                scalar an = 0;
                if (f < nInt)
                {
                    const label o = own[f] == c ? nei[f] : own[f];
                    ln = lab[o];
                    an = a[o];
                }
                else if (coupled[f - nInt])
                {
                    ln = labNbr[f - nInt];
                    an = aNbr[f - nInt];
                }
                if (ln >= 0 && an > best)
                {
                    best = an;
                    l = ln;
                }
            }
            nextLab[k] = l;
        }
        forAll(next, k) lab[next[k]] = nextLab[k];
        if (returnReduce(next.size(), sumOp<label>()) == 0) break;
        front.transfer(next);
    }

    // Volume and a reference point: the circular mean along periodic
    // directions, so that a body split by a cyclic is one body
    const boundBox& bb = mesh_.bounds();
    const scalar twoPi = constant::mathematical::twoPi;
    volume_.setSize(nB);
    volume_ = Zero;
    List<vector> X(nB, Zero), Cs(nB, Zero), Sn(nB, Zero);
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b < 0) continue;
        const scalar w = a[c]*V[c];
        volume_[b] += w;
        X[b] += w*C[c];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                const scalar th = twoPi*(C[c][d] - bb.min()[d])/period_[d];
                Cs[b][d] += w*std::cos(th);
                Sn[b][d] += w*std::sin(th);
            }
        }
    }
    sumLists(volume_);
    sumLists(X);
    sumLists(Cs);
    sumLists(Sn);
    List<vector> ref(nB);
    forAll(ref, b)
    {
        ref[b] = X[b]/max(volume_[b], VSMALL);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                ref[b][d] = bb.min()[d]
                  + std::atan2(Sn[b][d], Cs[b][d])/twoPi*period_[d];
            }
        }
    }

    // The centroid, relative to the reference, wrapped into the domain
    List<vector> R(nB, Zero);
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b >= 0) R[b] += a[c]*V[c]*nearestImage(C[c] - ref[b]);
    }
    sumLists(R);
    centroid_.setSize(nB);
    forAll(centroid_, b)
    {
        vector& x = centroid_[b];
        x = ref[b] + R[b]/max(volume_[b], VSMALL);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                const scalar s = (x[d] - bb.min()[d])/period_[d];
                x[d] = bb.min()[d] + period_[d]*(s - std::floor(s));
            }
        }
    }
}


Foam::List<Foam::List<Foam::point>> Foam::bodyRegions::surface
(
    const scalarField& a
) const
{
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const label nInt = mesh_.nInternalFaces();
    const vectorField& C = mesh_.C().primitiveField();
    const boolList coupled(coupledFaces(mesh_));

    // The other side's fraction and centre across coupled faces (a
    // cyclic's neighbour centre transformed to this side)
    scalarField aNbr;
    syncTools::swapBoundaryCellList(mesh_, a, aNbr);
    pointField CNbr;
    syncTools::swapBoundaryCellPositions(mesh_, C, CNbr);

    List<DynamicList<point>> pts(size());
    auto crossing = [&](label c, const point& xn, scalar an)
    {
        const scalar t = (a[c] - threshold_)/(a[c] - an);
        pts[cellBody_[c]].append(C[c] + t*(xn - C[c]));
    };
    for (label f = 0; f < nInt; ++f)
    {
        const bool o = a[own[f]] > threshold_, n = a[nei[f]] > threshold_;
        if (o && !n) crossing(own[f], C[nei[f]], a[nei[f]]);
        if (n && !o) crossing(nei[f], C[own[f]], a[own[f]]);
    }
    forAll(coupled, i)
    {
        const label c = own[nInt + i];
        if (coupled[i] && a[c] > threshold_ && !(aNbr[i] > threshold_))
        {
            crossing(c, CNbr[i], aNbr[i]);
        }
    }
    List<List<point>> bodyPts(size());
    forAll(pts, b)
    {
        bodyPts[b].transfer(pts[b]);
    }
    Pstream::listCombineGather(bodyPts, appendEqOp());
    return bodyPts;
}


// ************************************************************************* //
