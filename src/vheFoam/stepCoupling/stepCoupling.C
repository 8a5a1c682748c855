/*---------------------------------------------------------------------------*\
  vheFoam: the momentum prediction and the projection of a step, iterated to
  their coupled solution where stiff bodies need it
\*---------------------------------------------------------------------------*/

#include "stepCoupling.H"
#include "fvMesh.H"
#include "vhe.h"

Foam::stepCoupling::stepCoupling
(
    const fvMesh& mesh,
    const dictionary& pimpleDict
)
:
    mesh_(mesh),
    tolerance_(1e-5),
    maxIter_(40),
    nHistory_(10),
    on_(false),
    iter_(0),
    change_(0),
    projection_(false)
{
    const dictionary* d = pimpleDict.findDict("coupling");
    if (d)
    {
        tolerance_ = d->getOrDefault<scalar>("tolerance", tolerance_);
        maxIter_ = d->getOrDefault<label>("maxIter", maxIter_);
        if (tolerance_ <= 0 || maxIter_ < 1)
        {
            FatalIOErrorInFunction(*d)
                << "coupling: tolerance must be > 0 and maxIter >= 1, got "
                << tolerance_ << " and " << maxIter_ << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::stepCoupling::dot
(
    const vectorField& aU, const vectorField& aA,
    const vectorField& bU, const vectorField& bA
) const
{
    return gSum((aU & bU)*mesh_.V()) + gSum((aA & bA)*mesh_.V());
}


void Foam::stepCoupling::start
(
    bool on,
    const volVectorField& U,
    const volVectorField& acceleration,
    bool projection
)
{
    // The differences of the last step are kept: its slow modes (the
    // stiff bodies' rigid motions) change little from step to step, so
    // the first updates of this step already act on them (the Couette
    // stiff disk of test_stiff: 2.2 passes a step against 2.6 with a build
    // that kept none).  They go when a step was not iterated, into and
    // out of a fallback's projection (another map), or when the mesh
    // changed.
    // (decided on all ranks together: a refinement may change some only,
    // and every rank must keep as many differences for the sums)
    const bool keep = returnReduce
    (
        on && on_ && !projection && !projection_ && dFU_.size()
     && dFU_[0].size() == U.size() && !mesh_.changing(),
        andOp<bool>()
    );
    projection_ = projection;
    on_ = on;
    iter_ = 0;
    change_ = 0;
    if (!keep)
    {
        dFU_.clear();
        dFA_.clear();
        dGU_.clear();
        dGA_.clear();
        dGFlux_.clear();
    }
    gFlux_.clear();
    if (!on_) return;
    xU_ = U.primitiveField();
    xA_ = mesh_.time().deltaTValue()*acceleration.primitiveField();
}


bool Foam::stepCoupling::loop
(
    volVectorField& U,
    surfaceScalarField& accelerationFlux,
    volVectorField& acceleration
)
{
    if (!on_) return false;
    ++iter_;
    const scalar dt = mesh_.time().deltaTValue();

    // The map's value at x_k and its residual
    const vectorField gU(U.primitiveField());
    const vectorField gA(dt*acceleration.primitiveField());
    const vectorField fU(gU - xU_);
    const vectorField fA(gA - xA_);
    if (iter_ > 1)
    {
        if (dFU_.size() == nHistory_)
        {
            for (label k = 1; k < nHistory_; ++k)
            {
                dFU_.set(k - 1, dFU_.set(k, nullptr));
                dFA_.set(k - 1, dFA_.set(k, nullptr));
                dGU_.set(k - 1, dGU_.set(k, nullptr));
                dGA_.set(k - 1, dGA_.set(k, nullptr));
                dGFlux_.set(k - 1, dGFlux_.set(k, nullptr));
            }
            dFU_.resize(nHistory_ - 1);
            dFA_.resize(nHistory_ - 1);
            dGU_.resize(nHistory_ - 1);
            dGA_.resize(nHistory_ - 1);
            dGFlux_.resize(nHistory_ - 1);
        }
        dFU_.append(new vectorField(fU - fU_));
        dFA_.append(new vectorField(fA - fA_));
        dGU_.append(new vectorField(gU - gU_));
        dGA_.append(new vectorField(gA - gA_));
        dGFlux_.append
        (
            new surfaceScalarField("dGFlux", accelerationFlux - gFlux_())
        );
    }
    gU_ = gU;
    gA_ = gA;
    fU_ = fU;
    fA_ = fA;
    gFlux_.reset(new surfaceScalarField("gFlux", accelerationFlux));

    // gamma minimising |f - dF gamma|
    const label m = dFU_.size();
    List<scalar> gram(m*m, Zero), b(m, Zero), gamma(m, Zero);
    for (label k = 0; k < m; ++k)
    {
        b[k] = dot(dFU_[k], dFA_[k], fU, fA);
        for (label l = 0; l <= k; ++l)
        {
            gram[k*m + l] = gram[l*m + k] =
                dot(dFU_[k], dFA_[k], dFU_[l], dFA_[l]);
        }
    }
    if (m > 0)
    {
        vhe_anderson_gamma(m, gram.cdata(), b.cdata(), gamma.data());
    }

    // The next iterate x_{k+1} = G(x_k) - dG gamma
    vectorField nextU(gU), nextA(gA);
    for (label k = 0; k < m; ++k)
    {
        nextU -= gamma[k]*dGU_[k];
        nextA -= gamma[k]*dGA_[k];
    }
    const scalar Uscale = max(gMax(mag(gU)), VSMALL);
    change_ = gMax(mag(nextU - xU_))/Uscale;
    if ((iter_ > 1 && change_ < tolerance_) || iter_ >= maxIter_)
    {
        Info<< "Coupling: " << iter_ << " passes, last update "
            << change_ << " of |U|max" << endl;
        return false;
    }

    xU_ = nextU;
    xA_ = nextA;
    U.primitiveFieldRef() = nextU;
    U.correctBoundaryConditions();
    acceleration.primitiveFieldRef() = nextA/dt;
    acceleration.correctBoundaryConditions();
    for (label k = 0; k < m; ++k)
    {
        accelerationFlux -= gamma[k]*dGFlux_[k];
    }
    return true;
}


// ************************************************************************* //
