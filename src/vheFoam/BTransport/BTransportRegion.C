/*---------------------------------------------------------------------------*\
  vheFoam: transport of the deformation B with the solid
  the solid region of a step, and the neighbours' values across coupled
  patches
\*---------------------------------------------------------------------------*/

#include "BTransport.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::BTransport::findRegion(solidRegion& r) const
{
    const scalarField& phis = mixture_.phis().primitiveField();
    const volScalarField& phis0 = mixture_.phis().oldTime();
    const scalar phisMin = mixture_.solidFractionMin();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    labelList& index = ws_.index;

    // Cells with solid before or after the step (MULES leaves round-off
    // fractions everywhere: above solidFractionMin, the cells that carry
    // a deformation), then their face neighbours, which exchange solid
    // with them
    boolList solid(mesh_.nCells(), false);
    forAll(solid, c)
    {
        solid[c] = phis[c] > phisMin || phis0[c] > phisMin;
    }
    boolList in(solid);
    forAll(own, f)
    {
        if (solid[own[f]] || solid[nei[f]])
        {
            in[own[f]] = in[nei[f]] = true;
        }
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!p.coupled() || !p.size()) continue;
        const scalarField nb(mixture_.phis().boundaryField()[patchi]
            .patchNeighbourField());
        const scalarField nb0(phis0.boundaryField()[patchi]
            .patchNeighbourField());
        const labelUList& fc = p.faceCells();
        forAll(fc, i)
        {
            if (nb[i] > phisMin || nb0[i] > phisMin) in[fc[i]] = true;
        }
    }

    label n = 0;
    forAll(in, c)
    {
        index[c] = in[c] ? n++ : -1;
    }
    r.cells.setSize(n);
    forAll(in, c)
    {
        if (in[c]) r.cells[index[c]] = c;
    }

    label nf = 0;
    forAll(own, f)
    {
        if (in[own[f]] && in[nei[f]]) ++nf;
    }
    r.faces.setSize(nf);
    r.own.setSize(nf);
    r.nei.setSize(nf);
    nf = 0;
    forAll(own, f)
    {
        if (in[own[f]] && in[nei[f]])
        {
            r.faces[nf] = f;
            r.own[nf] = index[own[f]];
            r.nei[nf] = index[nei[f]];
            ++nf;
        }
    }

    r.patchFaces.setSize(mesh_.boundary().size());
    r.patchCells.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const labelUList& fc = mesh_.boundary()[patchi].faceCells();
        DynamicList<label> pf, pc;
        forAll(fc, i)
        {
            if (in[fc[i]])
            {
                pf.append(i);
                pc.append(index[fc[i]]);
            }
        }
        r.patchFaces[patchi].transfer(pf);
        r.patchCells[patchi].transfer(pc);
    }
}


void Foam::BTransport::neighbourValues
(
    const solidRegion& r,
    const symmTensorField& x,
    const symmTensor& outside,
    List<symmTensorField>& nb
) const
{
    nb.setSize(mesh_.boundary().size());
    if (!ws_.coupled) return;
    volSymmTensorField& f = ws_.scratch();
    symmTensorField& fi = f.primitiveFieldRef();
    fi = outside;
    forAll(r.cells, i)
    {
        fi[r.cells[i]] = x[i];
    }
    f.correctBoundaryConditions();
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchSymmTensorField& fp = f.boundaryField()[patchi];
        if (!fp.coupled() || fp.empty()) continue;
        const symmTensorField all(fp.patchNeighbourField());
        nb[patchi] = symmTensorField(all, r.patchFaces[patchi]);
    }
}


// ************************************************************************* //
