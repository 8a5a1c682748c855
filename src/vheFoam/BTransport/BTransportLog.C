/*---------------------------------------------------------------------------*\
  vheFoam: transport of the deformation B as log B (BTransport log)
\*---------------------------------------------------------------------------*/

#include "BTransport.H"
#include "vheFlat.H"
#include "vhe.h"
#include <cfloat>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

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

    workspace& w = work();
    const surfaceScalarField& aPhi = mixture_.alphaPhiSolid();
    scalarField& a = w.a;
    forAll(a, facei)
    {
        a[facei] = deltaT*aPhi[facei];
    }

    // Psi = log B of the old step
    volSymmTensorField& Psi0 = w.Psi0();
    {
        const size_t bad = vhe_logb_from_bstar
        (
            nCells, phis0.primitiveField().cdata(),
            flat(Bstar.oldTime().primitiveField()), phisMin,
            flat(Psi0.primitiveFieldRef()), w.V.data()
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
    scalarField& m = w.m;
    symmTensorField& X = w.X;
    {
        scalarField& out = w.out;
        scalarField& W = w.W;
        symmTensorField& S = w.S;
        donorSums(Psi0, a, deltaT, out, W, S);
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
    const surfaceVectorField& delta = w.delta();
    scalarField& G = w.G;
    {
        // M and b are 0 on entry: the workspace starts so, and the
        // finish kernel sets them back
        symmTensorField& M = w.M;
        scalarField& b = w.b;
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
        vhe_lsq_grad_finish(nCells, flat(M), b.data(), G.data());
    }

    // The gradient's three directions as fields, for coupled neighbours
    const bool coupled = w.coupled;
    PtrList<volSymmTensorField>& Gd = w.Gd;
    for (direction d = 0; d < Gd.size(); ++d)
    {
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
    symmTensorField& A = w.A;
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
    volSymmTensorField& Emin = w.Emin();
    volSymmTensorField& Emax = w.Emax();
    vhe_fct_extrema_init
    (
        nCells, phis0.primitiveField().cdata(), flat(Psi0.primitiveField()),
        m.cdata(), flat(X), phisMin, flat(Emin.primitiveFieldRef()),
        flat(Emax.primitiveFieldRef())
    );
    if (coupled)
    {
        Emin.correctBoundaryConditions();
        Emax.correctBoundaryConditions();
    }
    symmTensorField& Xmin = w.Xmin;
    symmTensorField& Xmax = w.Xmax;
    Xmin = Emin.primitiveField();
    Xmax = Emax.primitiveField();
    vhe_fct_extrema_internal
    (
        nIntFaces, own.cdata(), nei.cdata(), flat(Emin.primitiveField()),
        flat(Emax.primitiveField()), flat(Xmin), flat(Xmax)
    );

    // Zalesak's ratios
    volSymmTensorField& Rp = w.Rp();
    volSymmTensorField& Rm = w.Rm();
    Rp.primitiveFieldRef() = Zero;
    Rm.primitiveFieldRef() = Zero;
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
    if (coupled)
    {
        Rp.correctBoundaryConditions();
        Rm.correctBoundaryConditions();
    }

    // Limited antidiffusion on the low-order content m Psi
    symmTensorField& mX = w.mX;
    forAll(mX, celli)
    {
        mX[celli] = m[celli]*X[celli];
    }
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
        flat(Bstar.primitiveFieldRef()), w.V.data()
    );
}


// ************************************************************************* //
