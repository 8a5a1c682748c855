/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- reading the phases
  (vheProperties: fluids, solids, their colours) and their fraction fields,
  and checking them
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::vheMixture::readPhases(const dictionary& dict, bool solid)
{
    const wordList allowed =
        solid
      ? wordList
        ({
            "rho", "mu", "nu", "G", "rigid", "motion", "velocity",
            "angularVelocity", "colours"
        })
              : wordList({"rho", "mu", "nu"});

    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << e.keyword() << "' in " << dict.dictName()
                << " is not a phase sub-dictionary" << nl
                << "    Expected: " << dict.dictName()
                << " { <name> { rho ...; nu ...;"
                << (solid ? " G ...;" : "") << " } }"
                << exit(FatalIOError);
        }
        const dictionary& pd = e.dict();
        const word& name = e.keyword();

        for (const phase& p : phases_)
        {
            if (p.name == name)
            {
                FatalIOErrorInFunction(pd)
                    << "Phase name '" << name << "' is used twice"
                    << exit(FatalIOError);
            }
        }
        for (const entry& pe : pd)
        {
            if (!allowed.found(pe.keyword()))
            {
                FatalIOErrorInFunction(pd)
                    << "Unknown entry '" << pe.keyword() << "' for "
                    << (solid ? "solid material " : "fluid phase ") << name
                    << nl << "    Valid entries: " << allowed
                    << exit(FatalIOError);
            }
        }

        const dimensionedScalar rho("rho", dimDensity, pd);
        if (rho.value() <= 0)
        {
            FatalIOErrorInFunction(pd)
                << "rho of " << name << " must be positive, got "
                << rho.value() << exit(FatalIOError);
        }

        // A rigid material has no modulus (its bodies move as rigid
        // bodies, rigidBodies; it carries no B*) and no viscosity (the
        // fluid beside its bodies shears, they do not: vhe_mixture)
        const bool rigid = solid && pd.getOrDefault<Switch>("rigid", false);
        const bool hasMu = pd.found("mu");
        const bool hasNu = pd.found("nu");
        if (!rigid && hasMu == hasNu)
        {
            FatalIOErrorInFunction(pd)
                << "Give exactly one of 'mu' [Pa s] or 'nu' [m2/s] for "
                << name << exit(FatalIOError);
        }
        const scalar visc =
            rigid ? 0
          : hasMu ? dimensionedScalar("mu", dimDynamicViscosity, pd).value()
          : dimensionedScalar("nu", dimViscosity, pd).value();
        if (visc < 0)
        {
            FatalIOErrorInFunction(pd)
                << "Viscosity of " << name << " must not be negative, got "
                << (hasMu ? "mu = " : "nu = ") << visc
                << exit(FatalIOError);
        }

        if (rigid && pd.found("G"))
        {
            FatalIOErrorInFunction(pd)
                << "G has no meaning for the rigid material " << name
                << ": remove it, or set rigid no" << exit(FatalIOError);
        }
        if (rigid && (hasMu || hasNu))
        {
            FatalIOErrorInFunction(pd)
                << (hasMu ? "mu" : "nu") << " has no meaning for the rigid"
                << " material " << name << ": its bodies do not shear, and"
                << " the fluid beside them gives the viscosity at their"
                << " surface; remove it" << exit(FatalIOError);
        }

        // A rigid material's bodies move freely (motion free), are held
        // in place (motion fixed: obstacles, a fixed bed, an array of
        // cylinders; a fixed body's fraction is its initial one for good)
        // or move as told (motion prescribed: stirrers, paddles, moving
        // walls; velocity and angularVelocity, Function1s of time, read
        // by rigidBodies)
        const word motion =
            solid ? pd.getOrDefault<word>("motion", "free") : word("free");
        if (motion != "free" && motion != "fixed" && motion != "prescribed")
        {
            FatalIOErrorInFunction(pd)
                << "motion of " << name << " must be free, fixed or"
                << " prescribed, got " << motion << exit(FatalIOError);
        }
        if (motion != "free" && !rigid)
        {
            FatalIOErrorInFunction(pd)
                << "motion " << motion << " holds a rigid body to a motion:"
                << " set rigid yes for " << name << exit(FatalIOError);
        }
        for (const word& k : {"velocity", "angularVelocity"})
        {
            if (pd.found(k) && motion != "prescribed")
            {
                FatalIOErrorInFunction(pd)
                    << k << " of " << name << " is a prescribed motion's:"
                    << " set motion prescribed, or remove it"
                    << exit(FatalIOError);
            }
        }

        scalar G = 0;
        if (solid && !rigid)
        {
            G = dimensionedScalar("G", dimPressure, pd).value();
            if (!(G > 0))
            {
                FatalIOErrorInFunction(pd)
                    << "Shear modulus G of " << name
                    << " must be positive, got " << G << exit(FatalIOError);
            }
            // Not a stiffer body but an overflow: the elastic viscosity
            // dt Ghat phi_s of the semi-implicit step enters the momentum
            // matrix, and the linear solvers' arithmetic on its
            // coefficients leaves double precision long before G does.
            // No material comes near (diamond: 5e11 Pa).
            const scalar Gmax = 1e20;
            if (!(G <= Gmax))
            {
                FatalIOErrorInFunction(pd)
                    << "Shear modulus G of " << name << " is " << G
                    << " Pa, above " << Gmax << " Pa: beyond any material,"
                    << " and the semi-implicit elastic viscosity dt G"
                    << " would overflow the momentum matrix"
                    << exit(FatalIOError);
            }
        }

        // Colours: given, or as many as there are alpha.<name>.<k> files
        label nColours = 1;
        if (solid && pd.found("colours"))
        {
            nColours = pd.get<label>("colours");
            if (nColours < 1 || nColours > 16)
            {
                FatalIOErrorInFunction(pd)
                    << "colours of " << name << " must lie in [1, 16], got "
                    << nColours << exit(FatalIOError);
            }
        }
        else if (solid)
        {
            const fileName timeDir(mesh_.time().timePath());
            auto present = [&](const label k)
            {
                const fileName f
                (
                    timeDir/word("alpha." + name + "." + Foam::name(k))
                );
                return isFile(f) || isFile(f + ".gz");
            };
            while (present(nColours)) ++nColours;
        }

        for (label k = 0; k < nColours; ++k)
        {
            phase p;
            p.name = k ? word(name + "." + Foam::name(k)) : name;
            p.material = name;
            p.colour = k;
            p.solid = solid;
            p.rigid = rigid;
            p.fixed = motion == "fixed";
            p.prescribed = motion == "prescribed";
            p.rho = rho.value();
            p.mu = hasMu ? visc : visc*rho.value();
            p.G = G;
            phases_.append(p);
        }
    }
}


