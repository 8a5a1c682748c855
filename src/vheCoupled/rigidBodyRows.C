/*---------------------------------------------------------------------------*\
  vheFoam: the coupled step's rows of the rigid bodies' velocities
\*---------------------------------------------------------------------------*/

#include "rigidBodyRows.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidBodyRows::rigidBodyRows
(
    const fvMesh& mesh,
    coupledRigidRows* rigid,
    const labelList& cmpts,
    const label nCells
)
:
    rigid_(rigid),
    cmpts_(cmpts),
    nd_(cmpts.size()),
    nb_(cmpts.size() + 1),
    rotAxes_(),
    nbd_(0),
    nBodies_(rigid ? rigid->held.size() : 0),
    lastRank_(Pstream::myProcNo() == Pstream::nProcs() - 1),
    start_(PetscInt(nCells)*nb_),
    cells_(nBodies_, Zero),
    held_(nBodies_, false)
{
    if (nd_ == 3)
    {
        rotAxes_ = labelList({0, 1, 2});
    }
    else if (nd_ == 2)
    {
        forAll(mesh.solutionD(), d)
        {
            if (mesh.solutionD()[d] < 0) rotAxes_.append(d);
        }
    }
    nbd_ = nd_ + rotAxes_.size();
    if (!nBodies_) return;

    scalarList cp(nBodies_, Zero);
    forAll(rigid_->body, c)
    {
        const label b = rigid_->body[c];
        if (b < 0) continue;
        ++cells_[b];
        cp[b] += rigid_->cpV[c];
    }
    Pstream::listCombineGather(cells_, plusEqOp<label>());
    Pstream::listCombineScatter(cells_);
    Pstream::listCombineGather(cp, plusEqOp<scalar>());
    Pstream::listCombineScatter(cp);
    forAll(held_, b)
    {
        held_[b] = rigid_->held[b] || cp[b] <= VSMALL;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rigidBodyRows::dUR(const label c, const label j) const
{
    vector e(Zero);
    if (j < nd_)
    {
        e[cmpts_[j]] = 1;
        return e;
    }
    e[rotAxes_[j - nd_]] = 1;
    return e ^ rigid_->r[c];
}


Foam::scalar& Foam::rigidBodyRows::component(const label b, const label j) const
{
    return j < nd_
      ? rigid_->Ub[b][cmpts_[j]]
      : rigid_->omega[b][rotAxes_[j - nd_]];
}


Foam::labelList Foam::rigidBodyRows::widths() const
{
    labelList w(nLocal(), Zero);
    forAll(w, i)
    {
        w[i] = nd_*cells_[i/nbd_] + nbd_;
    }
    return w;
}


void Foam::rigidBodyRows::add(Mat A, Vec b, const label start0) const
{
    if (!nBodies_) return;
    auto put = [&](PetscInt r, PetscInt c, scalar v)
    {
        if (!A) return;
        PetscScalar val = v;
        MatSetValues(A, 1, &r, 1, &c, &val, ADD_VALUES);
    };
    auto row = [&](label bi, label j) { return start_ + PetscInt(bi*nbd_ + j); };

    forAll(rigid_->body, c)
    {
        const label bi = rigid_->body[c];
        if (bi < 0) continue;
        const scalar cpV = rigid_->cpV[c];
        for (label j = 0; j < nbd_; ++j)
        {
            const vector d(dUR(c, j));
            for (label k = 0; k < nd_; ++k)
            {
                const PetscInt rc = PetscInt((start0 + c)*nb_ + k);
                const scalar v = cpV*d[cmpts_[k]];
                put(rc, row(bi, j), -v);
                if (!held_[bi]) put(row(bi, j), rc, v);
            }
            if (held_[bi]) continue;
            for (label m = 0; m < nbd_; ++m)
            {
                put(row(bi, j), row(bi, m), -cpV*(d & dUR(c, m)));
            }
        }
    }
    if (!lastRank_) return;
    for (label bi = 0; bi < nBodies_; ++bi)
    {
        if (!held_[bi]) continue;
        for (label j = 0; j < nbd_; ++j)
        {
            put(row(bi, j), row(bi, j), 1);
            PetscInt r = row(bi, j);
            PetscScalar val = component(bi, j);
            VecSetValues(b, 1, &r, &val, ADD_VALUES);
        }
    }
}


void Foam::rigidBodyRows::guess(PetscScalar* x) const
{
    if (!lastRank_) return;
    for (label bi = 0; bi < nBodies_; ++bi)
    {
        for (label j = 0; j < nbd_; ++j)
        {
            x[bi*nbd_ + j] = component(bi, j);
        }
    }
}


void Foam::rigidBodyRows::read(const PetscScalar* x) const
{
    for (label bi = 0; bi < nBodies_; ++bi)
    {
        scalarField v(nbd_, Zero);
        if (lastRank_)
        {
            forAll(v, j) v[j] = x[bi*nbd_ + j];
        }
        reduce(v, sumOp<scalarField>());
        forAll(v, j) component(bi, j) = v[j];
    }
}


// ************************************************************************* //
