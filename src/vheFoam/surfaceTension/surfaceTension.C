/*---------------------------------------------------------------------------*\
  vheFoam: surface tension between fluids
\*---------------------------------------------------------------------------*/

#include "surfaceTension.H"
#include "fvc.H"
#include "unitConversion.H"
#include "alphaContactAngleTwoPhaseFvPatchScalarField.H"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::surfaceTension::read()
{
    const dictionary& dict = mixture_;
    if (!dict.found("sigmas"))
    {
        return;
    }
    const List<vheMixture::phase>& phases = mixture_.phases();
    auto phaseIndex = [&](const word& name) -> label
    {
        forAll(phases, k)
        {
            if (phases[k].name == name || phases[k].material == name)
            {
                if (phases[k].solid)
                {
                    FatalIOErrorInFunction(dict)
                        << "sigmas: '" << name << "' is a solid; solids"
                        << " take no surface tension" << exit(FatalIOError);
                }
                return k;
            }
        }
        FatalIOErrorInFunction(dict)
            << "sigmas: unknown fluid '" << name << "'" << nl
            << "    Fluids: " << dict.subDict("fluids").toc()
            << exit(FatalIOError);
        return -1;
    };

    ITstream& is = dict.lookup("sigmas");
    token t(is);
    if (!t.isPunctuation() || t.pToken() != token::BEGIN_LIST)
    {
        FatalIOErrorInFunction(dict)
            << "sigmas: expected a list ( (fluid1 fluid2) sigma ... ),"
            << " got " << t << exit(FatalIOError);
    }
    while (true)
    {
        token next(is);
        if (next.isPunctuation() && next.pToken() == token::END_LIST)
        {
            break;
        }
        if (is.eof() || !next.good())
        {
            FatalIOErrorInFunction(dict)
                << "sigmas: the list is not closed" << exit(FatalIOError);
        }
        is.putBack(next);
        const wordList names(is);
        if (names.size() != 2 || names[0] == names[1])
        {
            FatalIOErrorInFunction(dict)
                << "sigmas: a pair is two different fluids, got " << names
                << exit(FatalIOError);
        }
        token d(is);
        is.putBack(d);
        if (d.isPunctuation() && d.pToken() == token::BEGIN_SQR)
        {
            const dimensionSet dims(is);
            if (dims != dimMass/sqr(dimTime))
            {
                FatalIOErrorInFunction(dict)
                    << "sigmas: " << names << " has dimensions " << dims
                    << ", a surface tension has " << dimMass/sqr(dimTime)
                    << exit(FatalIOError);
            }
        }
        const scalar sigma = readScalar(is);
        if (sigma < 0)
        {
            FatalIOErrorInFunction(dict)
                << "sigmas: " << names << " must not be negative, got "
                << sigma << exit(FatalIOError);
        }
        pair p{phaseIndex(names[0]), phaseIndex(names[1]), sigma};
        for (const pair& q : pairs_)
        {
            if ((q.i == p.i && q.j == p.j) || (q.i == p.j && q.j == p.i))
            {
                FatalIOErrorInFunction(dict)
                    << "sigmas: " << names << " is given twice"
                    << exit(FatalIOError);
            }
        }
        if (sigma > 0)
        {
            pairs_.append(p);
        }
    }
}


