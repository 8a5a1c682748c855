/*---------------------------------------------------------------------------*\
  vheFoam: interface curvature from height functions
\*---------------------------------------------------------------------------*/

#include "heightFunction.H"
#include "fvc.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::heightFunction::build()
{
    const label nCells = mesh_.nCells();
    const label nInternal = mesh_.nInternalFaces();
    const vectorField& Sf = mesh_.faceAreas();
    const scalarField& V = mesh_.V();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    FixedList<label, 6> none;
    none = -1;
    nbCell_.setSize(nCells);
    nbCell_ = none;
    nbFace_.setSize(nCells);
    nbFace_ = none;
    scalarField regular(nCells, 1);
    delta_.setSize(nCells);
    delta_ = vector::zero;

    // The face's axis and the side of the owner it lies on
    auto axis = [&](const label facei, direction& d, int& s) -> bool
    {
        const vector n(Sf[facei]/mag(Sf[facei]));
        d = findMax(List<scalar>({mag(n.x()), mag(n.y()), mag(n.z())}));
        s = n[d] > 0 ? 1 : 0;
        return mag(n[d]) > 1 - 1e-6;
    };

    forAll(Sf, facei)
    {
        direction d;
        int s;
        const bool aligned = axis(facei, d, s);
        const label o = own[facei];
        if (!aligned)
        {
            regular[o] = 0;
            if (facei < nInternal) regular[nei[facei]] = 0;
            continue;
        }
        delta_[o][d] = V[o]/mag(Sf[facei]);
        if (facei < nInternal)
        {
            const label n = nei[facei];
            delta_[n][d] = V[n]/mag(Sf[facei]);
            // A second neighbour on one side: a refined cell's split face
            if (nbCell_[o][2*d + s] >= 0 || nbCell_[n][2*d + 1 - s] >= 0)
            {
                regular[o] = regular[n] = 0;
            }
            nbCell_[o][2*d + s] = n;
            nbCell_[n][2*d + 1 - s] = o;
            if (mag(V[o] - V[n]) > 1e-6*max(V[o], V[n]))
            {
                regular[o] = regular[n] = 0;
            }
        }
        else
        {
            const label patchi = mesh_.boundaryMesh().whichPatch(facei);
            if (mesh_.boundaryMesh()[patchi].coupled())
            {
                nbFace_[o][2*d + s] = facei - nInternal;
            }
        }
    }
    forAll(regular, celli)
    {
        if (mesh_.cells()[celli].size() != 6) regular[celli] = 0;
    }

    regular_.reset
    (
        new volScalarField
        (
            IOobject("heightFunctionRegular", mesh_.time().timeName(), mesh_,
                     IOobject::NO_READ, IOobject::NO_WRITE, false),
            mesh_,
            dimensionedScalar(dimless, Zero)
        )
    );
    regular_->primitiveFieldRef() = regular;
    regular_->correctBoundaryConditions();
    nCellsBuilt_ = nCells;
}


Foam::tmp<Foam::volScalarField> Foam::heightFunction::shift
(
    const volScalarField& f,
    const direction d,
    const int s,
    const scalar wallValue
) const
{
    // The values across coupled faces (processor, cyclic)
    scalarField across(mesh_.nBoundaryFaces(), Zero);
    forAll(f.boundaryField(), patchi)
    {
        const fvPatchScalarField& pf = f.boundaryField()[patchi];
        if (pf.coupled())
        {
            SubList<scalar>
            (
                across, pf.size(),
                mesh_.boundaryMesh()[patchi].start() - mesh_.nInternalFaces()
            ) = pf.patchNeighbourField();
        }
    }

    tmp<volScalarField> tg(new volScalarField(f.name() + "Shift", f));
    scalarField& g = tg.ref().primitiveFieldRef();
    const label side = 2*d + (s > 0 ? 1 : 0);
    forAll(g, celli)
    {
        const label n = nbCell_[celli][side];
        if (n >= 0)
        {
            g[celli] = f[n];
        }
        else if (nbFace_[celli][side] >= 0)
        {
            g[celli] = across[nbFace_[celli][side]];
        }
        else if (wallValue != GREAT)
        {
            g[celli] = wallValue;
        }
    }
    tg.ref().correctBoundaryConditions();
    return tg;
}


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

Foam::heightFunction::heightFunction(const fvMesh& mesh)
:
    mesh_(mesh),
    nCellsBuilt_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::heightFunction::curvature
