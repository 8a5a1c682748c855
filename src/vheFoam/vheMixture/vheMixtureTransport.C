/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- transport of the
  phase fractions (MULES with interface compression between every pair of
  phases that meet, multiphaseInterFoam's method); the colours of a
  material that meet no other carried as shares of their sum's flux
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "colourShares.H"
#include "fvc.H"
#include "limitSum.H"
#include "profiling.H"
#include "vheFlat.H"
#include "vhe.h"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::vheMixture::checkSchemes() const
{
    // The interface compression takes linear face values (the C core)
    ITstream& is = mesh_.divScheme("div(phirb,alpha)");
    const word gauss(is), interp(is);
    if (gauss != "Gauss" || interp != "linear" || !is.eof())
    {
        FatalIOErrorInFunction(mesh_.schemesDict())
            << "div(phirb,alpha) must be 'Gauss linear' (the interface"
            << " compression takes linear face values), got '" << gauss
            << ' ' << interp << (is.eof() ? "" : " ...") << "'"
            << exit(FatalIOError);
    }
}


bool Foam::vheMixture::geometricSolids() const
{
    // Solids are carried geometrically (isoAdvector); MULES with
    // interface compression, as the fluids, is kept as the reference of
    // benchmarks/transport (solidTransport MULES)
    const dictionary& alphaControls = mesh_.solverDict("alpha");
    const word solidTransport
    (
        alphaControls.getOrDefault<word>("solidTransport", "geometric")
    );
    if (solidTransport != "geometric" && solidTransport != "MULES")
    {
        FatalIOErrorInFunction(alphaControls)
            << "solidTransport must be geometric or MULES, got '"
            << solidTransport << "'" << exit(FatalIOError);
    }
    return solidTransport == "geometric";
}


void Foam::vheMixture::alphaFluxes
(
    const transported& t,
    const surfaceScalarField& carrier,
    scalar cAlpha,
    PtrList<surfaceScalarField>& alphaPhis
) const
{
    const word alphaScheme("div(phi,alpha)");
    const label n = t.size();

    surfaceScalarField phic(mag(carrier/mesh_.magSf()));
    phic = min(cAlpha*phic, max(phic));

    // Each field's high-order flux, then the interface compression of
    // every pair that is on (multiphaseMixture's, linear face values; the
    // C core, one pass over the faces per pair)
    alphaPhis.setSize(n);
    PtrList<surfaceScalarField> af(n);
    PtrList<surfaceVectorField> gf(n);
    for (label i = 0; i < n; ++i)
    {
        alphaPhis.set
        (
            i,
            new surfaceScalarField
            (
                "alphaPhi." + t.fields[i].name(),
                fvc::flux(carrier, t.fields[i], alphaScheme)
            )
        );
        af.set(i, fvc::interpolate(t.fields[i]));
        gf.set(i, fvc::interpolate(fvc::grad(t.fields[i])));
    }
    for (label i = 0; i < n; ++i)
    {
        for (label j = i + 1; j < n; ++j)
        {
            if (!t.pairOn[pairIndex(i, j, n)]) continue;
            vhe_compress_pair
            (
                mesh_.nInternalFaces(), phic.primitiveField().cdata(),
                flat(mesh_.Sf().primitiveField()),
                af[i].primitiveField().cdata(), af[j].primitiveField().cdata(),
                flat(gf[i].primitiveField()), flat(gf[j].primitiveField()),
                deltaN_.value(), alphaPhis[i].primitiveFieldRef().data(),
                alphaPhis[j].primitiveFieldRef().data()
            );
            forAll(mesh_.boundary(), patchi)
            {
                vhe_compress_pair
                (
                    mesh_.boundary()[patchi].size(),
                    phic.boundaryField()[patchi].cdata(),
                    flat(mesh_.Sf().boundaryField()[patchi]),
                    af[i].boundaryField()[patchi].cdata(),
                    af[j].boundaryField()[patchi].cdata(),
                    flat(gf[i].boundaryField()[patchi]),
                    flat(gf[j].boundaryField()[patchi]), deltaN_.value(),
                    alphaPhis[i].boundaryFieldRef()[patchi].data(),
                    alphaPhis[j].boundaryFieldRef()[patchi].data()
                );
            }
        }
    }
}


void Foam::vheMixture::limitFluxes
(
    const transported& t,
    label nLimitSumIter,
    scalar deltaT,
    PtrList<surfaceScalarField>& alphaPhis,
    PtrList<scalarField>& alphaNew
) const
{
    // The explicit update from the sub-step's old value
    // (MULES::explicitSolve with unit density, written out so that
    // sub-steps are exact)
    const label n = t.size();
    alphaNew.setSize(n);
    const auto update = [&]()
    {
        scalar lo = GREAT;
        for (label i = 0; i < n; ++i)
        {
            alphaNew.set
            (
                i,
                new scalarField
                (
                    t.fields[i].oldTime().primitiveField()
                  - deltaT*fvc::surfaceIntegrate(alphaPhis[i])().primitiveField()
                )
            );
            lo = min(lo, min(alphaNew[i]));
        }
        return returnReduce(lo, minOp<scalar>());
    };
    vheMULES::limitSum
    (
        t.fields, geometricOneField(), phi_, deltaT, nLimitSumIter,
        alphaPhis, update
    );
}


void Foam::vheMixture::solveAlphaStep
(
    const labelList& active,
    scalar cAlpha,
    label nLimitSumIter,
    scalar deltaT,
    scalar weight
)
{
    transported t;
    selectTransported(active, t);
    const label n = t.size();

    PtrList<surfaceScalarField> alphaPhis;
    PtrList<scalarField> alphaNew;
    {
        addProfiling(mules, "vheMixture::MULES");
        alphaFluxes(t, phi_, cAlpha, alphaPhis);
        limitFluxes(t, nLimitSumIter, deltaT, alphaPhis, alphaNew);
    }

    // The colours a sum carries, on its flux
    for (label i = 0; i < n; ++i)
    {
        if (t.carried[i].empty()) continue;
        UPtrList<volScalarField> colours(t.carried[i].size());
        forAll(t.carried[i], c)
        {
            colours.set(c, &alphas_[t.carried[i][c]]);
        }
        colourShares::transport(colours, alphaPhis[i], deltaT);
    }

    rhoPhi_ = dimensionedScalar(rhoPhi_.dimensions(), Zero);
    for (label i = 0; i < n; ++i)
    {
        volScalarField& alpha = t.fields[i];
        const surfaceScalarField& alphaPhi = alphaPhis[i];

        alpha.primitiveFieldRef() = alphaNew[i];
        alpha.correctBoundaryConditions();

        rhoPhi_ += alphaPhi*dimensionedScalar("rho", dimDensity, t.rho[i]);
        if (t.elastic[i])
        {
            *alphaPhiSolid_ += weight*alphaPhi;
        }
    }

    // Remove the round-off drift of the sum, as multiphaseMixture
    scalarField sumAlpha(mesh_.nCells(), 0);
    for (const label i : active)
    {
        sumAlpha += alphas_[i].primitiveField();
    }
    const scalarField sumCorr(1.0 - sumAlpha);
    for (volScalarField& alpha : alphas_)
    {
        alpha.primitiveFieldRef() += alpha.primitiveField()*sumCorr;
        alpha.correctBoundaryConditions();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::vheMixture::solve()
{
    if (alphas_.size() < 2)
    {
        rhoPhi_ = fvc::interpolate(rho_)*phi_;
        return;
    }

    const dictionary& alphaControls = mesh_.solverDict("alpha");
    const label nSub = alphaControls.getOrDefault<label>("nAlphaSubCycles", 1);
    const scalar cAlpha = alphaControls.getOrDefault<scalar>("cAlpha", 1);
    // The phases with content: an empty phase (a colour no body has now)
    // has zero fluxes and zero compression against every other, exactly,
    // so it is left out, and a material's spare colours cost nothing
    DynamicList<label> act(alphas_.size());
    forAll(alphas_, i)
    {
        const volScalarField& a = alphas_[i];
        bool any = false;
        for (const scalar v : a.primitiveField())
        {
            if (v != 0) { any = true; break; }
        }
        for (const fvPatchScalarField& pf : a.boundaryField())
        {
            for (const scalar v : pf)
            {
                if (v != 0) { any = true; break; }
            }
        }
        if (returnReduce(any, orOp<bool>())) act.append(i);
    }
    const labelList active(act);
    // Two phases need no re-limiting: their corrections are exact opposites
    const label nLimitSumIter = alphaControls.getOrDefault<label>
    (
        "nLimitSumIter", active.size() > 2 ? 2 : 0
    );
    if (nSub < 1)
    {
        FatalIOErrorInFunction(alphaControls)
            << "nAlphaSubCycles must be >= 1, got " << nSub
            << exit(FatalIOError);
    }

    const scalar deltaT = mesh_.time().deltaTValue();

    if (nSolids_)
    {
        *alphaPhiSolid_ = dimensionedScalar(dimVolume/dimTime, Zero);
    }

    bool solids = false;
    for (const label i : active)
    {
        solids = solids || phases_[i].solid;
    }

    if (solids && geometricSolids())
    {
        // Bodies' outlines are geometry: isoAdvector for the solids
        solveGeometric(active, cAlpha, nLimitSumIter, nSub);
    }
    else if (nSub == 1)
    {
        solveAlphaStep(active, cAlpha, nLimitSumIter, deltaT, 1);
    }
    else
    {
        // Each sub-step restarts from its own old value; the true old-time
        // values are put back afterwards for the next PIMPLE iteration.
        PtrList<volScalarField> alpha0(alphas_.size());
        forAll(alphas_, i)
        {
            alpha0.set(i, new volScalarField("alpha0", alphas_[i].oldTime()));
        }
        surfaceScalarField rhoPhiSum("rhoPhiSum", 0*rhoPhi_);

        for (label s = 0; s < nSub; ++s)
        {
            if (s > 0)
            {
                for (volScalarField& alpha : alphas_) alpha.oldTime() == alpha;
            }
            solveAlphaStep
            (
                active, cAlpha, nLimitSumIter, deltaT/nSub, 1.0/nSub
            );
            rhoPhiSum += rhoPhi_/scalar(nSub);
        }
        forAll(alphas_, i) alphas_[i].oldTime() == alpha0[i];
        rhoPhi_ = rhoPhiSum;
    }

    correct();
    holdFixed();
    report();
}


// ************************************************************************* //
