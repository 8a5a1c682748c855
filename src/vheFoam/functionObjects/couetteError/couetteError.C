/*---------------------------------------------------------------------------*\
  vheFoam: error against the exact oscillating Couette solution
\*---------------------------------------------------------------------------*/

#include "couetteError.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(couetteError, 0);
    addToRunTimeSelectionTable(functionObject, couetteError, dictionary);
}
}


void Foam::functionObjects::couetteError::writeFileHeader(Ostream& os)
{
    writeHeader(os, "Error against the exact oscillating Couette solution");
    writeHeaderValue(os, "window", Pair<scalar>(tStart_, tEnd_));
    writeCommented(os, "Time");
    for
    (
        const char* col :
        {"L2_u", "max_u", "L2_Bxy", "max_Bxy",
         "window_rmsL2_u", "window_max_u", "window_rmsL2_Bxy",
         "window_max_Bxy"}
    )
    {
        writeTabbed(os, col);
    }
    os << endl;
}


Foam::functionObjects::couetteError::couetteError
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict),
    tStart_(0),
    tEnd_(GREAT),
    solidCells_(0.999),
    sumU2_(0), sumB2_(0), maxU_(0), maxB_(0), span_(0)
{
    read(dict);
    writeFileHeader(file());
}


bool Foam::functionObjects::couetteError::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    const List<FixedList<scalar, 4>> layers
    (
        dict.get<List<FixedList<scalar, 4>>>("layers")
    );
    const label n = layers.size();
    List<scalar> h(n), rho(n), mu(n), G(n);
    forAll(layers, j)
    {
        h[j] = layers[j][0]; rho[j] = layers[j][1];
        mu[j] = layers[j][2]; G[j] = layers[j][3];
    }
    if
    (
        vhe_couette_setup
        (
            &exact_, n, h.cdata(), rho.cdata(), mu.cdata(), G.cdata(),
            dict.get<scalar>("V"), dict.get<scalar>("omega")
        ) != VHE_OK
    )
    {
        FatalIOErrorInFunction(dict)
            << "Invalid layers (h rho mu G with h, rho > 0, mu, G >= 0; at"
            << " most " << VHE_COUETTE_MAX_LAYERS << ") or omega <= 0"
            << exit(FatalIOError);
    }
    const Pair<scalar> window(dict.get<Pair<scalar>>("window"));
    tStart_ = window.first();
    tEnd_ = window.second();
    solidCells_ = dict.getOrDefault<scalar>("solidCells", 0.999);
    return true;
}


bool Foam::functionObjects::couetteError::execute()
{
    return true;
}


bool Foam::functionObjects::couetteError::write()
{
    const scalar t = time_.value();
    const volVectorField& U = lookupObject<volVectorField>("U");
    const volVectorField& C = mesh_.C();
    const scalarField& V = mesh_.V();

    scalar sumV = 0, sumEu2 = 0, maxEu = 0;
    scalar sumVs = 0, sumEb2 = 0, maxEb = 0;

    const volScalarField* phis = findObject<volScalarField>("phis");
    const volSymmTensorField* Bstar =
        findObject<volSymmTensorField>("Bstar");

    forAll(U, c)
    {
        double u, gamma;
        vhe_couette_eval(&exact_, C[c].y(), t, &u, &gamma);
        const scalar eu = U[c].x() - u;
        sumV += V[c];
        sumEu2 += V[c]*eu*eu;
        maxEu = max(maxEu, mag(eu));
        if (phis && Bstar && (*phis)[c] >= solidCells_)
        {
            const scalar eb = (*Bstar)[c].xy()/sqrt((*phis)[c]) - gamma;
            sumVs += V[c];
            sumEb2 += V[c]*eb*eb;
            maxEb = max(maxEb, mag(eb));
        }
    }
    reduce(sumV, sumOp<scalar>());
    reduce(sumEu2, sumOp<scalar>());
    reduce(maxEu, maxOp<scalar>());
    reduce(sumVs, sumOp<scalar>());
    reduce(sumEb2, sumOp<scalar>());
    reduce(maxEb, maxOp<scalar>());

    const scalar L2u = sqrt(sumEu2/sumV);
    const scalar L2b = sumVs > 0 ? sqrt(sumEb2/sumVs) : 0;

    if (t >= tStart_ - 0.5*time_.deltaTValue() && t <= tEnd_ + SMALL)
    {
        const scalar dt = time_.deltaTValue();
        sumU2_ += dt*L2u*L2u;
        sumB2_ += dt*L2b*L2b;
        span_ += dt;
        maxU_ = max(maxU_, maxEu);
        maxB_ = max(maxB_, maxEb);
    }
    const scalar rmsU = span_ > 0 ? sqrt(sumU2_/span_) : 0;
    const scalar rmsB = span_ > 0 ? sqrt(sumB2_/span_) : 0;

    if (Pstream::master())
    {
        writeCurrentTime(file());
        file()
            << tab << L2u << tab << maxEu << tab << L2b << tab << maxEb
            << tab << rmsU << tab << maxU_ << tab << rmsB << tab << maxB_
            << endl;
    }
    return true;
}


// ************************************************************************* //
