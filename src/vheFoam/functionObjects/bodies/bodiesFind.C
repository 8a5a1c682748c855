/*---------------------------------------------------------------------------*\
  vheFoam: per-body output function object
  the bodies of one material and their moments
\*---------------------------------------------------------------------------*/

#include "bodies.H"
#include "volFields.H"
#include "bodyRegions.H"
#include "vhe.h"
#include "vheFlat.H"

void Foam::functionObjects::bodies::findBodies
(
    const volScalarField& alpha,
    const label m,
    const label colour,
    DynamicList<body>& found,
    DynamicList<List<point>>& surface
)
{
    const scalarField& a = alpha.primitiveField();
    regions_.find(a);
    const label nB = regions_.size();
    const labelList& lab = regions_.cellBody();
    const scalarField& V = mesh_.V();
    const vectorField& U = lookupObject<volVectorField>("U").primitiveField();

    // Velocity
    List<vector> P(nB, Zero);
    forAll(lab, c)
    {
        if (lab[c] >= 0) P[lab[c]] += a[c]*V[c]*U[c];
    }
    bodyRegions::sumLists(P);

    const label base = found.size();
    for (label b = 0; b < nB; ++b)
    {
        body bd;
        bd.id = -1;
        bd.material = m;
        bd.colour = colour;
        bd.volume = regions_.volume()[b];
        bd.centroid = regions_.centroid()[b];
        bd.U = P[b]/max(bd.volume, VSMALL);
        bd.omega = Zero;
        bd.D = 0;
        bd.axis = Zero;
        bd.maxDevB = 0;
        bd.gap = -1;
        found.append(bd);
    }

    // Second moments (bodyRegions, volume weighted: about the centroid),
    // angular momentum, |dev B|
    scalarList Vb;
    List<vector> Xb;
    vectorField r;
    List<symmTensor> J;
    regions_.moments(lab, regions_.centroid(), a*V, Vb, Xb, r, J);
    List<vector> L(nB, Zero);
    scalarList devMax(nB, Zero);
    scalarField devB(a.size(), Zero);
    if (foundObject<volSymmTensorField>("Bstar"))
    {
        const volScalarField& phis = lookupObject<volScalarField>("phis");
        vhe_devb_mag
        (
            a.size(), phis.primitiveField().cdata(),
            flat(lookupObject<volSymmTensorField>("Bstar").primitiveField()),
            regions_.threshold(), devB.data()
        );
    }
    forAll(lab, c)
    {
        const label b = lab[c];
        if (b < 0) continue;
        const body& bd = found[base + b];
        L[b] += a[c]*V[c]*(r[c] ^ (U[c] - bd.U));
        if (a[c] > regions_.threshold()) devMax[b] = max(devMax[b], devB[c]);
    }
    bodyRegions::sumLists(L);
    Pstream::listCombineGather(devMax, maxEqOp<scalar>());
    Pstream::listCombineScatter(devMax);

    for (label b = 0; b < nB; ++b)
    {
        body& bd = found[base + b];
        vhe_body_omega
        (
            J[b].cdata(), L[b].cdata(), regions_.normal(), bd.omega.data()
        );
        bd.D = vhe_body_shape(J[b].cdata(), regions_.normal(), bd.axis.data());
        bd.maxDevB = devMax[b];
    }

    // Surface points, on the master
    List<List<point>> pts(regions_.surface(a));
    for (label b = 0; b < nB; ++b)
    {
        surface.append(List<point>());
        surface.last().transfer(pts[b]);
    }
}


// ************************************************************************* //
