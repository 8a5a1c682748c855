/*---------------------------------------------------------------------------*\
  vheFoam: rigid bodies -- the edge of a body whose surface is known

  A cell whose centre lies inside the body is held to the body's motion;
  a fluid cell beside it is not held, but its face to the held cell
  carries the wall's viscous stress at the wall's true distance: the
  Laplacian's flux mu |S| (u_N - u_P)/|d| across that face takes the
  velocity of the held cell's centre, a distance (1 - delta)|d| inside
  the wall, where the wall stress wants mu |S| (u_N - u_wall)/(delta |d|).
  The penalty mu |S|/|d| (1/delta - 1) (u_N - u_wall) on the fluid cell
  makes up the difference, so a linear shear profile beside a wall is
  exact whatever the wall's position in the cell (a ghost-cell wall
  written as a penalty).  A weight of the cell's fraction held the body's
  edge by its volume instead: that sets the body's hydrodynamic radius
  to first order in the cell size, and a weight that made it right in
  Stokes flow (min(1, 4 alpha)) was too thick at a Reynolds number of 32.

  A free body's mass is then its held cells'; the solid outside them (in
  cells of fraction below about 1/2) would leave its weight, less that of
  the fluid it displaces, to the fluid cells beside the wall.  The face
  forces take that weight from those cells and give it to the held cells
  beside them (edgeDensity(), a change of the density under gravity, so
  that a cell of the edge weighs as its fluid; a held body's too, whose
  holding force then bears all of its solid's weight): without it a
  floating box of half the water's density sat 2.2 % of its height too
  deep and one of a tenth 22 % of its draft; given to the body's held
  cells evenly, not to those beside, the flat light box lost the righting
  moment of its edge row's buoyancy, tilted and floated 12 % of its draft
  high
\*---------------------------------------------------------------------------*/

#include "rigidBodies.H"
#include "syncTools.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "vhe.h"
#include <functional>

const Foam::rigidPoses::body& Foam::rigidBodies::shape
(
    const label b,
    const vector& x
) const
{
    return
        b < poses_.size()
      ? poses_[b]
      : poses_.nearestFixed(bodyPhase_[b], x);
}


Foam::scalar Foam::rigidBodies::sdf(const label b, const vector& x) const
{
    const rigidPoses::body& bd = shape(b, x);
    return poses_.shapes().sdf(bd.shape, bd.Q, bd.X, x);
}


void Foam::rigidBodies::edge()
{
    const fvMesh& mesh = mixture_.rho().mesh();
    const vectorField& C = mesh.C().primitiveField();
    const label nCells = mesh.nCells();

    hold_ = w_;
    wallK_.setSize(nCells);
    wallK_ = 0;
    if (!shaped_.found(true)) return;

    // The held cells: centres inside the surface
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b < 0 || !shaped_[b]) continue;
        hold_[c] = sdf(b, C[c]) < 0 ? 1 : 0;
    }

    // A fluid cell o beside the held cell i of body b across a face of
    // area magS, centres |dv| apart
    const auto wall = [&]
    (
        const label o,
        const label b,
        const vector& xi,
        const scalar magS
    )
    {
        if (body_[o] >= 0 && (body_[o] != b || hold_[o] >= 1)) return;
        // Where the surface cuts the segment between the centres: the
        // shape (of a fixed material, the body nearest the fluid centre)
        // and its image nearest the fluid centre, found once (the segment
        // is a cell long)
        const rigidPoses::body& bd = shape(b, C[o]);
        const vector Y
        (
            C[o] - poses_.shapes().nearestImage(C[o] - bd.X)
        );
        const scalar so = vhe_shape_sdf_posed
        (
            &bd.shape, bd.Q.cdata(), Y.cdata(), C[o].cdata()
        );
        if (so < 0) return;
        const scalar si = vhe_shape_sdf_posed
        (
            &bd.shape, bd.Q.cdata(), Y.cdata(), xi.cdata()
        );
        const scalar delta = vhe_shape_crossing
        (
            &bd.shape, bd.Q.cdata(), Y.cdata(), C[o].cdata(), xi.cdata(),
            so, si
        );
        wallK_[o] += vhe_wall_coefficient(magS, mag(xi - C[o]), delta);
        if (body_[o] < 0)
        {
            // Beside the body, not of it: weight 0 in its sums
            body_[o] = b;
            w_[o] = 0;
            hold_[o] = 0;
        }
    };

    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const scalarField& magSf = mesh.magSf().primitiveField();
    // The held side of each face as the step began (wall() adds cells)
    const labelList body0(body_);
    const scalarField hold0(hold_);
    const auto held = [&](const label c)
    {
        return body0[c] >= 0 && shaped_[body0[c]] && hold0[c] >= 1;
    };
    forAll(nei, f)
    {
        const label o = own[f], n = nei[f];
        if (held(o) && !held(n)) wall(n, body0[o], C[o], magSf[f]);
        if (held(n) && !held(o)) wall(o, body0[n], C[n], magSf[f]);
    }

    // Across processor and cyclic faces: each side adds its own fluid
    // cells, from the other side's centres (periodic images in sdf)
    labelList bodyNbr;
    scalarList holdNbr;
    syncTools::swapBoundaryCellList(mesh, body0, bodyNbr);
    syncTools::swapBoundaryCellList(mesh, hold0, holdNbr);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (!pp.coupled()) continue;
        const label start = pp.start() - mesh.nInternalFaces();
        // The neighbour's centre as seen from this side (delta: from
        // the cell's centre to its neighbour's, across the transform)
        const vectorField dn(pp.delta());
        const scalarField& pMagS = pp.magSf();
        forAll(pp, i)
        {
            const label c = pp.faceCells()[i];
            const label bn = bodyNbr[start + i];
            if
            (
                bn >= 0 && shaped_[bn] && holdNbr[start + i] >= 1
             && !held(c)
            )
            {
                wall(c, bn, C[c] + dn[i], pMagS[i]);
            }
        }
    }

    // A free body's mass and momentum are its held cells' (correct()
    // projects those); the weight of its solid outside them is moved to
    // them by edgeDensity()
    forAll(body_, c)
    {
        const label b = body_[c];
        if (b >= 0 && shaped_[b] && !held_[b]) w_[c] = hold_[c];
    }
}