void Foam::vheMixture::readAlphas()
{
    if (phases_.size() < 2) return;

    // Every alpha.* file present must name a phase of vheProperties: a
    // forgotten phase would silently carry volume nobody transports.
    const fileName timeDir(mesh_.time().timePath());
    for (const fileName& f : readDir(timeDir, fileName::FILE))
    {
        const word fw(f.name());
        if (fw.startsWith("alpha.") && !fw.hasExt("orig"))
        {
            const word phaseName(fw.substr(6));
            bool known = false;
            for (const phase& p : phases_) known = known || p.name == phaseName;
            if (!known)
            {
                FatalIOErrorInFunction(*this)
                    << "Field file " << timeDir/fw
                    << " names no phase of " << objectPath() << nl
                    << "    Phases: fluids and solids entries" << nl
                    << "    Either add '" << phaseName
                    << "' to vheProperties or remove the file"
                    << exit(FatalIOError);
            }
        }
    }

    alphas_.setSize(phases_.size());
    forAll(phases_, i)
    {
        const word name("alpha." + phases_[i].name);
        IOobject io(name, mesh_.time().timeName(), mesh_,
                    IOobject::MUST_READ, IOobject::AUTO_WRITE);
        if (phases_[i].colour > 0 && !io.typeHeaderOk<volScalarField>(true))
        {
            // A colour not yet used: empty, colour 0's boundary conditions
            const volScalarField& a0 = alphas_[i - phases_[i].colour];
            alphas_.set(i, new volScalarField(io, a0));
            alphas_[i] == dimensionedScalar(dimless, Zero);
            alphas_[i].oldTime();
            continue;
        }
        if (!io.typeHeaderOk<volScalarField>(true))
        {
            FatalIOErrorInFunction(*this)
                << "Phase '" << phases_[i].name << "' of " << objectPath()
                << " has no field file " << mesh_.time().timePath()/name
                << exit(FatalIOError);
        }
        alphas_.set(i, new volScalarField(io, mesh_));
        alphas_[i].oldTime();
    }
}


void Foam::vheMixture::checkAlphas() const
{
    if (alphas_.empty()) return;

    const scalar tol = 1e-6;
    scalarField sum(mesh_.nCells(), 0);
    for (const volScalarField& a : alphas_)
    {
        const scalar aMin = gMin(a.primitiveField());
        const scalar aMax = gMax(a.primitiveField());
        if (aMin < -tol || aMax > 1 + tol)
        {
            vheFieldFatalError(a.objectPath())
                << "Field " << a.objectPath() << " has values outside [0, 1]:"
                << " min " << aMin << ", max " << aMax
                << exit(FatalIOError);
        }
        sum += a.primitiveField();
    }
    const scalar sMin = gMin(sum), sMax = gMax(sum);
    if (sMin < 1 - tol || sMax > 1 + tol)
    {
        vheFieldFatalError(mesh_.time().timePath())
            << "The phase fractions alpha.* in "
            << mesh_.time().timePath() << " do not sum to 1:"
            << " sum ranges over [" << sMin << ", " << sMax << "]" << nl
            << "    Set them consistently (setFields, setBodies)"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
