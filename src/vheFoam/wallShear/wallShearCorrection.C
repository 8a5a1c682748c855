#include "wallShearCorrection.H"
#include "fvMesh.H"

Foam::tmp<Foam::volVectorField> Foam::wallShearCorrection
(
    const volVectorField& U,
    const volScalarField& mu,
    const volTensorField& gradU
)
{
    const fvMesh& mesh = U.mesh();
    tmp<volVectorField> tcorr
    (
        new volVectorField
        (
            IOobject("wallShearCorrection", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(mu.dimensions()*dimVelocity/dimArea, Zero)
        )
    );
    vectorField& corr = tcorr.ref().primitiveFieldRef();
    const scalarField& V = mesh.V();
    forAll(U.boundaryField(), patchi)
    {
        const fvPatchVectorField& Up = U.boundaryField()[patchi];
        if (Up.coupled() || !Up.fixesValue()) continue;
        const fvPatch& p = Up.patch();
        const labelUList& fc = p.faceCells();
        const vectorField n(p.nf());
        const scalarField& magSf = p.magSf();
        const scalarField& dc = p.deltaCoeffs();
        const scalarField& muw = mu.boundaryField()[patchi];
        forAll(fc, i)
        {
            const label P = fc[i];
            const vector halfCell = dc[i]*(Up[i] - U[P]);
            corr[P] +=
                (2.0/3.0)*muw[i]*magSf[i]*(halfCell - (n[i] & gradU[P]))
               /V[P];
        }
    }
    return tcorr;
}