bool Foam::rigidBodies::wallEdges() const
{
    return shaped_.found(true);
}


Foam::tmp<Foam::volScalarField> Foam::rigidBodies::edgeDensity() const
{
    const volScalarField& rho = mixture_.rho();
    const fvMesh& mesh = rho.mesh();
    tmp<volScalarField> td
    (
        new volScalarField
        (
            IOobject("rigidEdgeDensity", mesh.time().timeName(), mesh),
            mesh,
            dimensionedScalar(dimDensity, Zero)
        )
    );
    // None before the step's bodies are found (the acceleration of the
    // start and of a changed mesh is taken before them)
    if (updated_ != mesh.time().timeIndex() || !wallEdges()) return td;

    const label nCells = mesh.nCells();
    const scalarField& V = mesh.V();
    scalarField& d = td.ref().primitiveFieldRef();
    const auto walled = [&](const label b)
    {
        return b >= 0 && shaped_[b];
    };

    // A cell of a body with a wall edge outside its held cells: its
    // solid's mass over the fluid's it displaces, (rho_s - rho_f) alpha V,
    // rho_f the cell's fluid density (rho - rho_s alpha)/(1 - alpha),
    // taken out.  (A held body too: its holding force then bears all of
    // its solid's weight, as a free body's motion does; without, ten
    // Cate's sphere moved in its box at the free sphere's velocity felt
    // 1.029 of its weight less buoyancy, with 1.019, and 0.017 at rest)
    scalarField m(nCells, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (!walled(b) || hold_[c] >= 1 || rhoAlpha_[c] <= 0) continue;
        const scalar alpha =
            rhoAlpha_[c]/mixture_.phases()[bodyPhase_[b]].rho;
        if (alpha >= 1) continue;
        const scalar rhoF = (rho[c] - rhoAlpha_[c])/(1 - alpha);
        const scalar e = rhoAlpha_[c] - alpha*rhoF;
        m[c] = e*V[c];
        d[c] = -e;
    }

    // ... and given to its held neighbours across its faces, evenly, so
    // that it acts where it was (a flat box floating a cell deep is
    // righted by its edge row's buoyancy: spread over the whole body, the
    // box tilted and floated 12 % of its draft high); a cell that touches
    // the held cells at a corner only gives it to all of them, evenly by
    // volume
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    labelList bodyNbr;
    scalarList holdNbr;
    syncTools::swapBoundaryCellList(mesh, body_, bodyNbr);
    syncTools::swapBoundaryCellList(mesh, hold_, holdNbr);
    const label nInternal = mesh.nInternalFaces();
    const auto heldBy = [&](const label c, const label b)
    {
        return body_[c] == b && hold_[c] >= 1;
    };
    // Over the faces from an edge cell e to a held cell of its body: on
    // this rank (h its index) or across a coupled face (bf its boundary
    // face index)
    typedef std::function<void(label, label)> visit;
    const auto edgeFaces = [&](const visit& internal, const visit& coupled)
    {
        forAll(nei, f)
        {
            const label o = own[f], n = nei[f];
            if (m[o] != 0 && heldBy(n, body_[o])) internal(o, n);
            if (m[n] != 0 && heldBy(o, body_[n])) internal(n, o);
        }
        forAll(mesh.boundary(), patchi)
        {
            const fvPatch& pp = mesh.boundary()[patchi];
            if (!pp.coupled()) continue;
            const label start = pp.start() - nInternal;
            forAll(pp, i)
            {
                const label c = pp.faceCells()[i];
                if
                (
                    m[c] != 0 && bodyNbr[start + i] == body_[c]
                 && holdNbr[start + i] >= 1
                )
                {
                    coupled(c, start + i);
                }
            }
        }
    };
    labelList nHeld(nCells, 0);
    edgeFaces
    (
        [&](const label e, const label) { ++nHeld[e]; },
        [&](const label e, const label) { ++nHeld[e]; }
    );
    scalarField gain(nCells, Zero);
    scalarList across(mesh.nFaces() - nInternal, Zero);
    edgeFaces
    (
        [&](const label e, const label h) { gain[h] += m[e]/nHeld[e]; },
        [&](const label e, const label bf) { across[bf] = m[e]/nHeld[e]; }
    );
    syncTools::swapBoundaryFaceList(mesh, across);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& pp = mesh.boundary()[patchi];
        if (!pp.coupled()) continue;
        const label start = pp.start() - nInternal;
        forAll(pp, i)
        {
            gain[pp.faceCells()[i]] += across[start + i];
        }
    }
    scalarList rest(nBodies_, Zero), heldV(nBodies_, Zero);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (!walled(b)) continue;
        if (hold_[c] >= 1) heldV[b] += V[c];
        else if (nHeld[c] == 0) rest[b] += m[c];
    }
    bodyRegions::sumLists(rest);
    bodyRegions::sumLists(heldV);
    forAll(body_, c)
    {
        const label b = body_[c];
        if (walled(b) && hold_[c] >= 1 && heldV[b] > 0)
        {
            d[c] = (gain[c] + rest[b]*V[c]/heldV[b])/V[c];
        }
    }
    td.ref().correctBoundaryConditions();
    return td;
}

// ************************************************************************* //