void Foam::surfaceTension::correctContactAngle
(
    const pair& p,
    surfaceVectorField::Boundary& nHatb,
    const surfaceVectorField::Boundary& gradAlphaf
) const
{
    const fvMesh& mesh = U_.mesh();
    const fvBoundaryMesh& boundary = mesh.boundary();
    const PtrList<volScalarField>& alphas = mixture_.alphas();

    forAll(boundary, patchi)
    {
        // The angle of phase i, or of phase j (its normal is -n)
        for (const label k : {p.i, p.j})
        {
            const fvPatchScalarField& ap = alphas[k].boundaryField()[patchi];
            if (!isA<alphaContactAngleTwoPhaseFvPatchScalarField>(ap))
            {
                continue;
            }
            auto& acap = const_cast<alphaContactAngleTwoPhaseFvPatchScalarField&>
            (
                refCast<const alphaContactAngleTwoPhaseFvPatchScalarField>(ap)
            );
            const scalar s = (k == p.i ? 1 : -1);
            fvsPatchVectorField& nHatp = nHatb[patchi];
            vectorField nk(s*nHatp);

            const scalarField theta
            (
                degToRad()*acap.theta(U_.boundaryField()[patchi], nHatp)
            );
            const vectorField nf(boundary[patchi].nf());

            // As interFoam (interfaceProperties::correctContactAngle): the
            // normal turned in the plane of n and the wall normal so that
            // it makes the angle theta with the wall
            const scalarField a12(nk & nf);
            const scalarField b1(cos(theta));
            scalarField b2(nk.size());
            forAll(b2, facei)
            {
                b2[facei] = cos(acos(a12[facei]) - theta[facei]);
            }
            const scalarField det(1.0 - a12*a12);
            const scalarField a((b1 - a12*b2)/det);
            const scalarField b((b2 - a12*b1)/det);

            nk = a*nf + b*nk;
            nk /= (mag(nk) + mixture_.deltaN().value());

            acap.gradient() = (nf & nk)*mag(gradAlphaf[patchi]);
            acap.evaluate();

            nHatp = s*nk;
            break;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructor  * * * * * * * * * * * * * * //

Foam::surfaceTension::surfaceTension
(
    const vheMixture& mixture,
    const volVectorField& U
)
:
    mixture_(mixture),
    U_(U),
    hf_(U.mesh())
{
    read();
    if (!active())
    {
        return;
    }
    Info<< "Surface tension (height-function curvature, balanced force):" << nl;
    for (const pair& p : pairs_)
    {
        Info<< "    (" << mixture_.phases()[p.i].name << ' '
            << mixture_.phases()[p.j].name << ") " << p.sigma << " N/m"
            << nl;
    }
    Info<< "    capillary step limit " << maxDeltaT() << " s" << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volScalarField> Foam::surfaceTension::K(const pair& p) const
{
    const fvMesh& mesh = U_.mesh();
    const volScalarField& ai = mixture_.alphas()[p.i];
    const volScalarField& aj = mixture_.alphas()[p.j];

    // The pair's face normal, toward phase i: interFoam's
    // interpolate(grad(alpha1)) when alpha_j = 1 - alpha_i
    const surfaceScalarField aif(fvc::interpolate(ai));
    const surfaceScalarField ajf(fvc::interpolate(aj));
    const surfaceVectorField gradAlphaf
    (
        ajf*fvc::interpolate(fvc::grad(ai, "nHat"))
      - aif*fvc::interpolate(fvc::grad(aj, "nHat"))
    );
    surfaceVectorField nHatfv
    (
        gradAlphaf/(mag(gradAlphaf) + mixture_.deltaN())
    );
    correctContactAngle(p, nHatfv.boundaryFieldRef(), gradAlphaf.boundaryField());

    return tmp<volScalarField>::New
    (
        "K." + mixture_.phases()[p.i].name + "." + mixture_.phases()[p.j].name,
        -fvc::div(nHatfv & mesh.Sf())
    );
}


Foam::tmp<Foam::surfaceScalarField> Foam::surfaceTension::force() const
{
    const fvMesh& mesh = U_.mesh();
    tmp<surfaceScalarField> tf
    (
        surfaceScalarField::New
        (
            "surfaceTensionForce",
            mesh,
            dimensionedScalar(dimForce/dimVolume, Zero)
        )
    );
    for (const pair& p : pairs_)
    {
        const volScalarField& ai = mixture_.alphas()[p.i];
        const volScalarField& aj = mixture_.alphas()[p.j];
        const dimensionedScalar sigma("sigma", dimMass/sqr(dimTime), p.sigma);
        // The face curvature: the height functions' where a cell of the
        // face has one (their mean if both have), else the continuum
        // surface force's
        const volScalarField Kcsf(K(p));
        volScalarField Khf("Khf", Kcsf*0);
        volScalarField valid("valid", ai*0);
        hf_.curvature(ai, Khf, valid);
        // Beside a contact-angle wall the angle is the continuum surface
        // force's (its wall normal, correctContactAngle): the heights there
        // would not know it.  Two layers of cells.
        forAll(mesh.boundary(), patchi)
        {
            if
            (
                !isA<alphaContactAngleTwoPhaseFvPatchScalarField>
                (
                    ai.boundaryField()[patchi]
                )
             && !isA<alphaContactAngleTwoPhaseFvPatchScalarField>
                (
                    aj.boundaryField()[patchi]
                )
            )
            {
                continue;
            }
            for (const label c : mesh.boundary()[patchi].faceCells())
            {
                valid[c] = 0;
                for (const label n : mesh.cellCells()[c]) valid[n] = 0;
            }
        }
        valid.correctBoundaryConditions();
        const surfaceScalarField validf(fvc::interpolate(valid));
        surfaceScalarField Kf(fvc::interpolate(Kcsf));
        const surfaceScalarField Kvalid(fvc::interpolate(Khf*valid));
        Kf.primitiveFieldRef() = pos(validf.primitiveField() - SMALL)
            *Kvalid.primitiveField()/max(validf.primitiveField(), SMALL)
          + neg0(validf.primitiveField() - SMALL)*Kf.primitiveField();
        forAll(Kf.boundaryField(), patchi)
        {
            scalarField& kb = Kf.boundaryFieldRef()[patchi];
            const scalarField& vb = validf.boundaryField()[patchi];
            const scalarField& kvb = Kvalid.boundaryField()[patchi];
            kb = pos(vb - SMALL)*kvb/max(vb, SMALL) + neg0(vb - SMALL)*kb;
        }
        tf.ref() +=
            sigma*Kf
           *(
                fvc::interpolate(aj)*fvc::snGrad(ai)
              - fvc::interpolate(ai)*fvc::snGrad(aj)
            );
    }
    return tf;
}


Foam::scalar Foam::surfaceTension::maxDeltaT() const
{
    if (!active())
    {
        return GREAT;
    }
    const fvMesh& mesh = U_.mesh();
    const scalar dx = 1/gMax(mesh.deltaCoeffs().primitiveField());
    scalar dt = GREAT;
    for (const pair& p : pairs_)
    {
        const scalar rhoAvg =
            0.5*(mixture_.phases()[p.i].rho + mixture_.phases()[p.j].rho);
        dt = min(dt, sqrt(rhoAvg*pow3(dx)/(constant::mathematical::twoPi*p.sigma)));
    }
    return dt;
}


// ************************************************************************* //
