/*---------------------------------------------------------------------------*\
  vheFoam: the coupled step's kept matrix -- whether a new solve's matrix
  is the kept one, or has its nonzero pattern
\*---------------------------------------------------------------------------*/

#include "coupledStepPETSc.H"

#include <algorithm>
#include <cstring>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coupledStepPETSc::samePattern(Mat A) const
{
    bool same = A_ != nullptr;
    if (same)
    {
        PetscInt m0, n0, m1, n1;
        MatGetLocalSize(A_, &m0, &n0);
        MatGetLocalSize(A, &m1, &n1);
        same = m0 == m1 && n0 == n1;
    }
    if (same)
    {
        PetscInt r0, r1;
        MatGetOwnershipRange(A, &r0, &r1);
        for (PetscInt r = r0; same && r < r1; ++r)
        {
            PetscInt n0, n1;
            const PetscInt *c0, *c1;
            MatGetRow(A_, r, &n0, &c0, nullptr);
            MatGetRow(A, r, &n1, &c1, nullptr);
            same = n0 == n1;
            for (PetscInt k = 0; same && k < n0; ++k)
            {
                same = c0[k] == c1[k];
            }
            MatRestoreRow(A, r, &n1, &c1, nullptr);
            MatRestoreRow(A_, r, &n0, &c0, nullptr);
        }
    }
    return returnReduce(same, andOp<bool>());
}


bool Foam::coupledStepPETSc::sameMatrix
(
    const fvMatrix<vector>& UEqn,
    const volScalarField& rho,
    const volScalarField* muT,
    const coupledRigidRows* rigid
)
{
    DynamicList<scalar> key
    (
        2*UEqn.diag().size() + 2*UEqn.upper().size() + 16
    );
    key.append(scalar(mesh_.time().timeIndex()));
    key.append(UEqn.diag());
    key.append(UEqn.upper());
    key.append(UEqn.lower());
    forAll(mesh_.boundary(), patchi)
    {
        for (const vector& v : UEqn.internalCoeffs()[patchi])
        {
            key.append(v.x()); key.append(v.y()); key.append(v.z());
        }
        for (const vector& v : UEqn.boundaryCoeffs()[patchi])
        {
            key.append(v.x()); key.append(v.y()); key.append(v.z());
        }
        key.append(rho.boundaryField()[patchi]);
        if (muT) key.append(muT->boundaryField()[patchi]);
    }
    key.append(rho.primitiveField());
    if (muT) key.append(muT->primitiveField());
    if (rigid)
    {
        key.append(scalar(rigid->held.size()));
        forAll(rigid->body, c)
        {
            if (rigid->body[c] < 0) continue;
            key.append(scalar(c));
            key.append(scalar(rigid->body[c]));
            key.append(rigid->cpV[c]);
            for (direction d = 0; d < 3; ++d) key.append(rigid->r[c][d]);
        }
        forAll(rigid->held, b) key.append(scalar(rigid->held[b]));
    }

    bool same = A_ && key.size() == matrixKey_.size();
    if (same)
    {
        same = std::equal
        (
            key.cbegin(), key.cend(), matrixKey_.cbegin(),
            [](scalar a, scalar b)
            {
                return std::memcmp(&a, &b, sizeof(scalar)) == 0;
            }
        );
    }
    matrixKey_.transfer(key);
    return returnReduce(same, andOp<bool>());
}


// ************************************************************************* //