(
    const volScalarField& alpha,
    volScalarField& K,
    volScalarField& valid
)
{
    if (nCellsBuilt_ != mesh_.nCells() || mesh_.topoChanging())
    {
        build();
    }
    const scalar eps = 1e-3;
    const Vector<label>& geomD = mesh_.geometricD();
    DynamicList<direction> dirs;
    for (direction d = 0; d < 3; ++d)
    {
        if (geomD[d] == 1) dirs.append(d);
    }

    // A field with alpha's boundary conditions but its own values
    volScalarField a("heightAlpha", alpha);

    // Per direction: the column's height [m] and orientation (+1: full
    // below, -1: full above, 0: invalid)
    PtrList<volScalarField> H(3), orient(3);
    for (const direction d : dirs)
    {
        volScalarField h("height", a*0);
        volScalarField reg("reg", *regular_);
        tmp<volScalarField> up(a), down(a);
        tmp<volScalarField> regUp(*regular_), regDown(*regular_);
        h.primitiveFieldRef() = a.primitiveField();
        for (int k = 1; k <= 3; ++k)
        {
            up = shift(up(), d, 1);
            down = shift(down(), d, -1);
            regUp = shift(regUp(), d, 1);
            regDown = shift(regDown(), d, -1);
            h.primitiveFieldRef() += up().primitiveField() + down().primitiveField();
            reg.primitiveFieldRef() *=
                regUp().primitiveField()*regDown().primitiveField();
        }
        volScalarField o("orient", reg*0);
        forAll(o, celli)
        {
            h[celli] *= delta_[celli][d];
            const scalar lo = down()[celli], hi = up()[celli];
            if (reg[celli] > 0.5)
            {
                if (lo > 1 - eps && hi < eps) o[celli] = 1;
                else if (lo < eps && hi > 1 - eps) o[celli] = -1;
            }
        }
        h.correctBoundaryConditions();
        o.correctBoundaryConditions();
        H.set(d, new volScalarField(h));
        orient.set(d, new volScalarField(o));
    }

    // Per direction: the curvature where the stencil's columns are valid
    PtrList<volScalarField> Kd(3), validd(3);
    for (const direction d : dirs)
    {
        DynamicList<direction> t;
        for (const direction e : dirs) if (e != d) t.append(e);

        volScalarField k("Kd", H[d]*0);
        volScalarField v("validd", orient[d]*0);
        const volScalarField& h0 = H[d];
        const volScalarField& o0 = orient[d];
        if (t.size() == 1)
        {
            const tmp<volScalarField> hp(shift(h0, t[0], 1)), hm(shift(h0, t[0], -1));
            const tmp<volScalarField> op(shift(o0, t[0], 1, 0)), om(shift(o0, t[0], -1, 0));
            forAll(k, c)
            {
                if (o0[c] != 0 && op()[c] == o0[c] && om()[c] == o0[c])
                {
                    const double h[9] =
                        {0, hm()[c], 0, 0, h0[c], 0, 0, hp()[c], 0};
                    const scalar dt = delta_[c][t[0]];
                    k[c] = vhe_height_curvature(h, dt, dt, 2);
                    v[c] = 1;
                }
            }
        }
        else
        {
            // The 3 x 3 columns: shifted along t0, then along t1
            PtrList<volScalarField> hs(9), os(9);
            for (int i = -1; i <= 1; ++i)
            {
                tmp<volScalarField> hi(h0), oi(o0);
                if (i != 0)
                {
                    hi = shift(h0, t[0], i);
                    oi = shift(o0, t[0], i, 0);
                }
                for (int j = -1; j <= 1; ++j)
                {
                    const label slot = 3*(i + 1) + (j + 1);
                    if (j == 0)
                    {
                        hs.set(slot, new volScalarField(hi()));
                        os.set(slot, new volScalarField(oi()));
                    }
                    else
                    {
                        hs.set(slot, shift(hi(), t[1], j).ptr());
                        os.set(slot, shift(oi(), t[1], j, 0).ptr());
                    }
                }
            }
            forAll(k, c)
            {
                bool ok = o0[c] != 0;
                for (label s = 0; s < 9 && ok; ++s) ok = os[s][c] == o0[c];
                if (!ok) continue;
                double h[9];
                for (label s = 0; s < 9; ++s) h[s] = hs[s][c];
                k[c] = vhe_height_curvature
                (
                    h, delta_[c][t[0]], delta_[c][t[1]], 3
                );
                v[c] = 1;
            }
        }
        Kd.set(d, new volScalarField(k));
        validd.set(d, new volScalarField(v));
    }

    // Each cell: the direction of grad(alpha)'s largest component first
    const volVectorField gradA(fvc::grad(alpha));
    K = dimensionedScalar(K.dimensions(), Zero);
    valid = dimensionedScalar(dimless, Zero);
    forAll(K, c)
    {
        List<scalar> g(3, scalar(-1));
        for (const direction d : dirs) g[d] = mag(gradA[c][d]);
        for (label n = 0; n < dirs.size(); ++n)
        {
            const label d = findMax(g);
            if (validd[d][c] > 0.5)
            {
                K[c] = Kd[d][c];
                valid[c] = 1;
                break;
            }
            g[d] = -1;
        }
    }
    K.correctBoundaryConditions();
    valid.correctBoundaryConditions();

    // A cell with no valid stencil of its own takes the mean curvature of
    // its face neighbours that have one (twice: up to two cells away), as
    // Basilisk's curvature.h averages its neighbours' heights' curvatures
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    for (int pass = 0; pass < 2; ++pass)
    {
        scalarField sumK(K.size(), Zero), sumW(K.size(), Zero);
        forAll(nei, facei)
        {
            const label o = own[facei], n = nei[facei];
            if (valid[n] > 0.5) { sumK[o] += K[n]; sumW[o] += 1; }
            if (valid[o] > 0.5) { sumK[n] += K[o]; sumW[n] += 1; }
        }
        forAll(K.boundaryField(), patchi)
        {
            const fvPatchScalarField& vp = valid.boundaryField()[patchi];
            if (!vp.coupled()) continue;
            const scalarField vn(vp.patchNeighbourField());
            const scalarField kn(K.boundaryField()[patchi].patchNeighbourField());
            const labelUList& fc = mesh_.boundary()[patchi].faceCells();
            forAll(fc, i)
            {
                if (vn[i] > 0.5) { sumK[fc[i]] += kn[i]; sumW[fc[i]] += 1; }
            }
        }
        forAll(K, c)
        {
            if (valid[c] < 0.5 && sumW[c] > 0)
            {
                K[c] = sumK[c]/sumW[c];
                valid[c] = 1;
            }
        }
        K.correctBoundaryConditions();
        valid.correctBoundaryConditions();
    }
}


// ************************************************************************* //
