/*---------------------------------------------------------------------------*\
  vheFoam: transport of the deformation B with the solid
\*---------------------------------------------------------------------------*/

#include "BTransport.H"
#include "vheElasticity.H"
#include "vheFlat.H"
#include "vhe.h"
#include <cfloat>

const Foam::scalar Foam::BTransport::phisGradient_ = 0.1;


Foam::BTransport::BTransport
(
    const vheMixture& mixture,
    const dictionary& pimple
)
:
    mixture_(mixture),
    mesh_(mixture.rho().mesh()),
    log_(true)
{
    const word scheme(pimple.getOrDefault<word>("BTransport", "log"));
    if (scheme != "log" && scheme != "donorCell")
    {
        FatalIOErrorInFunction(pimple)
            << "Unknown BTransport '" << scheme << "'" << nl
            << "    Valid: (log donorCell)" << exit(FatalIOError);
    }
    log_ = scheme == "log";
}


Foam::tmp<Foam::volSymmTensorField> Foam::BTransport::field
(
    const word& name
) const
{
    return tmp<volSymmTensorField>
    (
        new volSymmTensorField
        (
            IOobject(name, mesh_.time().timeName(), mesh_),
            mesh_,
            dimensionedSymmTensor(dimless, Zero),
            vheElasticity::patchTypes(mesh_)
        )
    );
}


void Foam::BTransport::advect
(
    volSymmTensorField& Bstar,
    const volVectorField& U,
    scalar deltaT
) const
{
    if (log_)
    {
        advectLog(Bstar, U, deltaT);
    }
    else
    {
        advectDonorB(Bstar, deltaT);
    }
}


void Foam::BTransport::donorSums
(
    const volSymmTensorField& X0,
    scalar deltaT,
    scalarField& out,
    scalarField& W,
    symmTensorField& S
) const
{
    const surfaceScalarField& aPhi = mixture_.alphaPhiSolid();
    const scalarField a(deltaT*aPhi.primitiveField());
    out = 0;
    W = 0;
    S = Zero;
    vhe_bdonor_internal
    (
        mesh_.nInternalFaces(), mesh_.owner().cdata(),
        mesh_.neighbour().cdata(), a.cdata(), flat(X0.primitiveField()),
        out.data(), W.data(), flat(S)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchSymmTensorField& Xp = X0.boundaryField()[patchi];
        if (Xp.empty()) continue;
        // Across a coupled patch the donor is the neighbour cell; at any
        // other boundary, the boundary value
        const symmTensorField Xnb
        (
            Xp.coupled() ? Xp.patchNeighbourField()() : symmTensorField(Xp)
        );
        const scalarField ap(deltaT*aPhi.boundaryField()[patchi]);
        vhe_bdonor_boundary
        (
            ap.size(), mesh_.boundary()[patchi].faceCells().cdata(),
            ap.cdata(), flat(Xnb), out.data(), W.data(), flat(S)
        );
    }
}


void Foam::BTransport::reportFlushed(size_t flushed) const
{
    const label nFlushed = returnReduce(label(flushed), sumOp<label>());
    if (nFlushed)
    {
        Info<< "B transport: " << nFlushed << " solid cells renewed"
            << " entirely in one step (reduce maxAlphaCo if this persists)"
            << endl;
    }
}


void Foam::BTransport::advectDonorB
(
    volSymmTensorField& Bstar,
    scalar deltaT
) const
{
    const volScalarField& phis = mixture_.phis();
    const volScalarField& phis0 = phis.oldTime();
    const scalar phisMin = mixture_.solidFractionMin();
    const label nCells = mesh_.nCells();

    // Old B of the solid; I where there is none
    tmp<volSymmTensorField> tB0(field("B"));
    volSymmTensorField& B0 = tB0.ref();
    vhe_b_from_bstar
    (
        nCells, phis0.primitiveField().cdata(),
        flat(Bstar.oldTime().primitiveField()), phisMin,
        flat(B0.primitiveFieldRef())
    );
    B0.correctBoundaryConditions();

    scalarField out(nCells), W(nCells);
    symmTensorField S(nCells);
    donorSums(B0, deltaT, out, W, S);
    reportFlushed
    (
        vhe_bdonor_finish
        (
            nCells, mesh_.V().cdata(), phis0.primitiveField().cdata(),
            phis.primitiveField().cdata(), flat(B0.primitiveField()),
            out.cdata(), W.cdata(), flat(S), phisMin,
            flat(Bstar.primitiveFieldRef())
        )
    );
}


