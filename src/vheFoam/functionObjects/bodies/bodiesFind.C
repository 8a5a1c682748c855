/*---------------------------------------------------------------------------*\
  vheFoam: per-body output function object
  the bodies of one material: regions, their diffuse edges, their moments
\*---------------------------------------------------------------------------*/

#include "bodies.H"
#include "volFields.H"
#include "regionSplit.H"
#include "syncTools.H"
#include "ListOps.H"
#include "mathematicalConstants.H"
#include "vhe.h"
#include "vheFlat.H"

namespace
{
    template<class T>
    void sumLists(Foam::List<T>& l)
    {
        Foam::Pstream::listCombineGather(l, Foam::plusEqOp<T>());
        Foam::Pstream::listCombineScatter(l);
    }

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


void Foam::functionObjects::bodies::findBodies
(
    const volScalarField& alpha,
    const label m,
    DynamicList<body>& found,
    DynamicList<List<point>>& surface
) const
{
    const scalarField& a = alpha.primitiveField();
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const label nInt = mesh_.nInternalFaces();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const vectorField& C = mesh_.C().primitiveField();
    const scalarField& V = mesh_.V();

    // The other side's fraction and centre across coupled faces
    scalarField aNbr;
    syncTools::swapBoundaryCellList(mesh_, a, aNbr);
    pointField CNbr;
    syncTools::swapBoundaryCellPositions(mesh_, C, CNbr);
    boolList coupledFace(mesh_.nBoundaryFaces(), false);
    for (const polyPatch& pp : patches)
    {
        if (pp.coupled())
        {
            SubList<bool>(coupledFace, pp.size(), pp.start() - nInt) = true;
        }
    }

    // Regions of the cells above threshold, cut off from the rest
    boolList blocked(mesh_.nFaces(), false);
    for (label f = 0; f < nInt; ++f)
    {
        blocked[f] = (a[own[f]] > threshold_) != (a[nei[f]] > threshold_);
    }
    forAll(coupledFace, i)
    {
        const label f = nInt + i;
        blocked[f] =
            coupledFace[i]
         && (a[own[f]] > threshold_) != (aNbr[i] > threshold_);
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
    if (nB == 0) return;

    // Each cell's body: the core cells', then the cells of smaller
    // fraction layer by layer, each to the body of its neighbour with the
    // larger fraction
    labelList lab(a.size(), -1);
    forAll(a, c)
    {
        if (a[c] > threshold_) lab[c] = bodyOf[regions[c]];
    }
    for (label layer = 0; layer < 8; ++layer)
    {
        labelList labNbr;
        syncTools::swapBoundaryCellList(mesh_, lab, labNbr);
        labelList next(lab);
        scalarField best(a.size(), -1);
        auto offer = [&](label c, label l, scalar an)
        {
            if (lab[c] < 0 && a[c] > 0 && l >= 0 && an > best[c])
            {
                best[c] = an;
                next[c] = l;
            }
        };
        for (label f = 0; f < nInt; ++f)
        {
            offer(own[f], lab[nei[f]], a[nei[f]]);
            offer(nei[f], lab[own[f]], a[own[f]]);
        }
        forAll(coupledFace, i)
        {
            if (coupledFace[i]) offer(own[nInt + i], labNbr[i], aNbr[i]);
        }
        label changed = 0;
        forAll(lab, c)
        {
            if (next[c] != lab[c]) ++changed;
        }
        lab.transfer(next);
        if (returnReduce(changed, sumOp<label>()) == 0) break;
    }

    // Volume and a reference point: the circular mean along periodic
    // directions, so that a body split by a cyclic is one body
    const boundBox& bb = mesh_.bounds();
    const scalar twoPi = constant::mathematical::twoPi;
    scalarList W(nB, Zero);
    List<vector> X(nB, Zero), Cs(nB, Zero), Sn(nB, Zero);
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b < 0) continue;
        const scalar w = a[c]*V[c];
        W[b] += w;
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
    sumLists(W);
    sumLists(X);
    sumLists(Cs);
    sumLists(Sn);
    List<vector> ref(nB);
    forAll(ref, b)
    {
        ref[b] = X[b]/max(W[b], VSMALL);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                ref[b][d] = bb.min()[d]
                  + std::atan2(Sn[b][d], Cs[b][d])/twoPi*period_[d];
            }
        }
    }

    // Centroid and velocity
    const vectorField& U = lookupObject<volVectorField>("U").primitiveField();
    List<vector> R(nB, Zero), P(nB, Zero);
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b < 0) continue;
        const scalar w = a[c]*V[c];
        R[b] += w*nearestImage(C[c] - ref[b]);
        P[b] += w*U[c];
    }
    sumLists(R);
    sumLists(P);

    const label base = found.size();
    for (label b = 0; b < nB; ++b)
    {
        body bd;
        bd.id = -1;
        bd.material = m;
        bd.colour = 0;
        bd.volume = W[b];
        bd.centroid = ref[b] + R[b]/max(W[b], VSMALL);
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (period_[d] > 0)
            {
                bd.centroid[d] = bb.min()[d] + period_[d]*
                (
                    (bd.centroid[d] - bb.min()[d])/period_[d]
                  - std::floor((bd.centroid[d] - bb.min()[d])/period_[d])
                );
            }
        }
        bd.U = P[b]/max(W[b], VSMALL);
        bd.gap = -1;
        found.append(bd);
    }

    // Second moments, angular momentum, |dev B|
    List<symmTensor> J(nB, Zero);
    List<vector> L(nB, Zero);
    scalarList devMax(nB, Zero);
    scalarField devB(a.size(), 0);
    if (foundObject<volSymmTensorField>("Bstar"))
    {
        const volScalarField& phis = lookupObject<volScalarField>("phis");
        vhe_devb_mag
        (
            a.size(), phis.primitiveField().cdata(),
            flat(lookupObject<volSymmTensorField>("Bstar").primitiveField()),
            threshold_, devB.data()
        );
    }
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b < 0) continue;
        const body& bd = found[base + b];
        const scalar w = a[c]*V[c];
        const vector r(nearestImage(C[c] - bd.centroid));
        J[b] += w*sqr(r);
        L[b] += w*(r ^ (U[c] - bd.U));
        if (a[c] > threshold_) devMax[b] = max(devMax[b], devB[c]);
    }
    sumLists(J);
    sumLists(L);
    Pstream::listCombineGather(devMax, maxEqOp<scalar>());
    Pstream::listCombineScatter(devMax);

    // 2D: the empty direction
    label normal = -1;
    if (mesh_.nGeometricD() == 2)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (mesh_.geometricD()[d] == -1) normal = d;
        }
    }
    for (label b = 0; b < nB; ++b)
    {
        body& bd = found[base + b];
        vhe_body_omega(J[b].cdata(), L[b].cdata(), normal, bd.omega.data());
        bd.D = vhe_body_shape(J[b].cdata(), normal, bd.axis.data());
        bd.maxDevB = devMax[b];
    }

    // Surface points: where the fraction crosses threshold between two
    // cell centres, gathered on the master
    List<DynamicList<point>> pts(nB);
    auto crossing = [&](label c, const point& xn, scalar an)
    {
        const scalar t = (a[c] - threshold_)/(a[c] - an);
        pts[lab[c]].append(C[c] + t*(xn - C[c]));
    };
    for (label f = 0; f < nInt; ++f)
    {
        const bool o = a[own[f]] > threshold_, n = a[nei[f]] > threshold_;
        if (o && !n) crossing(own[f], C[nei[f]], a[nei[f]]);
        if (n && !o) crossing(nei[f], C[own[f]], a[own[f]]);
    }
    forAll(coupledFace, i)
    {
        const label c = own[nInt + i];
        if (coupledFace[i] && a[c] > threshold_ && !(aNbr[i] > threshold_))
        {
            crossing(c, CNbr[i], aNbr[i]);
        }
    }
    List<List<point>> bodyPts(nB);
    forAll(pts, b)
    {
        bodyPts[b].transfer(pts[b]);
    }
    Pstream::listCombineGather(bodyPts, appendEqOp());
    for (label b = 0; b < nB; ++b)
    {
        surface.append(List<point>());
        surface.last().transfer(bodyPts[b]);
    }
}


// ************************************************************************* //
