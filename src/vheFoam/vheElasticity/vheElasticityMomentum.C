/*---------------------------------------------------------------------------*\
  vheFoam: the elastic part of the phase-averaged model
  the elastic terms of the momentum equation
\*---------------------------------------------------------------------------*/

#include "vheElasticity.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "zeroGradientFvPatchFields.H"
#include "polyPatch.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "vhe.h"
#include "vheFlat.H"
#include "linearFaceValues.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The words of a scheme entry (Gauss linear corrected -> three words)
Foam::wordList schemeWords(Foam::ITstream& is)
{
    Foam::wordList words;
    forAll(is, i)
    {
        if (is[i].isWord()) words.append(is[i].wordToken());
    }
    is.rewind();
    return words;
}

//- The internal faces with a cell of the set on either side, each once
//  (by the set's cells: a scan of every face cost more than the sums)
Foam::labelList facesOf(const Foam::fvMesh& mesh, const Foam::boolList& in)
{
    const Foam::label nInt = mesh.nInternalFaces();
    const Foam::labelUList& own = mesh.owner();
    Foam::DynamicList<Foam::label> faces;
    forAll(in, c)
    {
        if (!in[c]) continue;
        for (const Foam::label f : mesh.cells()[c])
        {
            if (f >= nInt) continue;
            const bool owner = own[f] == c;
            if (owner || !in[own[f]]) faces.append(f);
        }
    }
    return Foam::labelList(std::move(faces));
}

} // End anonymous namespace


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::cellVectorField
(
    const word& name,
    const dimensionSet& dims
) const
{
    return tmp<volVectorField>
    (
        new volVectorField
        (
            IOobject
            (
                name, mesh_.time().timeName(), mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            ),
            mesh_,
            dimensionedVector(dims, Zero),
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muElastic
(
    scalar deltaT
) const
{
    // The stress increment's viscosity where the body's stress lives
    // (vhe_body_weight): none in the cells whose centre lies a quarter of
    // a cell or more outside its outline, as their stress is none.  Their
    // faces with the body's cells keep half of it (the linear face value),
    // as their face stress keeps half of the body's.
    tmp<volScalarField> tmu
    (
        new volScalarField
        (
            "muElastic",
            dimensionedScalar("deltaT", dimTime, stressStep(deltaT))
           *mixture_.Ghat()*mixture_.phis()
        )
    );
    const auto weigh = [](scalarField& mu, const scalarField& phis)
    {
        forAll(mu, i)
        {
            mu[i] *= vhe_body_weight(phis[i]);
        }
    };
    volScalarField& mu = tmu.ref();
    const volScalarField& phis = mixture_.phis();
    weigh(mu.primitiveFieldRef(), phis.primitiveField());
    forAll(mu.boundaryField(), patchi)
    {
        weigh(mu.boundaryFieldRef()[patchi], phis.boundaryField()[patchi]);
    }
    return tmu;
}


Foam::tmp<Foam::volScalarField> Foam::vheElasticity::muEff
(
    scalar deltaT
) const
{
    if (semiImplicit_)
    {
        return mixture_.mu() + muElastic(deltaT);
    }
    return tmp<volScalarField>(new volScalarField("muEff", mixture_.mu()));
}


Foam::tmp<Foam::volSymmTensorField> Foam::vheElasticity::explicitStress
(
    const volVectorField& U,
    scalar deltaT
) const
{
    if (!backward_)
    {
        return sigma();
    }
    // The stress of the new step's B*, B*^(n+1) = Bhat + tau (L B* +
    // B* L^T): the part linear about phi_s^(1/2) I is the implicit
    // viscosity muElastic, the rest, tau (L A + A L^T) with A = Bhat -
    // phi_s^(1/2) I, is taken with the current velocity gradient (an
    // O(dt^2) error per step, where linearising about I would leave
    // O(dt) at finite strain)
    symmTensorField Bs(predictorBstar());
    const tensorField gradU
    (
        dev(velocityGradient(U, deltaT)().primitiveField())
    );
    const tensorField L(gradU.T());
    const scalarField& phis = mixture_.phis().primitiveField();
    const scalar tau = stressStep(deltaT);
    forAll(Bs, celli)
    {
        if (phis[celli] <= mixture_.solidFractionMin()) continue;
        const symmTensor A(Bs[celli] - sqrt(phis[celli])*I);
        Bs[celli] += tau*twoSymm(L[celli] & A);
    }
    return stressOf(Bs);
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::divSigma
(
    const volSymmTensorField& sig,
    const volScalarField& muEff
) const
{
    if (stabilisation_ > 0)
    {
        return fvc::surfaceIntegrate(mesh_.Sf() & faceStress(sig, muEff));
    }

    // fvc::div(sig) over the faces of the cells with stress (none outside
    // the bodies), for Gauss linear; any other scheme by fvc::div
    const word name("div(sigma)");
    if (schemeWords(mesh_.divScheme(name)) != wordList{"Gauss", "linear"})
    {
        return fvc::div(sig, name);
    }
    tmp<volVectorField> tD
    (
        cellVectorField("divSigma", sig.dimensions()/dimLength)
    );
    vectorField& D = tD.ref().primitiveFieldRef();
    const symmTensorField& S = sig.primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const scalarField& w = mesh_.weights().primitiveField();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    boolList stressed(S.size());
    forAll(S, c)
    {
        stressed[c] = S[c] != symmTensor::zero;
    }
    for (const label f : facesOf(mesh_, stressed))
    {
        const label o = own[f], n = nei[f];
        const vector flux(Sf[f] & (w[f]*S[o] + (1 - w[f])*S[n]));
        D[o] += flux;
        D[n] -= flux;
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const fvPatchSymmTensorField& Sb = sig.boundaryField()[patchi];
        if (!p.size() || !Sb.size()) continue;
        const symmTensorField Sp(linearFaceValues(Sb));
        const labelUList& fc = p.faceCells();
        const vectorField& pSf = p.Sf();
        forAll(fc, i)
        {
            D[fc[i]] += pSf[i] & Sp[i];
        }
    }
    D /= mesh_.V();
    tD.ref().correctBoundaryConditions();
    return tD;
}


Foam::tmp<Foam::volVectorField> Foam::vheElasticity::explicitDiffusion
(
    const volScalarField& muEl,
    const volVectorField& U
) const
{
    // fvc::laplacian(muEl, U) with the scheme of laplacian(mu,U), over the
    // faces where muEl acts: it is zero outside the bodies, and the whole
    // mesh's Laplacian (face interpolation, snGrad, its correction's
    // interpolated gradient) cost as much as the momentum equation's
    // other explicit terms together (scene B, four spheres).  Gauss linear
    // with a corrected, uncorrected or orthogonal snGrad is evaluated
    // here; any other scheme by fvc::laplacian
    const word name("laplacian(mu,U)");
    const wordList words(schemeWords(mesh_.laplacianScheme(name)));
    const bool fast =
        words.size() == 3 && words[0] == "Gauss" && words[1] == "linear"
     && (
            words[2] == "corrected" || words[2] == "uncorrected"
         || words[2] == "orthogonal"
        );
    if (!fast)
    {
        return fvc::laplacian(muEl, U, name);
    }
    const bool orthogonal = words[2] == "orthogonal";
    const scalarField& mu = muEl.primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();

    // The faces where muEl acts; the correction of a corrected scheme only
    // where some of them are not orthogonal (on any rank: its gradient
    // exchanges across processor patches)
    boolList viscous(mu.size());
    forAll(mu, c)
    {
        viscous[c] = mu[c] != 0;
    }
    const labelList faces(facesOf(mesh_, viscous));
    bool correct = false;
    if (words[2] == "corrected")
    {
        const surfaceVectorField& k = mesh_.nonOrthCorrectionVectors();
        for (const label f : faces)
        {
            correct = correct || magSqr(k[f]) > 0;
        }
        forAll(mesh_.boundary(), patchi)
        {
            if (mesh_.boundary()[patchi].coupled())
            {
                correct =
                    correct || max(magSqr(k.boundaryField()[patchi])) > 0;
            }
        }
        reduce(correct, orOp<bool>());
    }

    tmp<volVectorField> tL
    (
        cellVectorField
        (
            "explicitDiffusion", muEl.dimensions()*U.dimensions()/dimArea
        )
    );
    vectorField& L = tL.ref().primitiveFieldRef();
    const vectorField& Ui = U.primitiveField();
    // the correction's gradient: grad(U), as the scheme's (cached)
    const tmp<volTensorField> tgradU
    (
        correct ? fvc::grad(U) : tmp<volTensorField>()
    );
    const tensorField& G =
        correct ? tgradU().primitiveField() : tensorField::null();
    const scalarField& w = mesh_.weights().primitiveField();
    const scalarField& magSf = mesh_.magSf().primitiveField();
    const scalarField& dc =
        orthogonal
      ? mesh_.deltaCoeffs().primitiveField()
      : mesh_.nonOrthDeltaCoeffs().primitiveField();
    for (const label f : faces)
    {
        const label o = own[f], n = nei[f];
        vector g(dc[f]*(Ui[n] - Ui[o]));
        if (correct)
        {
            g += mesh_.nonOrthCorrectionVectors()[f]
               & (w[f]*G[o] + (1 - w[f])*G[n]);
        }
        const vector flux((w[f]*mu[o] + (1 - w[f])*mu[n])*magSf[f]*g);
        L[o] += flux;
        L[n] -= flux;
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const fvPatchScalarField& mub = muEl.boundaryField()[patchi];
        if (!p.size() || !mub.size()) continue;
        const scalarField mup(linearFaceValues(mub));
        if (max(mag(mup)) == 0) continue;   // (each rank its own patches)
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        vectorField g
        (
            p.coupled()
          ? Up.snGrad
            (
                orthogonal
              ? mesh_.deltaCoeffs().boundaryField()[patchi]
              : mesh_.nonOrthDeltaCoeffs().boundaryField()[patchi]
            )
          : Up.snGrad()
        );
        if (correct && p.coupled())
        {
            g += mesh_.nonOrthCorrectionVectors().boundaryField()[patchi]
               & linearFaceValues(tgradU().boundaryField()[patchi]);
        }
        const labelUList& fc = p.faceCells();
        const scalarField& pMagSf = p.magSf();
        forAll(fc, i)
        {
            L[fc[i]] += mup[i]*pMagSf[i]*g[i];
        }
    }
    L /= mesh_.V();
    tL.ref().correctBoundaryConditions();
    return tL;
}


// ************************************************************************* //