void Foam::BTransport::advectLog
(
    volSymmTensorField& Bstar,
    const volVectorField& U,
    scalar deltaT
) const
{
    const volScalarField& phis = mixture_.phis();
    const volScalarField& phis0 = phis.oldTime();
    const scalar phisMin = mixture_.solidFractionMin();
    const label nCells = mesh_.nCells();
    const label nIntFaces = mesh_.nInternalFaces();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();

    // Psi = log B of the old step
    tmp<volSymmTensorField> tPsi0(field("logB"));
    volSymmTensorField& Psi0 = tPsi0.ref();
    {
        const size_t bad = vhe_logb_from_bstar
        (
            nCells, phis0.primitiveField().cdata(),
            flat(Bstar.oldTime().primitiveField()), phisMin,
            flat(Psi0.primitiveFieldRef())
        );
        const label nBad = returnReduce(label(bad), sumOp<label>());
        if (nBad)
        {
            WarningInFunction
                << nBad << " cells whose B* is not positive definite"
                << " (eigenvalues below " << DBL_MIN << " taken as it)"
                << endl;
        }
    }
    Psi0.correctBoundaryConditions();

    // Low order: donor-cell Psi and solid content m of every cell
    scalarField m(nCells);
    symmTensorField X(nCells);
    {
        scalarField out(nCells), W(nCells);
        symmTensorField S(nCells);
        donorSums(Psi0, deltaT, out, W, S);
        reportFlushed
        (
            vhe_donor_finish
            (
                nCells, mesh_.V().cdata(), phis0.primitiveField().cdata(),
                phis.primitiveField().cdata(), flat(Psi0.primitiveField()),
                out.cdata(), W.cdata(), flat(S), phisMin, m.data(), flat(X)
            )
        );
    }

    // Least-squares gradient of Psi0 between cells with solid
    tmp<surfaceVectorField> tdelta(mesh_.delta());
    const surfaceVectorField& delta = tdelta();
    scalarField G(18*nCells, 0);
    {
        symmTensorField M(nCells, Zero);
        scalarField b(18*nCells, 0);
        vhe_lsq_grad_internal
        (
            nIntFaces, own.cdata(), nei.cdata(), flat(delta.primitiveField()),
            phis0.primitiveField().cdata(), phisGradient_,
            flat(Psi0.primitiveField()), flat(M), b.data()
        );
        forAll(mesh_.boundary(), patchi)
        {
            const fvPatchSymmTensorField& Pp = Psi0.boundaryField()[patchi];
            if (!Pp.coupled() || Pp.empty()) continue;
            const symmTensorField Pnb(Pp.patchNeighbourField());
            const scalarField phisNb
            (
                phis0.boundaryField()[patchi].patchNeighbourField()
            );
            vhe_lsq_grad_boundary
            (
                Pp.size(), mesh_.boundary()[patchi].faceCells().cdata(),
                flat(delta.boundaryField()[patchi]),
                phis0.primitiveField().cdata(), phisNb.cdata(),
                phisGradient_, flat(Psi0.primitiveField()), flat(Pnb),
                flat(M), b.data()
            );
        }
        vhe_lsq_grad_finish(nCells, flat(M), b.cdata(), G.data());
    }

    // The gradient's three directions as fields, for coupled neighbours
    PtrList<volSymmTensorField> Gd(3);
    for (direction d = 0; d < 3; ++d)
    {
        Gd.set(d, field("gradLogB" + Foam::name(d)));
        symmTensorField& g = Gd[d].primitiveFieldRef();
        forAll(g, celli)
        {
            for (direction k = 0; k < 6; ++k)
            {
                g[celli][k] = G[18*celli + 6*d + k];
            }
        }
        Gd[d].correctBoundaryConditions();
    }

    // Antidiffusive fluxes, internal and coupled faces
    const surfaceScalarField& aPhi = mixture_.alphaPhiSolid();
    const scalarField a(deltaT*aPhi.primitiveField());
    symmTensorField A(nIntFaces, Zero);
    vhe_antidiffusive_internal
    (
        nIntFaces, own.cdata(), nei.cdata(), a.cdata(),
        flat(mesh_.Sf().primitiveField()), flat(delta.primitiveField()),
        flat(mesh_.Cf().primitiveField()), flat(mesh_.C().primitiveField()),
        flat(U.primitiveField()), phis0.primitiveField().cdata(),
        phisGradient_, flat(Psi0.primitiveField()), G.cdata(), deltaT,
        flat(A)
    );
    PtrList<symmTensorField> Ab(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        Ab.set(patchi, new symmTensorField(p.size(), Zero));
        if (!p.coupled() || !p.size()) continue;
        const scalarField ap(deltaT*aPhi.boundaryField()[patchi]);
        const vectorField Unb(U.boundaryField()[patchi].patchNeighbourField());
        const scalarField phisNb
        (
            phis0.boundaryField()[patchi].patchNeighbourField()
        );
        const symmTensorField Pnb
        (
            Psi0.boundaryField()[patchi].patchNeighbourField()
        );
        scalarField Gnb(18*p.size());
        for (direction d = 0; d < 3; ++d)
        {
            const symmTensorField g
            (
                Gd[d].boundaryField()[patchi].patchNeighbourField()
            );
            forAll(g, facei)
            {
                for (direction k = 0; k < 6; ++k)
                {
                    Gnb[18*facei + 6*d + k] = g[facei][k];
                }
            }
        }
        vhe_antidiffusive_boundary
        (
            p.size(), p.faceCells().cdata(), ap.cdata(),
            flat(mesh_.Sf().boundaryField()[patchi]),
            flat(delta.boundaryField()[patchi]),
            flat(mesh_.Cf().boundaryField()[patchi]),
            flat(mesh_.C().primitiveField()), flat(U.primitiveField()),
            phis0.primitiveField().cdata(), phisNb.cdata(), phisGradient_,
            flat(Psi0.primitiveField()), flat(Pnb), flat(Unb), G.cdata(),
            Gnb.cdata(), deltaT, flat(Ab[patchi])
        );
    }

    // Local extrema of the old and low-order Psi
    tmp<volSymmTensorField> tEmin(field("logBmin"));
    tmp<volSymmTensorField> tEmax(field("logBmax"));
    volSymmTensorField& Emin = tEmin.ref();
    volSymmTensorField& Emax = tEmax.ref();
    vhe_fct_extrema_init
    (
        nCells, phis0.primitiveField().cdata(), flat(Psi0.primitiveField()),
        m.cdata(), flat(X), phisMin, flat(Emin.primitiveFieldRef()),
        flat(Emax.primitiveFieldRef())
    );
    Emin.correctBoundaryConditions();
    Emax.correctBoundaryConditions();
    symmTensorField Xmin(Emin.primitiveField()), Xmax(Emax.primitiveField());
    vhe_fct_extrema_internal
    (
        nIntFaces, own.cdata(), nei.cdata(), flat(Emin.primitiveField()),
        flat(Emax.primitiveField()), flat(Xmin), flat(Xmax)
    );

    // Zalesak's ratios
    tmp<volSymmTensorField> tRp(field("logBRplus"));
    tmp<volSymmTensorField> tRm(field("logBRminus"));
    volSymmTensorField& Rp = tRp.ref();
    volSymmTensorField& Rm = tRm.ref();
    vhe_fct_sums_internal
    (
        nIntFaces, own.cdata(), nei.cdata(), flat(A),
        flat(Rp.primitiveFieldRef()), flat(Rm.primitiveFieldRef())
    );
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled() || !p.size()) continue;
        const symmTensorField EminNb
        (
            Emin.boundaryField()[patchi].patchNeighbourField()
        );
        const symmTensorField EmaxNb
        (
            Emax.boundaryField()[patchi].patchNeighbourField()
        );
        vhe_fct_extrema_boundary
        (
            p.size(), p.faceCells().cdata(), flat(EminNb), flat(EmaxNb),
            flat(Xmin), flat(Xmax)
        );
        vhe_fct_sums_boundary
        (
            p.size(), p.faceCells().cdata(), flat(Ab[patchi]),
            flat(Rp.primitiveFieldRef()), flat(Rm.primitiveFieldRef())
        );
    }
    vhe_fct_ratios
    (
        nCells, m.cdata(), flat(X), flat(Xmin), flat(Xmax),
        flat(Rp.primitiveFieldRef()), flat(Rm.primitiveFieldRef())
    );
    Rp.correctBoundaryConditions();
    Rm.correctBoundaryConditions();

    // Limited antidiffusion on the low-order content m Psi
    symmTensorField mX(m*X);
    vhe_fct_apply_internal
    (
        nIntFaces, own.cdata(), nei.cdata(), flat(A),
        flat(Rp.primitiveField()), flat(Rm.primitiveField()), flat(mX)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled() || !p.size()) continue;
        const symmTensorField RpNb
        (
            Rp.boundaryField()[patchi].patchNeighbourField()
        );
        const symmTensorField RmNb
        (
            Rm.boundaryField()[patchi].patchNeighbourField()
        );
        vhe_fct_apply_boundary
        (
            p.size(), p.faceCells().cdata(), flat(Ab[patchi]),
            flat(Rp.primitiveField()), flat(Rm.primitiveField()),
            flat(RpNb), flat(RmNb), flat(mX)
        );
    }
    forAll(X, celli)
    {
        if (m[celli] > 0) X[celli] = mX[celli]/m[celli];
    }

    vhe_bstar_from_logb
    (
        nCells, phis.primitiveField().cdata(), flat(X), phisMin,
        flat(Bstar.primitiveFieldRef())
    );
}


// ************************************************************************* //
