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
            IOobject
            (
                name, mesh_.time().timeName(), mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_,
            dimensionedSymmTensor(dimless, Zero),
            vheElasticity::patchTypes(mesh_)
        )
    );
}


Foam::BTransport::workspace& Foam::BTransport::work() const
{
    workspace& w = ws_;
    const label nCells = mesh_.nCells(), nFaces = mesh_.nInternalFaces();
    // Made again on every rank together (it reduces): after a refinement
    // only some ranks may have changed size
    const bool remake = returnReduce
    (
        w.nCells != nCells || w.nFaces != nFaces || mesh_.topoChanging(),
        orOp<bool>()
    );
    if (!remake)
    {
        return w;
    }
    w.nCells = nCells;
    w.nFaces = nFaces;
    w.cells.clear();
    w.V.clear();
    w.index.setSize(nCells);
    w.index = -1;
    // Coupled (processor, cyclic) faces anywhere: their neighbours' values
    // come through volField boundary conditions (collective: all ranks)
    bool coupled = false;
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        coupled = coupled || (p.coupled() && p.size());
    }
    w.coupled = returnReduce(coupled, orOp<bool>());
    w.scratch.reset(w.coupled ? field("logBExchange").ptr() : nullptr);
    return w;
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
    const solidRegion& r,
    const symmTensorField& X0,
    const List<symmTensorField>& X0nb,
    const scalarField& a,
    scalar deltaT,
    scalarField& out,
    scalarField& W,
    symmTensorField& S
) const
{
    const surfaceScalarField& aPhi = mixture_.alphaPhiSolid();
    out = 0;
    W = 0;
    S = Zero;
    vhe_bdonor_internal
    (
        r.faces.size(), r.own.cdata(), r.nei.cdata(), a.cdata(),
        flat(X0), out.data(), W.data(), flat(S)
    );
    forAll(mesh_.boundary(), patchi)
    {
        const labelList& pf = r.patchFaces[patchi];
        if (pf.empty()) continue;
        const labelList& pc = r.patchCells[patchi];
        // Across a coupled patch the donor is the neighbour cell; at any
        // other boundary the boundary value, zeroGradient (vheElasticity::
        // patchTypes) or a constraint without flux
        const symmTensorField Xnb
        (
            mesh_.boundary()[patchi].coupled()
          ? X0nb[patchi]
          : symmTensorField(X0, pc)
        );
        const scalarField& ab = aPhi.boundaryField()[patchi];
        scalarField ap(pf.size());
        forAll(pf, i)
        {
            ap[i] = deltaT*ab[pf[i]];
        }
        vhe_bdonor_boundary
        (
            ap.size(), pc.cdata(), ap.cdata(), flat(Xnb), out.data(),
            W.data(), flat(S)
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
    // Over the step's solid region, as the log transport: a cell outside
    // it has no solid and no neighbour with solid, so B* = 0 there
    const volScalarField& phis = mixture_.phis();
    const scalar phisMin = mixture_.solidFractionMin();
    work();
    solidRegion r;
    findRegion(r);
    const label n = r.cells.size();
    const scalarField phis0(phis.oldTime().primitiveField(), r.cells);

    // Old B of the solid; I where there is none
    symmTensorField B0(n);
    vhe_b_from_bstar
    (
        n, phis0.cdata(),
        flat(symmTensorField(Bstar.oldTime().primitiveField(), r.cells)),
        phisMin, flat(B0)
    );
    List<symmTensorField> B0nb;
    neighbourValues(r, B0, symmTensor::I, B0nb);

    scalarField a(mixture_.alphaPhiSolid().primitiveField(), r.faces);
    a *= deltaT;
    scalarField out(n), W(n);
    symmTensorField S(n);
    donorSums(r, B0, B0nb, a, deltaT, out, W, S);
    symmTensorField Bs(n);
    reportFlushed
    (
        vhe_bdonor_finish
        (
            n, scalarField(mesh_.V().field(), r.cells).cdata(),
            phis0.cdata(),
            scalarField(phis.primitiveField(), r.cells).cdata(), flat(B0),
            out.cdata(), W.cdata(), flat(S), phisMin, flat(Bs)
        )
    );
    symmTensorField& B = Bstar.primitiveFieldRef();
    B = Zero;
    forAll(r.cells, i)
    {
        B[r.cells[i]] = Bs[i];
    }
}


// ************************************************************************* //
