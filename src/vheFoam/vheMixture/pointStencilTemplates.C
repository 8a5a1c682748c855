/*---------------------------------------------------------------------------*\
  vheFoam: the cells that share a point with a cell, on every rank
\*---------------------------------------------------------------------------*/

#include "syncTools.H"
#include "coupledPolyPatch.H"

namespace Foam
{
namespace pointStencilOps
{

// Per point, a flat list of records of `width` scalars, the first the
// record's global cell id; merging keeps one record per id (a cell's record
// reaches a point from each of the point's ranks and cyclic sides)
struct uniqueRecords
{
    label width;

    void operator()(List<scalar>& x, const List<scalar>& y) const
    {
        for (label j = 0; j < y.size(); j += width)
        {
            bool known = false;
            for (label i = 0; i < x.size() && !known; i += width)
            {
                known = x[i] == y[j];
            }
            if (known) continue;
            const label n = x.size();
            x.setSize(n + width);
            for (label k = 0; k < width; ++k) x[n + k] = y[j + k];
        }
    }
};

// The records hold no direction that a translation changes (positions are
// relative to the point), and rotational cyclics are refused
struct noTransform
{
    template<class Type>
    void operator()(const vectorTensorTransform&, const bool, List<Type>&)
    const
    {}

    template<class Type>
    void operator()(const coupledPolyPatch&, UList<Type>&) const
    {}

    template<class Type, template<class> class Container>
    void operator()(const coupledPolyPatch&, Container<Type>&) const
    {}
};

} // End namespace pointStencilOps
} // End namespace Foam


template<class Fill>
Foam::pointStencil::records Foam::pointStencil::gather
(
    const label width,
    const Fill& fill
) const
{
    stamp_ = -1;
    records recs(coupledPts_.size());
    const pointStencilOps::uniqueRecords op{width};
    List<scalar> rec(width);
    forAll(coupledPts_, j)
    {
        const label q = coupledPts_[j];
        for (const label k : mesh_.pointCells()[q])
        {
            if (!fill(k, q, &rec[1])) continue;
            rec[0] = cellIds_.toGlobal(k);
            op(recs[j], rec);
        }
    }
    syncTools::syncPointList
    (
        mesh_, coupledPts_, recs, op, List<scalar>(),
        pointStencilOps::noTransform()
    );
    return recs;
}


template<class Local, class Record>
void Foam::pointStencil::visit
(
    const label c,
    const records& recs,
    const label width,
    const Local& local,
    const Record& record
) const
{
    remoteSeen_.clear();
    stamp_[c] = c;
    for (const label q : mesh_.cellPoints()[c])
    {
        const label j = coupledIndex_[q];
        if (j < 0)
        {
            for (const label k : mesh_.pointCells()[q])
            {
                if (stamp_[k] == c) continue;
                stamp_[k] = c;
                local(k);
            }
            continue;
        }
        const List<scalar>& rl = recs[j];
        for (label r = 0; r < rl.size(); r += width)
        {
            const label id = label(rl[r]);
            if (cellIds_.isLocal(id))
            {
                const label k = cellIds_.toLocal(id);
                if (stamp_[k] == c) continue;
                stamp_[k] = c;
            }
            else
            {
                if (remoteSeen_.found(rl[r])) continue;
                remoteSeen_.append(rl[r]);
            }
            record(&rl[r], q);
        }
    }
}


// ************************************************************************* //
