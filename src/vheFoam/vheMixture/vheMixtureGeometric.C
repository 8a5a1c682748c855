/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- the step with
  solids: each solid fraction carried geometrically (isoAdvector), the
  fluids as shares of the volume the solids leave
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "solidAdvection.H"
#include "colourShares.H"
#include "fvc.H"
#include "limitSum.H"
#include "profiling.H"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::vheMixture::fluidShares
(
    transported& t,
    const labelList& fluids,
    const surfaceScalarField& phiFluid,
    const scalarField& fluidNew,
    scalar cAlpha,
    label nLimitSumIter,
    label nSub,
    PtrList<surfaceScalarField>& alphaPhis
)
{
    const label nF = fluids.size();
    if (nF == 0) return;

    if (nF == 1)
    {
        // The one fluid fills what the solids leave, on what they leave of
        // the flux
        volScalarField& alpha = t.fields[fluids[0]];
        alpha.oldTime();
        alpha.primitiveFieldRef() = fluidNew;
        alpha.correctBoundaryConditions();
        alphaPhis.set
        (
            fluids[0],
            new surfaceScalarField("alphaPhi." + alpha.name(), phiFluid)
        );
        return;
    }

    addProfiling(shares, "vheMixture::fluidShares");

    // Several fluids: MULES on each fluid's share c_k of the fluid volume,
    // f c_k = alpha_k, with f as MULES's density and phiFluid its flux:
    // f_new = f_old - dt div(phiFluid) exactly, so the upwind shares stay
    // within their neighbours' (where the fluid's outflow does not exceed
    // the cell's fluid) and the shares sum to 1 on every face.  delta
    // gives the shares a value (1/nF) where a cell holds no fluid; it is
    // far below any fraction that matters
    const scalar delta = 1e-9;
    const scalar deltaT = mesh_.time().deltaTValue()/nSub;

    scalarField f0(mesh_.nCells(), delta);
    for (const label i : fluids)
    {
        f0 += t.fields[i].oldTime().primitiveField();
    }
    const scalarField divF(fvc::surfaceIntegrate(phiFluid)().primitiveField());

    volScalarField f
    (
        IOobject
        (
            "fluidFraction", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh_,
        dimensionedScalar(dimless, Zero)
    );
    f.oldTime();

    // ... and on the patches
    PtrList<scalarField> fb(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        fb.set(patchi, new scalarField(mesh_.boundary()[patchi].size(), delta));
        for (const label i : fluids)
        {
            fb[patchi] += t.fields[i].oldTime().boundaryField()[patchi];
        }
    }

    PtrList<volScalarField> c(nF);
    PtrList<surfaceScalarField> phiSum(nF);
    forAll(fluids, k)
    {
        const volScalarField& a = t.fields[fluids[k]];
        wordList types(a.boundaryField().types());
        forAll(types, patchi)
        {
            if (!a.boundaryField()[patchi].coupled())
            {
                types[patchi] = calculatedFvPatchScalarField::typeName;
            }
        }
        c.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    a.name() + ".share", mesh_.time().timeName(), mesh_,
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                mesh_,
                dimensionedScalar(dimless, Zero),
                types
            )
        );
        c[k].primitiveFieldRef() =
            (a.oldTime().primitiveField() + delta/nF)/f0;
        forAll(mesh_.boundary(), patchi)
        {
            if (a.boundaryField()[patchi].coupled()) continue;
            c[k].boundaryFieldRef()[patchi] ==
                (a.oldTime().boundaryField()[patchi] + delta/nF)/fb[patchi];
        }
        c[k].correctBoundaryConditions();
        c[k].oldTime();
        phiSum.set
        (
            k,
            new surfaceScalarField
            (
                "alphaPhi." + a.name(), 0*phiFluid
            )
        );
    }

    transported ts;
    ts.fields.setSize(nF);
    forAll(c, k) ts.fields.set(k, &c[k]);
    ts.pairOn = List<bool>(nF*(nF - 1)/2, true);

    for (label s = 0; s < nSub; ++s)
    {
        f.oldTime().primitiveFieldRef() = f0 - s*deltaT*divF;
        f.primitiveFieldRef() = f0 - (s + 1)*deltaT*divF;
        if (s > 0)
        {
            for (volScalarField& ck : c) ck.oldTime() == ck;
        }

        PtrList<surfaceScalarField> cPhis;
        alphaFluxes(ts, phiFluid, cAlpha, cPhis);
        const scalarField& fOld = f.oldTime().primitiveField();
        const scalarField& fNew = f.primitiveField();
        // The shares' update from the fluxes (a cell the step empties of
        // fluid keeps its shares)
        PtrList<scalarField> cNew(nF);
        const auto update = [&]()
        {
            scalar lo = GREAT;
            forAll(c, k)
            {
                const scalarField& c0 = c[k].oldTime().primitiveField();
                const scalarField fc
                (
                    fOld*c0
                  - deltaT*fvc::surfaceIntegrate(cPhis[k])().primitiveField()
                );
                cNew.set(k, new scalarField(c0));
                scalarField& ck = cNew[k];
                forAll(ck, celli)
                {
                    if (fNew[celli] > delta) ck[celli] = fc[celli]/fNew[celli];
                }
                lo = min(lo, min(ck));
            }
            return returnReduce(lo, minOp<scalar>());
        };
        if (nF == 2)
        {
            // interFoam's two phases: the first share limited, the second
            // takes the rest
            MULES::limit
            (
                1.0/deltaT, f, c[0], phiFluid, cPhis[0],
                zeroField(), zeroField(), oneField(), zeroField(), true
            );
            cPhis[0] += upwind<scalar>(mesh_, phiFluid).flux(c[0]);
            cPhis[1] = phiFluid - cPhis[0];
            update();
        }
        else
        {
            vheMULES::limitSum
            (
                ts.fields, f, phiFluid, deltaT, nLimitSumIter, cPhis, update
            );
        }
        forAll(c, k)
        {
            c[k].primitiveFieldRef() = cNew[k];
            c[k].correctBoundaryConditions();
            phiSum[k] += cPhis[k]/scalar(nSub);
        }
    }

    // The fractions: the shares (within [0, 1], summing to 1) of what the
    // solids leave
    scalarField sumC(mesh_.nCells(), Zero);
    for (volScalarField& ck : c)
    {
        ck.primitiveFieldRef() = min(max(ck.primitiveField(), scalar(0)), 1.0);
        sumC += ck.primitiveField();
    }
    forAll(fluids, k)
    {
        volScalarField& alpha = t.fields[fluids[k]];
        const scalarField& ck = c[k].primitiveField();
        scalarField& a = alpha.primitiveFieldRef();
        forAll(a, celli)
        {
            a[celli] = sumC[celli] > 0
              ? fluidNew[celli]*ck[celli]/sumC[celli]
              : fluidNew[celli]/nF;
        }
    }

    // The clipping of the shares (and a cell the step empties of fluid)
    // must not move volume from one fluid to another (in the splashing dam
    // break 3.0e-8 of the liquid's volume had turned into gas by t = 2).
    // Each fluid but the last is set to its old volume less what its flux
    // took through the boundary, by moving the difference between it and
    // the later fluid it shares most with, in the cells that hold both;
    // the last fluid is the rest
    const scalarField& V = mesh_.V();
    for (label k = 0; k < nF - 1; ++k)
    {
        scalarField& ak = t.fields[fluids[k]].primitiveFieldRef();
        scalar outflow = 0;
        forAll(mesh_.boundary(), patchi)
        {
            if (mesh_.boundary()[patchi].coupled()) continue;
            outflow += sum(phiSum[k].boundaryField()[patchi]);
        }
        const scalar dV =
            gSum(t.fields[fluids[k]].oldTime().primitiveField()*V)
          - mesh_.time().deltaTValue()*returnReduce(outflow, sumOp<scalar>())
          - gSum(ak*V);
        label partner = -1;
        scalar sumW = 0;
        for (label j = k + 1; j < nF; ++j)
        {
            const scalar wj = gSum(ak*t.fields[fluids[j]].primitiveField()*V);
            if (wj > sumW)
            {
                partner = j;
                sumW = wj;
            }
        }
        if (dV == 0 || sumW <= mag(dV)) continue;
        scalarField& aj = t.fields[fluids[partner]].primitiveFieldRef();
        const scalarField da(dV*ak*aj/sumW);
        ak += da;
        aj -= da;
    }

    forAll(fluids, k)
    {
        t.fields[fluids[k]].correctBoundaryConditions();
        alphaPhis.set(fluids[k], phiSum.set(k, nullptr).ptr());
    }
}


