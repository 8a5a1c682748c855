/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- phases held to given
  fractions (fixed bodies' shapes, drawn rigid bodies), the fluids filling
  the rest with each fluid's volume kept
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::vheMixture::holdFixed()
{
    // A fixed body's velocity is held at zero in its cells of weight 1 and
    // its inner faces carry no flux (rigidBodies), but its diffuse edge
    // (fractions below 1/4) moves with the liquid in part, and over a long
    // run of a flow past it the transport would draw its edge out
    // downstream.  Its fraction is its shape, given: it is put back, and
    // the fluids of its cells share the rest in their proportions.  The
    // fluids' volume changes by what the transport moved across the edge
    // (benchmarks/rigid reports it)
    DynamicList<label> held;
    DynamicList<scalarField> values;
    forAll(fixedAlphas_, i)
    {
        if (!fixedAlphas_.set(i)) continue;
        held.append(i);
        values.append(fixedAlphas_[i].primitiveField());
    }
    if (held.empty()) return;

    // The hold's density change, which no flux carried, is a mass source
    // at the cell's old velocity, as for the drawn bodies.  (Without it
    // the air over a fixed box that a dam-break wave struck took the
    // momentum of the water the hold moved: its velocity doubled every
    // step and the run stopped at t = 0.19.)
    if (fixedStep_ != mesh_.time().timeIndex())
    {
        fixedStep_ = mesh_.time().timeIndex();
        fixedDRho_.clear();
    }
    holdAsSource(held, values, fixedDRho_);
}


void Foam::vheMixture::holdAsSource
(
    const labelList& held,
    const UList<scalarField>& values,
    scalarField& given
)
{
    // Every outer iteration holds from the step's start: the old density
    // takes the difference to what it was given
    const scalarField rho0(rho_.primitiveField());
    hold(held, values);
    drainEdges(held);
    correct();
    const scalarField dRho(rho_.primitiveField() - rho0);
    if (given.size() != dRho.size()) given = scalarField(dRho.size(), Zero);
    addToOldDensity(dRho - given);
    given = dRho;
}


void Foam::vheMixture::addToOldDensity(const scalarField& dRho)
{
    // Without an old time yet, ddt takes the current density as old
    if (rho_.nOldTimes() == 0) return;
    rho_.oldTime().primitiveFieldRef() += dRho;
}


void Foam::vheMixture::hold
(
    const labelList& held,
    const UList<scalarField>& values
)
{
    label firstFluid = 0;
    while (phases_[firstFluid].solid) ++firstFluid;
    const label nCells = mesh_.nCells();

    // The held phases' sum, scaled to 1 where they overlap, and the cells
    // where any of them changes
    scalarField sumHeld(nCells, Zero);
    boolList changed(nCells, false);
    forAll(held, k)
    {
        const scalarField& a = alphas_[held[k]].primitiveField();
        const scalarField& v = values[k];
        forAll(v, c)
        {
            sumHeld[c] += v[c];
            changed[c] = changed[c] || a[c] != v[c];
        }
    }
    // The other phases' shares from their non-negative parts: MULES leaves
    // fractions of -1e-10 and the like, and a share of a sum of such
    // values (water 1e-10, air -1e-10 + 1e-14) was 1e4 times the rest, so
    // that a cell a drawn body left took 2e4 of water and -2e4 of air.
    // Where they hold almost nothing (1e-9), the first fluid fills it
    scalarField rest(nCells, Zero);
    forAll(alphas_, j)
    {
        if (!held.found(j)) rest += max(alphas_[j].primitiveField(), scalar(0));
    }

    // The fluids' volumes before: each but the last is kept (below)
    const scalarField& V = mesh_.V();
    DynamicList<label> fluids;
    forAll(phases_, j)
    {
        if (!phases_[j].solid && !held.found(j)) fluids.append(j);
    }
    scalarList V0(fluids.size(), Zero);
    forAll(fluids, f)
    {
        V0[f] = gSum(alphas_[fluids[f]].primitiveField()*V);
    }
    forAll(alphas_, j)
    {
        scalarField& aj = alphas_[j].primitiveFieldRef();
        const label k = held.find(j);
        forAll(aj, c)
        {
            if (!changed[c]) continue;
            const scalar s = max(sumHeld[c], scalar(1));
            if (k >= 0)
            {
                aj[c] = values[k][c]/s;
            }
            else
            {
                const scalar free = 1 - sumHeld[c]/s;
                aj[c] = rest[c] > 1e-9
                  ? max(aj[c], scalar(0))*free/rest[c]
                  : (j == firstFluid ? free : 0);
            }
        }
        alphas_[j].correctBoundaryConditions();
    }

    // The shares keep the fluids' sum, not each fluid: where a body
    // crosses a free surface, the cells it leaves take water and air in
    // their proportions, and tutorials/floatingBodies lost 0.7 % of its
    // water to the air by t = 6.  Each fluid but the last gets its volume
    // back across its own interfaces with the fluids after it, a_j += s
    // a_j L (L their sum in the cell; |s| <= 1 keeps a_j in [0, a_j + L]),
    // those fluids scaled to keep a_j + L; the last fluid takes what the
    // held phases changed
    if (fluids.size() < 2) return;
    for (label f = 0; f < fluids.size() - 1; ++f)
    {
        // The later fluids' sum L in each cell: a_j + L is kept
        scalarField L(nCells, Zero);
        for (label g = f + 1; g < fluids.size(); ++g)
        {
            L += max(alphas_[fluids[g]].primitiveField(), scalar(0));
        }
        scalarField& aj = alphas_[fluids[f]].primitiveFieldRef();
        const scalarField w(max(aj, scalar(0))*L);
        const scalar W = gSum(w*V);
        if (W <= VSMALL) continue;
        const scalar sj =
            max(min((V0[f] - gSum(aj*V))/W, scalar(1)), scalar(-1));
        forAll(aj, c)
        {
            if (w[c] <= 0) continue;
            const scalar da = sj*w[c];
            aj[c] += da;
            for (label g = f + 1; g < fluids.size(); ++g)
            {
                scalar& ag = alphas_[fluids[g]].primitiveFieldRef()[c];
                ag = max(ag, scalar(0))*(L[c] - da)/L[c];
            }
        }
    }
    for (const label j : fluids) alphas_[j].correctBoundaryConditions();
}


// ************************************************************************* //
