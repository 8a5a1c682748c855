/*---------------------------------------------------------------------------*\
  vheFoam: phase-averaged gas/liquid/solid mixture -- the fields one alpha
  step transports: each active fluid, each colour of a solid that meets
  another colour, and the sum of a material's colours that meet none
\*---------------------------------------------------------------------------*/

#include "vheMixture.H"
#include "colourShares.H"
#include "HashTable.H"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

void Foam::vheMixture::selectTransported
(
    const labelList& active,
    transported& t
)
{
    // The fields MULES transports.  A solid material with two or more
    // active colours: each colour that meets another (bodies of two
    // colours touching) is a phase of its own, compressed against the
    // colours it meets; the colours that meet none are transported as one
    // phase, their sum, and carried on its flux afterwards (colourShares).
    // Fields of one material that do not meet are not compressed against
    // each other (their compression is below 1e-10).
    HashTable<labelList, word> coloursOf;
    wordList materials;
    for (const label i : active)
    {
        if (!phases_[i].solid) continue;
        if (!coloursOf.found(phases_[i].material))
        {
            materials.append(phases_[i].material);
        }
        coloursOf(phases_[i].material).append(i);
    }
    const label nMax = active.size() + materials.size();
    t.fields.setSize(nMax);
    t.rho.setSize(nMax);
    t.elastic.setSize(nMax);
    t.solid.setSize(nMax);
    t.carried.setSize(nMax);
    t.sums.setSize(nMax);
    labelList matOf(nMax, -1);          // material (index), -1: a fluid
    labelList colOf(nMax, -1);          // colour in meet (-1: meets none)
    List<labelList> meets(materials.size());
    label n = 0;
    const auto add = [&](volScalarField* f, const phase& ph, label m, label c)
    {
        t.fields.set(n, f);
        t.rho[n] = ph.rho;
        t.elastic[n] = ph.solid && !ph.rigid;  // B* is carried with elastic solids
        t.solid[n] = ph.solid;
        matOf[n] = m;
        colOf[n] = c;
        return n++;
    };
    for (const label i : active)
    {
        const phase& ph = phases_[i];
        if (!ph.solid)
        {
            add(&alphas_[i], ph, -1, -1);
            continue;
        }
        const label m = materials.find(ph.material);
        const labelList& cols = coloursOf[ph.material];
        if (cols[0] != i) continue;     // the material's first colour adds all
        const label K = cols.size();
        if (K == 1)
        {
            add(&alphas_[i], ph, m, -1);
            continue;
        }
        UPtrList<volScalarField> colours(K);
        forAll(cols, k) colours.set(k, &alphas_[cols[k]]);
        meets[m] = colourShares::meeting(colours);
        labelList lump;
        for (label k = 0; k < K; ++k)
        {
            bool meetsAny = false;
            for (label l = 0; l < K; ++l) meetsAny = meetsAny || meets[m][k*K + l];
            if (meetsAny) add(&alphas_[cols[k]], ph, m, k);
            else lump.append(cols[k]);
        }
        if (lump.size() == 1)
        {
            add(&alphas_[lump[0]], ph, m, -1);
        }
        else if (lump.size() > 1)
        {
            // Their sum, old time first, with colour 0's boundary types
            const auto sumOf = [&](const bool old)
            {
                tmp<volScalarField> tsum
                (
                    new volScalarField
                    (
                        IOobject
                        (
                            "alpha." + ph.material + ".sum",
                            mesh_.time().timeName(), mesh_,
                            IOobject::NO_READ, IOobject::NO_WRITE, false
                        ),
                        mesh_,
                        dimensionedScalar(dimless, Zero),
                        alphas_[i].boundaryField().types()
                    )
                );
                volScalarField& sum = tsum.ref();
                for (const label c : lump)
                {
                    const volScalarField& ac =
                        old ? alphas_[c].oldTime() : alphas_[c];
                    sum.primitiveFieldRef() += ac.primitiveField();
                    forAll(sum.boundaryField(), patchi)
                    {
                        sum.boundaryFieldRef()[patchi] ==
                            sum.boundaryField()[patchi]
                          + ac.boundaryField()[patchi];
                    }
                }
                return tsum;
            };
            t.sums.set(n, sumOf(true));
            t.sums[n].oldTime();
            t.sums[n] == sumOf(false)();
            t.carried[n] = lump;
            add(&t.sums[n], ph, m, -1);
        }
    }
    t.fields.setSize(n);
    t.rho.setSize(n);
    t.elastic.setSize(n);
    t.solid.setSize(n);
    t.carried.setSize(n);
    t.sums.setSize(n);

    // The pairs of fields compressed against each other
    t.pairOn = List<bool>(n*(n - 1)/2, true);
    for (label i = 0; i < n; ++i)
    {
        for (label j = i + 1; j < n; ++j)
        {
            const label m = matOf[i];
            if (m < 0 || matOf[j] != m) continue;
            const label K = coloursOf[materials[m]].size();
            t.pairOn[pairIndex(i, j, n)] =
                colOf[i] >= 0 && colOf[j] >= 0
             && meets[m][colOf[i]*K + colOf[j]];
        }
    }

}


// ************************************************************************* //