void Foam::vheMixture::solveGeometric
(
    const labelList& active,
    scalar cAlpha,
    label nLimitSumIter,
    label nSub
)
{
    transported t;
    selectTransported(active, t);
    const label n = t.size();
    const scalar deltaT = mesh_.time().deltaTValue();

    DynamicList<label> solidList(n), fluidList(n);
    for (label i = 0; i < n; ++i)
    {
        (t.solid[i] ? solidList : fluidList).append(i);
    }

    // Each solid field geometrically over the whole step (isoAdvector
    // needs no sub-cycles below a Courant number of 1); the colours a sum
    // carries on its flux
    PtrList<surfaceScalarField> alphaPhis(n);
    surfaceScalarField phiSolid
    (
        IOobject
        (
            "phiSolid", mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        ),
        mesh_,
        dimensionedScalar(phi_.dimensions(), Zero)
    );
    if (solidList.size())
    {
        for (const label i : solidList)
        {
            alphaPhis.set
            (
                i, solidAdvection::advect(t.fields[i], phi_, U_).ptr()
            );
        }
    }

    // isoAdvector's bounding leaves fractions a little outside [0, 1], and
    // bodies of two colours carried into one cell can fill it beyond 1:
    // what is out of bounds moves to the face neighbours (conservative, on
    // the fluxes too)
    {
        UPtrList<volScalarField> fields(solidList.size());
        UPtrList<surfaceScalarField> fluxes(solidList.size());
        forAll(solidList, k)
        {
            fields.set(k, &t.fields[solidList[k]]);
            fluxes.set(k, &alphaPhis[solidList[k]]);
        }
        solidAdvection::bound(fields, fluxes, deltaT);
    }

    for (const label i : solidList)
    {
        phiSolid += alphaPhis[i];
        if (t.carried[i].empty()) continue;
        UPtrList<volScalarField> colours(t.carried[i].size());
        forAll(t.carried[i], c)
        {
            colours.set(c, &alphas_[t.carried[i][c]]);
        }
        colourShares::transport(colours, alphaPhis[i], deltaT);
    }

    // What bound could not place (a body's interior, whose neighbours are
    // full) settles on each field's own surface; what finds no room is
    // scaled out and logged
    scalarField solidNew(mesh_.nCells(), Zero);
    {
        UPtrList<volScalarField> solids(active.size());
        label nS = 0;
        for (const label i : active)
        {
            if (phases_[i].solid) solids.set(nS++, &alphas_[i]);
        }
        solids.resize(nS);
        const scalar outside = solidAdvection::settle(solids, solidNew);
        if (outside > 0)
        {
            Info<< "Solids out of bounds: " << outside
                << " m^3 of solid scaled out" << endl;
        }
    }

    // The fluids on what the solids leave
    const surfaceScalarField phiFluid("phiFluid", phi_ - phiSolid);
    fluidShares
    (
        t, fluidList, phiFluid, max(1 - solidNew, scalar(0)), cAlpha,
        nLimitSumIter, nSub,
        alphaPhis
    );

    rhoPhi_ = dimensionedScalar(rhoPhi_.dimensions(), Zero);
    for (label i = 0; i < n; ++i)
    {
        rhoPhi_ += alphaPhis[i]*dimensionedScalar("rho", dimDensity, t.rho[i]);
        if (t.elastic[i])
        {
            *alphaPhiSolid_ += alphaPhis[i];
        }
    }
}


// ************************************************************************* //
