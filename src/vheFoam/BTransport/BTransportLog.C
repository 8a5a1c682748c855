/*---------------------------------------------------------------------------*\
  vheFoam: transport of the deformation B as log B (BTransport log)

  Over the step's solid region only (findRegion): the cells with solid and
  their neighbours, the faces between them, each patch's faces of region
  cells.  Every array below has one entry per region cell or face; the
  neighbours across coupled patches come through neighbourValues.
\*---------------------------------------------------------------------------*/

#include "BTransport.H"
#include "vheFlat.H"
#include "vhe.h"
#include <cfloat>

namespace
{
    //- Values of a mesh field at the given cells or faces
    template<class Type>
    Foam::Field<Type> pick(const Foam::UList<Type>& f, const Foam::labelList& l)
    {
        return Foam::Field<Type>(f, l);
    }
}

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::BTransport::advectLog
(
    volSymmTensorField& Bstar,
    const volVectorField& U,
    scalar deltaT
) const
{
    const volScalarField& phisField = mixture_.phis();
    const scalar phisMin = mixture_.solidFractionMin();
    workspace& w = work();
    solidRegion r;
    findRegion(r);
    const label n = r.cells.size();
    const label nf = r.faces.size();
    const symmTensor huge(symmTensor::one*HUGE_VAL);

    // The region's cells and faces
    const scalarField phis0(pick(phisField.oldTime().primitiveField(), r.cells));
    const scalarField phis(pick(phisField.primitiveField(), r.cells));
    const vectorField C(pick(mesh_.C().primitiveField(), r.cells));
    const vectorField Uc(pick(U.primitiveField(), r.cells));
    scalarField a(pick(mixture_.alphaPhiSolid().primitiveField(), r.faces));
    a *= deltaT;
    vectorField delta(nf);
    forAll(delta, i)
    {
        delta[i] = C[r.nei[i]] - C[r.own[i]];
    }
    // Each cell's eigenvectors of B, from the last step (the identity for
    // a cell new to the region; both cell lists ascend)
    scalarField V(9*n);
    for (label i = 0, j = 0; i < n; ++i)
    {
        const label c = r.cells[i];
        while (j < w.cells.size() && w.cells[j] < c) ++j;
        const bool had = j < w.cells.size() && w.cells[j] == c;
        for (direction k = 0; k < 9; ++k)
        {
            V[9*i + k] = had ? w.V[9*j + k] : (k % 4 == 0 ? 1 : 0);
        }
    }

    // Psi = log B of the old step
    symmTensorField Psi0(n);
    {
        const symmTensorField B0(pick(Bstar.oldTime().primitiveField(), r.cells));
        const size_t bad = vhe_logb_from_bstar
        (
            n, phis0.cdata(), flat(B0), phisMin, flat(Psi0), V.data()
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
    List<symmTensorField> Psi0nb;
    neighbourValues(r, Psi0, symmTensor::zero, Psi0nb);

    // Low order: donor-cell Psi and solid content m of every cell
    scalarField m(n);
    symmTensorField X(n);
    {
        scalarField out(n), W(n);
        symmTensorField S(n);
        donorSums(r, Psi0, Psi0nb, a, deltaT, out, W, S);
        reportFlushed
        (
            vhe_donor_finish
            (
                n, pick(mesh_.V().field(), r.cells).cdata(), phis0.cdata(),
                phis.cdata(), flat(Psi0), out.cdata(), W.cdata(), flat(S),
                phisMin, m.data(), flat(X)
            )
        );
    }

    // The old phi_s and the velocity across coupled patches
    List<scalarField> phisNb(mesh_.boundary().size());
    List<vectorField> UNb(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled() || !p.size()) continue;
        const labelList& pf = r.patchFaces[patchi];
        phisNb[patchi] = scalarField
        (
            phisField.oldTime().boundaryField()[patchi].patchNeighbourField(),
            pf
        );
        UNb[patchi] = vectorField
        (
            U.boundaryField()[patchi].patchNeighbourField(), pf
        );
    }

    // Least-squares gradient of Psi0 between cells with solid
    scalarField G(18*n);
    {
        symmTensorField M(n, Zero);
        scalarField b(18*n, Zero);
        vhe_lsq_grad_internal
        (
            nf, r.own.cdata(), r.nei.cdata(), flat(delta), phis0.cdata(),
            phisGradient_, flat(Psi0), flat(M), b.data()
        );
        forAll(mesh_.boundary(), patchi)
        {
            const labelList& pf = r.patchFaces[patchi];
            if (!mesh_.boundary()[patchi].coupled() || pf.empty()) continue;
            const vectorField d
            (
                pick(mesh_.boundary()[patchi].delta()(), pf)
            );
            vhe_lsq_grad_boundary
            (
                pf.size(), r.patchCells[patchi].cdata(), flat(d),
                phis0.cdata(), phisNb[patchi].cdata(), phisGradient_,
                flat(Psi0), flat(Psi0nb[patchi]), flat(M), b.data()
            );
        }
        vhe_lsq_grad_finish(n, flat(M), b.data(), G.data());
    }

    // The gradient's three directions across coupled patches
    List<scalarField> GNb(mesh_.boundary().size());
    for (direction d = 0; d < 3 && w.coupled; ++d)
    {
        symmTensorField g(n);
        forAll(g, i)
        {
            for (direction k = 0; k < 6; ++k) g[i][k] = G[18*i + 6*d + k];
        }
        List<symmTensorField> gNb;
        neighbourValues(r, g, symmTensor::zero, gNb);
        forAll(gNb, patchi)
        {
            if (gNb[patchi].empty()) continue;
            scalarField& Gp = GNb[patchi];
            Gp.setSize(18*gNb[patchi].size());
            forAll(gNb[patchi], i)
            {
                for (direction k = 0; k < 6; ++k)
                {
                    Gp[18*i + 6*d + k] = gNb[patchi][i][k];
                }
            }
        }
    }

    // Antidiffusive fluxes, internal and coupled faces
    symmTensorField A(nf);
    vhe_antidiffusive_internal
    (
        nf, r.own.cdata(), r.nei.cdata(), a.cdata(),
        flat(pick(mesh_.Sf().primitiveField(), r.faces)), flat(delta),
        flat(pick(mesh_.Cf().primitiveField(), r.faces)), flat(C),
        flat(Uc), phis0.cdata(), phisGradient_, flat(Psi0), G.cdata(),
        deltaT, flat(A)
    );
    List<symmTensorField> Ab(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const labelList& pf = r.patchFaces[patchi];
        Ab[patchi].setSize(pf.size(), Zero);
        if (!p.coupled() || pf.empty()) continue;
        scalarField ap(pick(mixture_.alphaPhiSolid().boundaryField()[patchi], pf));
        ap *= deltaT;
        vhe_antidiffusive_boundary
        (
            pf.size(), r.patchCells[patchi].cdata(), ap.cdata(),
            flat(pick(mesh_.Sf().boundaryField()[patchi], pf)),
            flat(pick(p.delta()(), pf)),
            flat(pick(mesh_.Cf().boundaryField()[patchi], pf)),
            flat(C), flat(Uc), phis0.cdata(), phisNb[patchi].cdata(),
            phisGradient_, flat(Psi0), flat(Psi0nb[patchi]),
            flat(UNb[patchi]), G.cdata(), GNb[patchi].cdata(), deltaT,
            flat(Ab[patchi])
        );
    }

    // Local extrema of the old and low-order Psi
    symmTensorField Emin(n), Emax(n);
    vhe_fct_extrema_init
    (
        n, phis0.cdata(), flat(Psi0), m.cdata(), flat(X), phisMin,
        flat(Emin), flat(Emax)
    );
    List<symmTensorField> EminNb, EmaxNb;
    neighbourValues(r, Emin, huge, EminNb);
    neighbourValues(r, Emax, -huge, EmaxNb);
    symmTensorField Xmin(Emin), Xmax(Emax);
    vhe_fct_extrema_internal
    (
        nf, r.own.cdata(), r.nei.cdata(), flat(Emin), flat(Emax),
        flat(Xmin), flat(Xmax)
    );

    // Zalesak's ratios
    symmTensorField Rp(n, Zero), Rm(n, Zero);
    vhe_fct_sums_internal
    (
        nf, r.own.cdata(), r.nei.cdata(), flat(A), flat(Rp), flat(Rm)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const labelList& pf = r.patchFaces[patchi];
        if (!mesh_.boundary()[patchi].coupled() || pf.empty()) continue;
        const labelList& pc = r.patchCells[patchi];
        vhe_fct_extrema_boundary
        (
            pf.size(), pc.cdata(), flat(EminNb[patchi]),
            flat(EmaxNb[patchi]), flat(Xmin), flat(Xmax)
        );
        vhe_fct_sums_boundary
        (
            pf.size(), pc.cdata(), flat(Ab[patchi]), flat(Rp), flat(Rm)
        );
    }
    vhe_fct_ratios
    (
        n, m.cdata(), flat(X), flat(Xmin), flat(Xmax), flat(Rp), flat(Rm)
    );
    const symmTensor one(symmTensor::one);
    List<symmTensorField> RpNb, RmNb;
    neighbourValues(r, Rp, one, RpNb);
    neighbourValues(r, Rm, one, RmNb);

    // Limited antidiffusion on the low-order content m Psi
    symmTensorField mX(n);
    forAll(mX, i)
    {
        mX[i] = m[i]*X[i];
    }
    vhe_fct_apply_internal
    (
        nf, r.own.cdata(), r.nei.cdata(), flat(A), flat(Rp), flat(Rm),
        flat(mX)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const labelList& pf = r.patchFaces[patchi];
        if (!mesh_.boundary()[patchi].coupled() || pf.empty()) continue;
        vhe_fct_apply_boundary
        (
            pf.size(), r.patchCells[patchi].cdata(), flat(Ab[patchi]),
            flat(Rp), flat(Rm), flat(RpNb[patchi]), flat(RmNb[patchi]),
            flat(mX)
        );
    }
    forAll(X, i)
    {
        if (m[i] > 0) X[i] = mX[i]/m[i];
    }

    // B* of the new step: 0 outside the region (no solid there)
    symmTensorField Bs(n);
    vhe_bstar_from_logb(n, phis.cdata(), flat(X), phisMin, flat(Bs), V.data());
    symmTensorField& B = Bstar.primitiveFieldRef();
    B = Zero;
    forAll(r.cells, i)
    {
        B[r.cells[i]] = Bs[i];
    }
    w.cells = r.cells;
    w.V.transfer(V);
}


// ************************************************************************* //
