/*---------------------------------------------------------------------------*\
  vheFoam: the colours of one material that meet no other, carried as
  shares of their sum's flux
\*---------------------------------------------------------------------------*/

#include "colourShares.H"
#include "fvc.H"
#include "upwind.H"
#include "calculatedFvPatchFields.H"
#include "profiling.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// Two colours meet where max alpha_k times max alpha_l over a face's two
// cells exceeds this; below it their mutual compression (proportional to
// the product of their face values) is below 1e-10 of the flux
const scalar meetTol = 1e-10;

// A patch's neighbour-cell values: the other side of a coupled patch, the
// patch values elsewhere
tmp<scalarField> neighbourValues(const fvPatchScalarField& pf)
{
    return pf.coupled() ? pf.patchNeighbourField() : tmp<scalarField>(pf);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

Foam::labelList Foam::colourShares::meeting
(
    const UPtrList<volScalarField>& colours
)
{
    const fvMesh& mesh = colours[0].mesh();
    const label K = colours.size();
    const label nInt = mesh.nInternalFaces();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    addProfiling(meets, "colourShares::meet");

    // Each colour's values across each coupled patch, once
    List<PtrList<scalarField>> across(K);
    for (label k = 0; k < K; ++k)
    {
        across[k].setSize(mesh.boundary().size());
        forAll(mesh.boundary(), patchi)
        {
            if (!mesh.boundary()[patchi].coupled()) continue;
            across[k].set
            (
                patchi,
                neighbourValues(colours[k].boundaryField()[patchi]).ptr()
            );
        }
    }

    labelList meet(K*K, Zero);
    for (label k = 0; k < K; ++k)
    {
        const scalarField& a = colours[k].primitiveField();
        for (label l = k + 1; l < K; ++l)
        {
            const scalarField& b = colours[l].primitiveField();
            label m = vhe_share_meet
            (
                nInt, own.cdata(), nei.cdata(), a.cdata(), b.cdata(),
                nullptr, nullptr, meetTol
            );
            forAll(mesh.boundary(), patchi)
            {
                if (m || !across[k].set(patchi)) continue;
                const labelUList& fc = mesh.boundary()[patchi].faceCells();
                m = vhe_share_meet
                (
                    fc.size(), fc.cdata(), nullptr, a.cdata(), b.cdata(),
                    across[k][patchi].cdata(), across[l][patchi].cdata(),
                    meetTol
                );
            }
            meet[k*K + l] = m;
        }
    }
    Pstream::listCombineGather(meet, maxEqOp<label>());
    Pstream::listCombineScatter(meet);
    for (label k = 0; k < K; ++k)
    {
        for (label l = 0; l < k; ++l)
        {
            meet[k*K + l] = meet[l*K + k];
        }
    }
    return meet;
}


void Foam::colourShares::transport
(
    UPtrList<volScalarField>& colours,
    const surfaceScalarField& F,
    scalar deltaT
)
{
    const fvMesh& mesh = F.mesh();
    const label K = colours.size();
    const label nInt = mesh.nInternalFaces();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    addProfiling(shares, "colourShares::split");

    // What each cell gives: its composition, or where the step's outflow
    // exceeds its content, content and inflow mixed (two passes: the
    // inflow's own composition from the first)
    PtrList<volScalarField> s(K);
    List<const scalar*> a(K), sc(K), sn(K);
    List<scalar*> sp(K), ip(K);
    for (label k = 0; k < K; ++k)
    {
        s.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    "share", mesh.time().timeName(), mesh,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                mesh,
                dimensionedScalar(dimless, Zero),
                calculatedFvPatchScalarField::typeName
            )
        );
        a[k] = colours[k].oldTime().primitiveField().cdata();
        sp[k] = s[k].primitiveFieldRef().data();
    }
    vhe_share_cells(mesh.nCells(), K, a.cdata(), sp.cdata());
    forAll(mesh.boundary(), patchi)
    {
        if (mesh.boundary()[patchi].coupled()) continue;
        List<const scalar*> ab(K);
        List<scalar*> sb(K);
        for (label k = 0; k < K; ++k)
        {
            ab[k] = colours[k].oldTime().boundaryField()[patchi].cdata();
            sb[k] = s[k].boundaryFieldRef()[patchi].data();
        }
        vhe_share_cells
        (
            mesh.boundary()[patchi].size(), K, ab.cdata(), sb.cdata()
        );
    }

    const scalarField& Fi = F.primitiveField();
    scalarField out(mesh.nCells(), Zero), in(mesh.nCells(), Zero);
    vhe_share_flows
    (
        nInt, own.cdata(), nei.cdata(), Fi.cdata(), out.data(), in.data()
    );
    forAll(mesh.boundary(), patchi)
    {
        const labelUList& fc = mesh.boundary()[patchi].faceCells();
        vhe_share_flows
        (
            fc.size(), fc.cdata(), nullptr, F.boundaryField()[patchi].cdata(),
            out.data(), in.data()
        );
    }
    for (label pass = 0; pass < 2; ++pass)
    {
        PtrList<scalarField> inK(K);
        for (label k = 0; k < K; ++k)
        {
            s[k].correctBoundaryConditions();
            inK.set(k, new scalarField(mesh.nCells(), Zero));
            sc[k] = s[k].primitiveField().cdata();
            ip[k] = inK[k].data();
        }
        vhe_share_inflow
        (
            nInt, own.cdata(), nei.cdata(), Fi.cdata(), K, sc.cdata(),
            nullptr, ip.cdata()
        );
        forAll(mesh.boundary(), patchi)
        {
            const labelUList& fc = mesh.boundary()[patchi].faceCells();
            PtrList<scalarField> nb(K);
            for (label k = 0; k < K; ++k)
            {
                nb.set
                (
                    k,
                    neighbourValues(s[k].boundaryField()[patchi]).ptr()
                );
                sn[k] = nb[k].cdata();
            }
            vhe_share_inflow
            (
                fc.size(), fc.cdata(), nullptr,
                F.boundaryField()[patchi].cdata(), K, sc.cdata(), sn.cdata(),
                ip.cdata()
            );
        }
        vhe_share_mix
        (
            mesh.nCells(), K, a.cdata(), mesh.V().cdata(), deltaT,
            out.cdata(), in.cdata(), ip.cdata(),
            sp.cdata()
        );
    }
    for (label k = 0; k < K; ++k)
    {
        s[k].correctBoundaryConditions();
    }

    // The split: each colour's share of the flux from the upwind cell
    PtrList<surfaceScalarField> Fk(K);
    {
        const upwind<scalar> up(mesh, F);
        PtrList<surfaceScalarField> sUp(K);
        List<const scalar*> u(K);
        List<scalar*> o(K);
        for (label k = 0; k < K; ++k)
        {
            sUp.set(k, up.interpolate(s[k]).ptr());
            Fk.set
            (
                k,
                new surfaceScalarField("alphaPhi." + colours[k].name(), F)
            );
            u[k] = sUp[k].primitiveField().cdata();
            o[k] = Fk[k].primitiveFieldRef().data();
        }
        vhe_share_split(nInt, K, Fi.cdata(), u.cdata(), o.cdata());
        forAll(mesh.boundary(), patchi)
        {
            for (label k = 0; k < K; ++k)
            {
                u[k] = sUp[k].boundaryField()[patchi].cdata();
                o[k] = Fk[k].boundaryFieldRef()[patchi].data();
            }
            vhe_share_split
            (
                F.boundaryField()[patchi].size(), K,
                F.boundaryField()[patchi].cdata(), u.cdata(), o.cdata()
            );
        }
    }

    // The colours' update from their old values
    for (label k = 0; k < K; ++k)
    {
        colours[k].primitiveFieldRef() =
            colours[k].oldTime().primitiveField()
          - deltaT*fvc::surfaceIntegrate(Fk[k])().primitiveField();
        colours[k].correctBoundaryConditions();
    }
}


// ************************************************************************* //
