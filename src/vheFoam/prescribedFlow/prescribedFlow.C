/*---------------------------------------------------------------------------*\
  vheFoam: a prescribed velocity, for verification of the transport
\*---------------------------------------------------------------------------*/

#include "prescribedFlow.H"

Foam::prescribedFlow::prescribedFlow
(
    const fvMesh& mesh,
    const dictionary& pimple
)
:
    active_(pimple.found("prescribedVelocity")),
    flow_()
{
    if (!active_) return;
    const dictionary& d = pimple.subDict("prescribedVelocity");
    const word type(d.get<word>("type"));
    if (type == "translation")
    {
        const vector U(d.get<vector>("U"));
        flow_.kind = VHE_FLOW_TRANSLATION;
        flow_.U[0] = U.x();
        flow_.U[1] = U.y();
    }
    else if (type == "rotation")
    {
        const vector o(d.get<vector>("origin"));
        flow_.kind = VHE_FLOW_ROTATION;
        flow_.omega = d.get<scalar>("omega");
        flow_.origin[0] = o.x();
        flow_.origin[1] = o.y();
    }
    else if (type == "singleVortex")
    {
        flow_.kind = VHE_FLOW_SINGLE_VORTEX;
        flow_.period = d.get<scalar>("period");
        if (!(flow_.period > 0))
        {
            FatalIOErrorInFunction(d)
                << "period must be > 0, got " << flow_.period
                << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(d)
            << "Unknown prescribedVelocity type '" << type << "'" << nl
            << "    Valid: (translation rotation singleVortex)"
            << exit(FatalIOError);
    }
    const Vector<label> solD(mesh.solutionD());
    if (mesh.nSolutionD() != 2 || solD.z() > 0)
    {
        FatalIOErrorInFunction(d)
            << "prescribedVelocity needs a 2D case with z the empty"
            << " direction" << exit(FatalIOError);
    }
    Info<< "Prescribed velocity: " << type
        << " (momentum and pressure are not solved)" << endl;
}


void Foam::prescribedFlow::set
(
    volVectorField& U,
    surfaceScalarField& phi,
    scalar t
) const
{
    const fvMesh& mesh = U.mesh();
    const pointField& pts = mesh.points();
    const faceList& faces = mesh.faces();

    // depth x (psi(b) - psi(a)), a and b the face's end points in the
    // x-y plane, ordered so that the right normal of a -> b is along S_f
    auto psiFlux = [&](label facei, const vector& Sf)
    {
        const face& f = faces[facei];
        const scalar zc = mesh.faceCentres()[facei].z();
        point ab[2];
        label n = 0;
        forAll(f, i)
        {
            if (pts[f[i]].z() < zc && n < 2) ab[n++] = pts[f[i]];
        }
        if (n < 2) return scalar(0);
        vector e(ab[1] - ab[0]);
        e.z() = 0;
        if (e.y()*Sf.x() - e.x()*Sf.y() < 0)
        {
            Swap(ab[0], ab[1]);
        }
        return mag(Sf)/mag(e)
           *(
               vhe_flow_psi(&flow_, ab[1].v_, t)
             - vhe_flow_psi(&flow_, ab[0].v_, t)
            );
    };

    scalarField& phiI = phi.primitiveFieldRef();
    forAll(phiI, facei)
    {
        phiI[facei] = psiFlux(facei, mesh.Sf()[facei]);
    }
    forAll(phi.boundaryField(), patchi)
    {
        fvsPatchScalarField& pp = phi.boundaryFieldRef()[patchi];
        const label start = mesh.boundaryMesh()[patchi].start();
        forAll(pp, i)
        {
            pp[i] = psiFlux(start + i, mesh.Sf().boundaryField()[patchi][i]);
        }
    }

    vectorField& UI = U.primitiveFieldRef();
    forAll(UI, celli)
    {
        vhe_flow_u(&flow_, mesh.C()[celli].v_, t, UI[celli].v_);
    }
    U.correctBoundaryConditions();
}


// ************************************************************************* //
