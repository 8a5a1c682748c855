/*
 * vhe.h -- the pointwise mathematics of vheFoam (C99, no OpenFOAM).
 *
 * Every function is a pure kernel over caller-owned arrays: no globals, no
 * allocation, no I/O.  The OpenFOAM shim hands field data pointers straight
 * in (Field<T>::cdata()/data()), so the array layouts are OpenFOAM's:
 *   scalar      1 double per cell
 *   vector      3 doubles  (x y z)
 *   symmTensor  6 doubles  (xx xy xz yy yz zz)
 *   tensor      9 doubles  row-major (xx xy xz yx yy yz zx zy zz)
 * OpenFOAM's fvc::grad(U) has (i,j) = d u_j / d x_i, i.e. it is L^T where
 * L_ij = d u_i / d x_j is the velocity gradient of the papers; kernels that
 * take a velocity gradient take OpenFOAM's grad(U) and say so.
 *
 * Units are SI and given per argument.  B* = phi_s^(1/2) B with B the left
 * Cauchy-Green tensor of the solid (dimensionless).
 */
#ifndef VHE_H
#define VHE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes returned by the kernels that can fail. */
enum vhe_status {
    VHE_OK = 0,
    VHE_EBADARG = 1,   /* an argument is out of its domain (NULL, r <= 0, ...) */
    VHE_ENOFIT = 2     /* a packing cannot place the requested bodies        */
};

/* ------------------------------------------------------------------ mixture */

/*
 * Mixture properties from the phase fractions.
 *   alpha[k][c]  volume fraction of phase k in cell c (k < nphase)
 *   rho_k[k]     density of phase k [kg/m^3]
 *   mu_k[k]      dynamic viscosity of phase k [Pa s]
 *   G_k[k]       shear modulus of phase k [Pa]; 0 for a fluid phase
 *   is_solid[k]  nonzero for an elastic solid material
 *   is_rigid[k]  nonzero for a rigid material (may be NULL: none)
 * Outputs (any may be NULL to skip):
 *   rho[c] = sum_k alpha_k rho_k, mu[c] = sum_k alpha_k mu_k,
 *   phis[c] = sum_solids alpha_m (clipped to [0,1]),
 *   Ghat[c] = sum_solids alpha_m G_m / phis, 0 where phis <= phis_min.
 * A rigid material has no viscosity of its own (its mu_k is not read).
 * Where it holds less than VHE_RIGID_HELD of a cell, mu[c] is the other
 * phases' mean over their own fraction, sum_{k not rigid} alpha_k mu_k /
 * sum_{k not rigid} alpha_k (fractions below 0 taken as 0): the viscosity
 * of the fluid that shears beside the body.  Where it holds more, -1: the
 * body holds the cell wholly (rigidBodies), and the caller gives it the
 * smallest viscosity of its neighbours (vheMixture::rigidViscosity), so
 * that a face between the body and a fluid carries that fluid's.  *Why:*
 * a rigid body's own viscosity entered the face viscosity between its
 * cells and the fluid's, the stress at its surface: ten Cate's settling
 * sphere with the template's 1e-3 m^2/s (19 times the oil's) settled 25 %
 * too slowly at 6 cells across, 12 % with the oil's.  And the held cells
 * do not take their own traces of fluid: 1e-5 of water in a fixed box's
 * corner cell, taken at its own weight, put the water's viscosity on the
 * faces of the air beside it, whose explicit stress blew up
 * (test_rigid's fixedDam).
 */
#define VHE_RIGID_HELD 0.25
void vhe_mixture(size_t n, int nphase, const double *const *alpha,
                 const double *rho_k, const double *mu_k, const double *G_k,
                 const int *is_solid, const int *is_rigid, double phis_min,
                 double *rho, double *mu, double *phis, double *Ghat);

/* ----------------------------------------------------------- elastic stress */

/*
 * A body's elastic stress lives at the cell centres inside it.  The share
 * of it a cell carries, w(phi_s), rises from 0 at phi_s = 1/4 to 1 at
 * phi_s = 3/4: from a centre a quarter of a cell outside the outline (the
 * isovalue 1/2 of phi_s; an outline parallel to the cell's faces) to a
 * quarter inside.  Below it, a cell is a fluid cell holding a sliver of
 * the body (its B* stretched with the body's strain rate beside it,
 * vheElasticity::bodyEdgeGradient).  Stressed in proportion to phi_s, such
 * a cell tied the fluid beside the body to it (its stress increment is a
 * viscosity dt Ghat phi_s, rigid for a stiff body at any phi_s): a stiff
 * body was half a cell larger than it is (a stiff disk's wall stress in
 * plane Couette flow 1.139 at 32 cells, a rigid disk's 1.057; now 1.089).
 * A step at 1/2 instead of the ramp switches a cell's stiffness on and off
 * as the body moves over its centre: a stiff disk in a lid-driven cavity
 * (G/(rho U^2) = 1e8) reached 4.5 times the lid speed, 1 with the ramp.
 */
double vhe_body_weight(double phis);

/*
 * sigma[c] = w(phi_s) Ghat phi_s^(1/2) dev(B*)   [Pa], symmTensor layout (6
 * per cell), w = vhe_body_weight.  Zero where phis <= phis_min.
 * dev(A) = A - tr(A)/3 I.
 */
void vhe_elastic_stress(size_t n, const double *Ghat, const double *phis,
                        const double *Bstar, double phis_min, double *sigma);

/* ------------------------------------------------------------------ stretch */

/* 3x3 matrix exponential, row-major, scaling and squaring with Pade(6,6). */
void vhe_expm3(const double A[9], double E[9]);

/*
 * Upper-convected stretch over one step, exact for a velocity gradient held
 * constant over dt:  B* <- F B* F^T,  F = exp(dt L).
 *   gradU  OpenFOAM's fvc::grad(U) per cell (9 doubles) [1/s]; L = gradU^T
 *   dt     time step [s]
 *   Bstar  in/out, symmTensor per cell
 * F B F^T is congruent to B, so a symmetric positive (semi)definite B* stays
 * so for any dt; det(F) = exp(dt tr L), so det(B*) is preserved when tr L = 0.
 */
void vhe_stretch(size_t n, double dt, const double *gradU, double *Bstar);

/*
 * Implicit stretch of the second-order backward (BDF2) scheme: solves
 *   B* - tau (L B* + B* L^T) = Bhat      per cell, L = gradU^T,
 * tau = dt/(1 + dt/(dt + dt0)) (2 dt/3 at a constant step), Bhat the
 * advected B* plus the BDF2 carry of the previous step's increment.  A 6x6
 * linear solve per cell (Gaussian elimination, partial pivoting).  Cells
 * with Bhat = 0 (pure fluid) stay 0.  Bhat and Bstar may alias.  Unlike
 * vhe_stretch it is not a congruence: det and positivity hold to O(tau^3)
 * per step only.  Returns the number of cells whose system was singular
 * (left at Bhat).
 */
size_t vhe_stretch_implicit(size_t n, double tau, const double *gradU,
                            const double *Bhat, double *Bstar);

/* Sets B* to 0 where phis <= phis_min (pure fluid carries no deformation). */
void vhe_clip_fluid(size_t n, const double *phis, double phis_min,
                    double *Bstar);

/*
 * B = B* / phi_s^(1/2) where phis > phis_min, else I (the neutral value a
 * donor cell without solid lends to a vanishing solid flux).
 */
void vhe_b_from_bstar(size_t n, const double *phis, const double *Bstar,
                      double phis_min, double *B);

/*
 * Donor-cell transport of B with the solid volume flux, written so that
 * the new B is a convex combination of old B values (hence symmetric
 * positive definite whenever they are, and exactly unchanged for a uniform
 * B).  Three steps, called by the framework:
 *
 * 1. vhe_bdonor_internal over the internal faces (owner -> neighbour) and
 *    vhe_bdonor_boundary over boundary faces: a[f] is the solid volume
 *    crossing face f during the step [m^3] (flux * dt, positive out of the
 *    owner); B is the old B per cell (B* / phi_s^(1/2), I without solid);
 *    Bnb[f] is the B on the far side of a boundary face (the coupled
 *    neighbour's value, or the boundary value).  They accumulate, per cell,
 *    out[c] [m^3] the solid volume leaving, W[c] [m^3] the volume entering
 *    and S[c] (6 per cell) [m^3] the entering volume times its B.
 *    out, W and S start at 0.
 * 2. vhe_bdonor_finish: per cell, the solid left in place is
 *    w0 = max(phis0 V - out, 0) and B_new = (w0 B_old + S) / (w0 + W);
 *    B*_new = phis^(1/2) B_new where phis > phis_min, else 0.  Returns the
 *    number of solid cells whose old content left entirely (w0 clipped).
 */
void vhe_bdonor_internal(size_t nf, const int32_t *owner,
                         const int32_t *neighbour, const double *a,
                         const double *B, double *out, double *W, double *S);
void vhe_bdonor_boundary(size_t nf, const int32_t *face_cells,
                         const double *a, const double *Bnb, double *out,
                         double *W, double *S);
size_t vhe_bdonor_finish(size_t n, const double *V, const double *phis0,
                         const double *phis, const double *Bold,
                         const double *out, const double *W, const double *S,
                         double phis_min, double *Bstar);

/* --------------------------------------------- log-conformation of B */

/*
 * The deformation is carried as Psi = log B (logb.c; its transport:
 * transport.c).  For the incompressible solid tr Psi = log det B = 0;
 * every kernel below is linear in Psi with one coefficient for the three
 * diagonal components, so a trace-free Psi stays trace-free and
 * B = exp(Psi) has det B = 1 and is symmetric positive definite by
 * construction.
 *
 * vhe_sym_eigen: eigenvalues (unordered) and orthonormal eigenvectors
 * (columns of V, row-major) of a symmTensor, cyclic Jacobi on its six
 * entries; warm nonzero: V on entry is a guess (the last eigenvectors of
 * a tensor that changed little), made orthonormal and used as the start,
 * so one or two sweeps finish instead of four or five.
 * vhe_sym_from_eigen: S = V diag(f) V^T.
 * vhe_sym_log: L = log S for S symmetric positive definite; eigenvalues
 * below DBL_MIN are taken as DBL_MIN, and the number of such is returned
 * (0 for a valid S).  vhe_sym_exp: E = exp S, any symmetric S.
 */
void vhe_sym_eigen(const double S[6], double lambda[3], double V[9],
                   int warm);
void vhe_sym_from_eigen(const double V[9], const double f[3], double S[6]);
int vhe_sym_log(const double S[6], double L[6]);
void vhe_sym_exp(const double S[6], double E[6]);

/*
 * Psi = log(B* / phi_s^(1/2)) where phis > phis_min, else 0 (B = I, the
 * neutral value a cell without solid lends to a vanishing solid flux).
 * Returns the number of cells whose B* was not positive definite.
 * vhe_bstar_from_logb is the inverse: B* = phi_s^(1/2) exp(Psi) where
 * phis > phis_min, else 0.  V (9 per cell, row-major, or NULL): each
 * cell's last eigenvectors, the start of its eigen-decomposition and
 * overwritten by the new ones (set to I before the first use); from one
 * step to the next they change little, and the decompositions take one or
 * two Jacobi sweeps instead of four or five.
 */
size_t vhe_logb_from_bstar(size_t n, const double *phis, const double *Bstar,
                           double phis_min, double *Psi, double *V);
void vhe_bstar_from_logb(size_t n, const double *phis, const double *Psi,
                         double phis_min, double *Bstar, double *V);

/*
 * B* of a field read from a file, made unimodular: where phis > phis_min,
 * B = exp(dev log B), det B = 1 to round-off (a file of 8 digits holds B*
 * to 5e-9, det B to ~3e-8).  Returns the largest |det B - 1| before, over
 * the cells with phis > phis_solid (0 if none).
 */
double vhe_bstar_unimodular(size_t n, const double *phis, double phis_min,
                            double phis_solid, double *Bstar);

/*
 * Bounded second-order conservative transport of a symmTensor X per unit
 * solid volume (X = Psi) with the solid volume a[f] crossing each face
 * over the step (flux-corrected transport, Zalesak 1979):
 *
 * 1. Low order: vhe_bdonor_internal/boundary (above) with X in place of B,
 *    then vhe_donor_finish gives per cell the solid content
 *    m = max(phis0 V - out, 0) + W [m^3] and the donor-cell X, a convex
 *    combination of old X values (m = 0, X = 0 where phis <= phis_min).
 *    Returns the number of solid cells whose old content left entirely.
 * 2. Gradient G of the old X (18 per cell: d/dx, d/dy, d/dz of the 6
 *    components) by least squares weighted 1/|d|^2 over the face
 *    neighbours, d the vector between the cell centres, counting only
 *    faces whose both cells have phis > phis_grad: cells with little solid
 *    take no part (their X is bounded but not smooth), and a cell without
 *    such neighbours has G = 0.  _internal and _boundary (coupled patches:
 *    delta = x_nb - x_owner, phis_nb and X_nb the neighbour's values)
 *    accumulate M (6 per cell) and b (18 per cell), starting at 0;
 *    _finish solves per cell and sets M and b back to 0 (ready for the
 *    next use).  Exact for a linear X.
 * 3. Antidiffusive flux A[f] (6 per face, [m^3]) = a (X_f - X_up), X_f
 *    the QUICKEST face value (Leonard 1979) in MUSCL-Hancock form:
 *      X_f = X_up + (x_f - x_up - dt/2 U_up) . G_up
 *            + k/2 ((X_dn - X_up) - (x_dn - x_up) . G_up),
 *    k = (1 - c)(1 - 2c)/3, c = |a| / (|S_f| |x_dn - x_up| phis_up) the
 *    face Courant number (third order in 1D on a uniform mesh; k = 0 where
 *    the downwind cell has phis <= phis_grad), up the upwind cell, A = 0
 *    where phis_up <= phis_grad; positive from the owner to the neighbour.
 *    delta = x_neighbour - x_owner per face.  Boundary (coupled patches;
 *    pass a = 0 elsewhere): phis_nb, X_nb, U_nb, G_nb the neighbour's.
 * 4. Limiter: local extrema of the old and low-order X over each cell
 *    and its face neighbours (vhe_fct_extrema_init, then _internal and
 *    _boundary with Emin/Emax the cells' own extrema from init: a cell
 *    without solid has none, +-HUGE_VAL); sums of the entering positive
 *    and negative fluxes (vhe_fct_sums_*, into Rp and Rm, starting at 0);
 *    vhe_fct_ratios turns them in place into Zalesak's R+ and R-; then
 *    vhe_fct_apply_* adds lambda_f A[f] to mX = m X (start: m times the
 *    low-order X), lambda_f per component Zalesak's, except that the
 *    three diagonal components share the smallest of theirs, so every
 *    component stays within its local extrema and tr X is kept exactly.
 *    Boundary: Rp_nb, Rm_nb the coupled neighbour's ratios.
 */
size_t vhe_donor_finish(size_t n, const double *V, const double *phis0,
                        const double *phis, const double *Xold,
                        const double *out, const double *W, const double *S,
                        double phis_min, double *m, double *X);
void vhe_lsq_grad_internal(size_t nf, const int32_t *owner,
                           const int32_t *neighbour, const double *delta,
                           const double *phis, double phis_grad,
                           const double *X, double *M, double *b);
void vhe_lsq_grad_boundary(size_t nf, const int32_t *face_cells,
                           const double *delta, const double *phis,
                           const double *phis_nb, double phis_grad,
                           const double *X, const double *X_nb, double *M,
                           double *b);
void vhe_lsq_grad_finish(size_t n, double *M, double *b, double *G);
void vhe_antidiffusive_internal(size_t nf, const int32_t *owner,
                                const int32_t *neighbour, const double *a,
                                const double *Sf, const double *delta,
                                const double *Cf, const double *C,
                                const double *U, const double *phis,
                                double phis_grad, const double *X,
                                const double *G, double dt, double *A);
void vhe_antidiffusive_boundary(size_t nf, const int32_t *face_cells,
                                const double *a, const double *Sf,
                                const double *delta, const double *Cf,
                                const double *C, const double *U,
                                const double *phis, const double *phis_nb,
                                double phis_grad, const double *X,
                                const double *X_nb, const double *U_nb,
                                const double *G, const double *G_nb,
                                double dt, double *A);
void vhe_fct_extrema_init(size_t n, const double *phis0, const double *Xold,
                          const double *m, const double *X, double phis_min,
                          double *Xmin, double *Xmax);
void vhe_fct_extrema_internal(size_t nf, const int32_t *owner,
                              const int32_t *neighbour, const double *Emin,
                              const double *Emax, double *Xmin, double *Xmax);
void vhe_fct_extrema_boundary(size_t nf, const int32_t *face_cells,
                              const double *Emin_nb, const double *Emax_nb,
                              double *Xmin, double *Xmax);
void vhe_fct_sums_internal(size_t nf, const int32_t *owner,
                           const int32_t *neighbour, const double *A,
                           double *Pp, double *Pm);
void vhe_fct_sums_boundary(size_t nf, const int32_t *face_cells,
                           const double *A, double *Pp, double *Pm);
void vhe_fct_ratios(size_t n, const double *m, const double *X,
                    const double *Xmin, const double *Xmax, double *Rp,
                    double *Rm);
void vhe_fct_apply_internal(size_t nf, const int32_t *owner,
                            const int32_t *neighbour, const double *A,
                            const double *Rp, const double *Rm, double *mX);
void vhe_fct_apply_boundary(size_t nf, const int32_t *face_cells,
                            const double *A, const double *Rp,
                            const double *Rm, const double *Rp_nb,
                            const double *Rm_nb, double *mX);

/* Sets B* = phi_s^(1/2) I (undeformed solid, zero in fluid). */
void vhe_bstar_undeformed(size_t n, const double *phis, double *Bstar);

/* ----------------------------------------------------- symmetric 3x3 tools */

/* Eigenvalues of a symmTensor, ascending (analytic, trigonometric form). */
void vhe_sym_eigenvalues(const double S[6], double lambda[3]);

/* Determinant of a symmTensor. */
double vhe_sym_det(const double S[6]);

/*
 * Solid diagnostics over n cells, for cells with phis > phis_solid:
 *   out[0] min eigenvalue of B* over all cells (>= 0 for a valid state)
 *   out[1] max |dev(B)| (Frobenius norm), B = B* / phi_s^(1/2)
 *   out[2] max |det(B) - 1|, det(B) = det(B*)/phi_s^(3/2)
 * Cells with phis <= phis_solid contribute only to out[0].  With no such
 * cell out[1] = out[2] = 0.  out[0] = +HUGE_VAL when n = 0.
 */
void vhe_solid_diagnostics(size_t n, const double *phis, const double *Bstar,
                           double phis_solid, double out[3]);

/*
 * |dev(B)| (Frobenius norm) per cell, B = B* / phi_s^(1/2), where
 * phis > phis_solid; 0 elsewhere.
 */
void vhe_devb_mag(size_t n, const double *phis, const double *Bstar,
                  double phis_solid, double *out);

/*
 * Repairs B* in place where it is not positive definite: eigenvalues below
 * lambda_min phi_s^(1/2) are raised to it.  Returns the number of cells
 * changed.  Used only when the case asks for it (never silent).
 */
size_t vhe_spd_repair(size_t n, const double *phis, double lambda_min,
                      double *Bstar);

/* ------------------------------------------------------------- time step */

/* Elastic shear-wave speed c = sqrt(Ghat phi_s / rho) [m/s] per cell. */
void vhe_wave_speed(size_t n, const double *Ghat, const double *phis,
                    const double *rho, double *c);

/*
 * Largest stable explicit step for the elastic wave:
 *   elastic Courant number Co_e = 0.5 dt c sum_f |S_f| / V   per cell
 *   (the same face-sum form as OpenFOAM's flow Courant number).
 *   sumMagSfByV[c] = sum_f |S_f| / V  [1/m] over the cell's non-empty faces.
 * Returns max_c dt with Co_e <= maxCo, HUGE_VAL where no cell is elastic.
 * courant_out, if not NULL, receives max Co_e for the given dt.
 */
double vhe_elastic_dt(size_t n, const double *Ghat, const double *phis,
                      const double *rho, const double *sumMagSfByV,
                      double maxCo, double dt, double *courant_out);

/* ---------------------------------------------------------------- energy */

/* Kinetic energy density 0.5 rho |U|^2 [J/m^3]. */
void vhe_kinetic_energy(size_t n, const double *rho, const double *U,
                        double *e);

/* Elastic energy density Ghat/2 (phi_s^(1/2) tr(B*) - 3 phi_s) [J/m^3]. */
void vhe_elastic_energy(size_t n, const double *Ghat, const double *phis,
                        const double *Bstar, double *e);

/* ---------------------------------------------------------------- shapes */

enum vhe_shape_kind {
    VHE_SPHERE = 0,     /* centre, radius                                 */
    VHE_CYLINDER = 1,   /* centre, axis (unit), radius, half_length;
                           half_length <= 0 means infinite (a 2D disk)    */
    VHE_BOX = 2,        /* centre, half-extents in semi[]                 */
    VHE_ELLIPSOID = 3   /* centre, semi-axes in semi[] (axis aligned)     */
};

struct vhe_shape {
    int kind;            /* enum vhe_shape_kind */
    double centre[3];    /* [m] */
    double axis[3];      /* cylinder axis, unit vector */
    double radius;       /* sphere/cylinder radius [m] */
    double half_length;  /* cylinder half length [m], <= 0: infinite */
    double semi[3];      /* box half-extents / ellipsoid semi-axes [m] */
};

/*
 * VHE_OK if the shape is usable, VHE_EBADARG otherwise (NULL, unknown kind,
 * non-finite centre, radius <= 0, zero cylinder axis, semi[] <= 0 for a box
 * or ellipsoid).  The functions below treat an invalid shape as empty:
 * sdf = +HUGE_VAL, volume 0, fraction 0, bounds lo = +HUGE_VAL, hi = -HUGE_VAL.
 */
int vhe_shape_check(const struct vhe_shape *s);

/*
 * Lipschitz-1 signed distance bound: < 0 inside, > 0 outside, and
 * |value| <= true distance to the surface (exact for sphere, box, cylinder).
 */
double vhe_shape_sdf(const struct vhe_shape *s, const double x[3]);

/* Exact volume of the shape [m^3] (an infinite cylinder: area per length). */
double vhe_shape_volume(const struct vhe_shape *s);

/*
 * The shape's smallest half-width [m] in the directions a mesh solves
 * (solved[d] != 0; a 2D mesh leaves out its empty direction): a sphere's
 * or cylinder's radius (a finite cylinder's half length if shorter and
 * its axis not along an unsolved direction), a box's or ellipsoid's
 * smallest solved semi-axis.  0 for an invalid shape.  setBodies divides
 * it by the cell size to say how many cells resolve a body.
 */
double vhe_shape_half_width(const struct vhe_shape *s, const int solved[3]);

/*
 * Volume fraction of the shape in an axis-aligned box cell [lo, hi] by
 * adaptive sub-cell integration: a sub-box whose centre lies farther from
 * the surface (by vhe_shape_sdf) than its half-diagonal is wholly in or out;
 * any other is split in 2 along each integrated direction, down to
 * max_depth levels, where the leaf counts by the linear estimate
 * clamp(0.5 - sdf(centre) / (2 h), 0, 1), h the mean half-edge of the leaf
 * (first order in the leaf's size).  A box is exact instead: the cell
 * clipped by its six faces' half-spaces (to round-off; max_depth unused).
 * A smooth surface (sphere, ellipsoid,
 * infinite cylinder) stops 3 levels higher (at 0 at least, and no higher
 * than where a leaf's half-diagonal is a quarter of the smallest radius
 * of curvature, so that a body smaller than a cell is resolved) with a
 * second-order leaf: the leaf's and its halves' cuts (vhe_cell_cut) at the
 * corner values of the distance bound, extrapolated as (4 halves - leaf)/3
 * (a chord's error falls by 4 a level).  At max_depth 5 a sphere of 5.3
 * cells' radius takes a quarter of the linear leaf's time, its largest
 * cell error 6.4e-5 against 1.7e-4.  ndim = 2: the case is 2D with z the
 * empty direction; z is not split and the shape is sampled at the cell's
 * mid z (use shapes infinite along z).  Returns a value in [0, 1].
 */
double vhe_shape_fraction(const struct vhe_shape *s, const double lo[3],
                          const double hi[3], int ndim, int max_depth);

/* Axis-aligned bounding box of the shape; infinite extents are +-HUGE_VAL. */
void vhe_shape_bounds(const struct vhe_shape *s, double lo[3], double hi[3]);

/*
 * A shape moved rigidly (a rigid body's pose): its centre carried to X and
 * the shape turned by the rotation Q (3 x 3, row-major, orthonormal), so
 * that a point x of the world lies at centre + Q^T (x - X) of the shape as
 * given.  vhe_shape_fraction_posed: vhe_shape_fraction of the moved shape
 * (the same sub-cell integration; Q = I, X = centre gives the same value
 * to the last bit).  vhe_shape_bounds_posed: an axis-aligned box holding
 * the moved shape (the given shape's box turned; infinite extents stay
 * infinite along the directions they are turned into).
 */
double vhe_shape_fraction_posed(const struct vhe_shape *s, const double Q[9],
                                const double X[3], const double lo[3],
                                const double hi[3], int ndim, int max_depth);
void vhe_shape_bounds_posed(const struct vhe_shape *s, const double Q[9],
                            const double X[3], double lo[3], double hi[3]);
/* vhe_shape_sdf of the moved shape at x (a rigid motion keeps distances). */
double vhe_shape_sdf_posed(const struct vhe_shape *s, const double Q[9],
                           const double X[3], const double x[3]);

/*
 * Where the moved shape's surface cuts the segment from xo (outside, its
 * sdf so > 0) to xi (inside, sdf si < 0): the fraction of the segment from
 * xo, in (0, 1].  Regula falsi (Illinois) on the sdf along the segment, to
 * 1e-9 of its length or 8 evaluations; exact at once where the sdf is
 * linear along it (a plane).  Returns 1 where so <= 0 or si >= 0.  This is
 * the fluid's share delta of the segment between a fluid cell's centre and
 * a held cell's: the wall penalty mu |S|/|d| (1/delta - 1) of the fluid
 * cell (vhe_wall_coefficient) puts the wall's viscous stress at the
 * surface, not at the held cell's centre.
 */
double vhe_shape_crossing(const struct vhe_shape *s, const double Q[9],
                          const double X[3], const double xo[3],
                          const double xi[3], double so, double si);

/*
 * The wall penalty's geometric factor of a face of area magS between
 * centres dist apart, the fluid's share of the segment delta: magS/dist
 * (1/delta - 1), >= 0 (delta below 1e-6 taken as 1e-6).
 */
double vhe_wall_coefficient(double magS, double dist, double delta);

/* -------------------------------------------------------------- packings */

/*
 * Deterministic pseudo-random generator (splitmix64): the same seed gives the
 * same sequence on every machine and every MPI rank.
 */
uint64_t vhe_rng_next(uint64_t *state);
double vhe_rng_uniform(uint64_t *state);          /* in [0, 1) */

/*
 * Lattice packing: nx*ny*nz centres evenly spaced in the box [lo, hi]
 * (cell-centred: centre_i = lo + (i + 1/2) (hi - lo)/n).  centres has room
 * for 3 * nx*ny*nz doubles.  Returns VHE_ENOFIT when bodies of the given
 * radius plus gap would overlap or cross the box (dimension d counts only
 * where n[d] > 0 and not 2D-ignored: ndim 2 ignores z), VHE_OK otherwise.
 * Precisely: fits iff (hi - lo)/n >= 2 radius + gap in every counted
 * direction (clearance >= gap between bodies, >= gap/2 to the box); ndim 2
 * with n[2] > 1 is VHE_ENOFIT (coincident disks); any n[d] = 0 places no
 * body (VHE_OK); n[d] < 0, radius <= 0, gap < 0: VHE_EBADARG.  Centres are
 * ordered x fastest, then y, then z.
 */
int vhe_pack_lattice(const double lo[3], const double hi[3], const int n[3],
                     double radius, double gap, int ndim, double *centres);

/*
 * Random sequential addition of `count` spheres (ndim 3) or disks (ndim 2,
 * z = (lo+hi)/2) of `radius` in the box [lo, hi] with a clearance `gap`
 * between bodies and, in non-periodic directions, between a body and the
 * box.  periodic[d] nonzero makes direction d periodic (distances taken
 * through the boundary, bodies may cross it).  Tries at most max_tries
 * candidates in all; returns VHE_ENOFIT if the count is not reached (the
 * centres written so far stay valid, *placed says how many).
 */
int vhe_pack_random(const double lo[3], const double hi[3],
                    const int periodic[3], int ndim, size_t count,
                    double radius, double gap, uint64_t seed,
                    size_t max_tries, double *centres, size_t *placed);

/* Smallest clearance (surface-to-surface) among n equal bodies, with
 * periodic images as in vhe_pack_random; HUGE_VAL for n < 2. */
double vhe_min_clearance(const double lo[3], const double hi[3],
                         const int periodic[3], int ndim, size_t n,
                         double radius, const double *centres);

/* ------------------------------------------------------- exact solutions */

/*
 * Plane Poiseuille between walls y = 0 and y = h driven by a body force f
 * per unit mass: u(y) = f/(2 nu) y (h - y); flow rate Q = f h^3 / (12 nu)
 * per unit depth.
 */
double vhe_poiseuille_u(double f, double nu, double h, double y);
double vhe_poiseuille_q(double f, double nu, double h);

/*
 * Oscillating Couette flow through a stack of layers (Sugiyama et al. 2011,
 * first test; the fluid/solid/fluid variant of Parthasarathy, Bhosale and
 * Gazzola 2022): layers j = 0..n-1 from the wall at rest at y = 0 up to the
 * wall at y = sum h_j moving with u = V sin(w t).  Layer j has thickness
 * h[j] [m], density rho[j], viscosity mu[j] [Pa s] and shear modulus G[j]
 * [Pa] (0 for a fluid).  In simple shear the neo-Hookean solid is exactly
 * linear, so the periodic state is u = Im[Vh(y) e^{i w t}] with, per layer,
 * complex viscosity mu* = mu + G/(i w), k = sqrt(i w rho / mu*), and
 * continuous velocity and shear stress mu* Vh' at the interfaces.  The
 * shear strain is gamma = Im[Vh'/(i w) e^{i w t}] and, in a solid,
 * B = [[1 + gamma^2, gamma], [gamma, 1]].
 *
 * vhe_couette_setup solves for the layer coefficients (at most
 * VHE_COUETTE_MAX_LAYERS layers; VHE_EBADARG for bad input).
 * vhe_couette_eval gives u [m/s] and gamma at height y and time t (either
 * output may be NULL); vhe_couette_interface gives Vh at the top of layer
 * j as (re, im).
 */
#define VHE_COUETTE_MAX_LAYERS 8

struct vhe_couette {
    int n;
    double w;                                  /* [rad/s] */
    double y0[VHE_COUETTE_MAX_LAYERS + 1];     /* layer bottoms, y0[n] top */
    /* per layer: k, and Vh = a cosh(k (y - y0)) + b sinh(k (y - y0)) */
    double k_re[VHE_COUETTE_MAX_LAYERS], k_im[VHE_COUETTE_MAX_LAYERS];
    double a_re[VHE_COUETTE_MAX_LAYERS], a_im[VHE_COUETTE_MAX_LAYERS];
    double b_re[VHE_COUETTE_MAX_LAYERS], b_im[VHE_COUETTE_MAX_LAYERS];
};

int vhe_couette_setup(struct vhe_couette *c, int n, const double *h,
                      const double *rho, const double *mu, const double *G,
                      double V, double w);
void vhe_couette_eval(const struct vhe_couette *c, double y, double t,
                      double *u, double *gamma);
void vhe_couette_interface(const struct vhe_couette *c, int j,
                           double *re, double *im);

/*
 * Prescribed 2D flows (x-y plane) of the transport verification, from a
 * stream function psi [m^2/s] (u = d psi/dy, v = -d psi/dx), so that face
 * fluxes from psi at the face's end points are exactly divergence-free:
 *   translation    uniform U[0], U[1] [m/s]
 *   rotation       solid-body rotation, omega [rad/s] about origin [m]
 *   singleVortex   LeVeque (1996) on the unit square: psi = sin^2(pi x)
 *                  sin^2(pi y) cos(pi t/period)/pi, reversing, so the
 *                  state at t = period is the initial one
 * vhe_flow_psi gives psi at x and time t, vhe_flow_u the velocity.
 */
enum vhe_flow_kind {
    VHE_FLOW_TRANSLATION = 0,
    VHE_FLOW_ROTATION = 1,
    VHE_FLOW_SINGLE_VORTEX = 2
};

struct vhe_flow {
    int kind;              /* enum vhe_flow_kind */
    double U[2];           /* translation [m/s] */
    double origin[2];      /* rotation centre [m] */
    double omega;          /* rotation rate [rad/s] */
    double period;         /* single vortex [s] */
};

double vhe_flow_psi(const struct vhe_flow *f, const double x[3], double t);
void vhe_flow_u(const struct vhe_flow *f, const double x[3], double t,
                double u[3]);

/* ------------------------------------------- one body's motion and shape */

/*
 * From the moments of one body about its centroid (bodies.c), with
 * weights w = alpha V and r the position relative to the centroid:
 *   J = sum w r r^T (symmTensor) [m^5], L = sum w r x (u - u_c) [m^5/s].
 * normal: the empty direction (0, 1, 2) of a 2D case, or -1 in 3D.
 *
 * vhe_body_omega: the rigid-body angular velocity omega [rad/s] that
 * carries L, I omega = L with I = tr(J) 1 - J (in 2D the normal
 * component only, L_n / I_nn); 0 where I is singular.
 * vhe_body_shape: Taylor deformation D = (a - b)/(a + b) of the
 * equivalent ellipse (2D, in plane) or ellipsoid (3D), a and b the
 * largest and smallest semi-axes (proportional to the square roots of
 * the eigenvalues of J); axis: the unit major axis, its largest
 * component positive.  D = 0 for a circle or sphere, -> 1 for a line.
 */
void vhe_body_omega(const double J[6], const double L[3], int normal,
                    double omega[3]);
double vhe_body_shape(const double J[6], int normal, double axis[3]);

/*
 * A rigid body's orientation turned by the angular velocity omega over dt:
 * Q <- R Q, R the rotation by |omega| dt about omega (Rodrigues, exact for
 * a constant omega), Q then re-orthonormalised (Gram-Schmidt on its
 * columns) so that round-off does not grow over millions of steps.
 */
void vhe_pose_rotate(double Q[9], const double omega[3], double dt);

/*
 * A body's fraction fitted to its volume without moving its surface:
 * vhe_volume_sums gives sums[0] = sum alpha V and sums[1] = sum alpha
 * (1 - alpha) V (add them over processors); vhe_volume_shift applies
 * alpha <- alpha + s alpha (1 - alpha), s = (target - sums[0])/sums[1]
 * clamped to [-1, 1], where the result stays in [0, 1] and cells of
 * fraction 0 or 1 are left as they are.  Returns the s applied (0 where
 * sums[1] is 0).  One application fits the volume to round-off unless s
 * is clamped (a body that cannot reach its volume on this mesh).
 */
void vhe_volume_sums(size_t n, const double *alpha, const double *V,
                     double sums[2]);
double vhe_volume_shift(size_t n, double *alpha, const double sums[2],
                        double target);

/*
 * vhe_colour_bodies: colours for n bodies, each given by a centre
 * (3 per body) and a bounding radius, so that no two bodies nearer than
 * margin (surface to surface, bounding spheres) share a colour where
 * ncolours allow.  period[k] > 0: direction k is periodic with that
 * length (nearest image).  Greedy in the given order: each body takes
 * the lowest colour no nearer body has, or, when all ncolours are taken,
 * the colour of fewest near bodies.  Returns the number of bodies that
 * had to share a colour with a near one (0: a proper colouring).
 */
int vhe_colour_bodies(int n, const double *centre, const double *radius,
                      const double period[3], double margin, int ncolours,
                      int *colour);


/*
 * Contact between bodies (contact.c).  The proximity psi of a body is
 * min(1, 2 alpha) on it and falls by step (1/range) per layer of cells
 * around it.
 * vhe_proximity_start: psi = min(1, max(0, 2 alpha)) in n cells.
 * vhe_proximity_layer: one layer over nFaces internal faces (owner own,
 *   neighbour nei): out = max(out, psi of the other cell - step); out
 *   must hold psi on entry.
 * vhe_contact_add: f -= coef alpha psi gradPsi in n cells (f and gradPsi
 *   3 per cell): the force density [N/m^3] on the material of fraction
 *   alpha near a body of proximity psi, coef [N/m^2] (alpha, psi
 *   dimensionless, gradPsi [1/m]).
 */
void vhe_proximity_start(long n, const double *alpha, double *psi);
void vhe_proximity_layer(long nFaces, const int *own, const int *nei,
                         const double *psi, double step, double *out);
void vhe_contact_add(long n, const double *coef, const double *alpha,
                     const double *psi, const double *gradPsi, double *f);

/* ------------------------------------------------------------------ shares */

/*
 * The colours of one material that meet no other, carried on the flux of
 * their sum A (shares.c): K colours alpha_k (sum A), A's face flux F
 * [m^3/s] split by what each upwind cell gives.  For internal faces
 * own/nei index the cells; for boundary faces nei is NULL and the
 * neighbour's value is given per face (a coupled patch's other side).
 *
 * vhe_share_cells: s_k = max(a_k, 0) / sum_j max(a_j, 0) in n cells (0
 *   where no colour is positive): each cell's composition.
 * vhe_share_flows: out[c], in[c] += the flux |F| [m^3/s] leaving and
 *   entering cell c over each face (F > 0 from owner to neighbour).
 * vhe_share_inflow: inK[k][c] += the flux of colour k entering cell c,
 *   |F| times the upwind cell's share s (sNei[k][f] on boundary faces).
 * vhe_share_mix: in cells whose outflow over dt exceeds their content
 *   (out dt > A V, A = sum_k max(a_k, 0)), s_k = (a_k V/dt + inK_k) /
 *   (A V/dt + in): the outflow carries content and inflow mixed.  The
 *   others keep s.  Returns the number of such cells.
 * vhe_share_split: out[k][f] = F[f] up[k][f] / sum_k up[.][f], up the
 *   upwind cell's shares; where they are all zero (F is then zero), all
 *   to colour 0.  sum_k out = F.
 * vhe_share_meet: 1 if on some face max(a_own, a_nei) max(b_own, b_nei)
 *   > tol (two colours a and b meet there), else 0.
 */
void vhe_share_cells(long n, int K, const double *const *a,
                     double *const *s);
void vhe_share_flows(long nFaces, const int *own, const int *nei,
                     const double *F, double *out, double *in);
void vhe_share_inflow(long nFaces, const int *own, const int *nei,
                      const double *F, int K, const double *const *s,
                      const double *const *sNei, double *const *inK);
long vhe_share_mix(long n, int K, const double *const *a, const double *V,
                   double dt, const double *out, const double *in,
                   const double *const *inK, double *const *s);
void vhe_share_split(long nFaces, int K, const double *F,
                     const double *const *up, double *const *out);
int vhe_share_meet(long nFaces, const int *own, const int *nei,
                   const double *a, const double *b, const double *aNei,
                   const double *bNei, double tol);

/* ------------------------------------------------------------------- drain */

/*
 * The fluids of a drawn rigid body's edge cells (drain.c).  Edge cells:
 * lo <= held < 1 (held the drawn bodies' sum, lo the fraction from which
 * a cell moves wholly with its body); outside cells: held < lo.  A link
 * is a face between an edge cell and an outside cell that holds fluid.
 * K fluids (at most VHE_DRAIN_MAX), fractions a[k] per cell; a fluid's
 * share s_k = a_k / sum_j a_j (negative fractions as 0).  Faces as in the
 * shares kernels (nei NULL: the neighbour's values per face).
 *
 * vhe_drain_links: links[c] += 1 for each link of cell c (edge and
 *   outside cells both).
 * vhe_drain_range: over each edge cell's links, sum[k][c] += the outside
 *   cell's share s_k, mn[k][c], mx[k][c] its least and largest (the
 *   caller starts them at 0, 2 and -1).
 * vhe_drain_lambda: lambda[c] in [0, 1], the least that brings every
 *   share of s + lambda (m - s) into [mn, mx] (m = sum / links), 0 where
 *   c gathered no range (not an edge cell).
 * vhe_drain_faces: d[k][f] [m^3], the volume of fluid k moving from the
 *   neighbour into the owner across face f, lambda/links of the edge
 *   cell's difference to the outside cell's share (its fluids' volume
 *   kept), the outside cell giving each link at most 1/links of each
 *   fluid it holds; sum_k d[k][f] = 0.  The caller adds d/V to the owner
 *   and takes it from the neighbour.
 */
#define VHE_DRAIN_MAX 16
void vhe_drain_links(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *const *aNei, const double *heldNei,
                     double lo, double *links);
void vhe_drain_range(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *const *aNei, const double *heldNei,
                     double lo, double *const *sum, double *const *mn,
                     double *const *mx);
void vhe_drain_lambda(long n, int K, const double *const *a,
                      const double *links, const double *const *sum,
                      const double *const *mn, const double *const *mx,
                      double *lambda);
void vhe_drain_faces(long nFaces, const int *own, const int *nei, int K,
                     const double *const *a, const double *held,
                     const double *V, const double *links,
                     const double *lambda, const double *const *aNei,
                     const double *heldNei, const double *VNei,
                     const double *linksNei, const double *lambdaNei,
                     double lo, double *const *d);

/* ---------------------------------------------------------------- compress */

/*
 * vhe_compress_pair: interface compression of phase i against phase j on
 * nFaces faces (compress.c), multiphaseMixture's with linear face values:
 * C = phic (n . Sf) a_i a_j, n = g/(|g| + deltaN), g = a_j grad a_i -
 * a_i grad a_j; fi += C, fj -= C (faces with a_i a_j < 1e-15, where C
 * is below round-off, skipped).  phic [m/s]; Sf [m^2] and the face
 * gradients gi, gj [1/m] 3 per face; ai, aj face values; deltaN [1/m];
 * fi, fj the phases' fluxes [m^3/s].
 */
void vhe_compress_pair(long nFaces, const double *phic, const double *Sf,
                       const double *ai, const double *aj, const double *gi,
                       const double *gj, double deltaN, double *fi,
                       double *fj);

/* ---------------------------------------------------------------- tension */

/*
 * vhe_height_curvature: the curvature of an interface y = h(x1, x2) from
 * its heights h[3 (i + 1) + (j + 1)] at the offsets (i d1, j d2), i, j in
 * {-1, 0, 1}, by central differences (tension.c): dim 2 uses h[1], h[4],
 * h[7] (offsets along x1 only) and returns -h''/(1 + h'^2)^(3/2); dim 3 returns
 * -(h11 (1 + h2^2) + h22 (1 + h1^2) - 2 h12 h1 h2)/(1 + h1^2 + h2^2)^(3/2).
 * The sign is interFoam's K = -div(n) with n toward the side below the
 * heights: a drop below y = h (a cap) has K > 0.  Second order in d.
 */
double vhe_height_curvature(const double h[9], double d1, double d2,
                            int dim);

/* ----------------------------------------------------------------- anderson */

/*
 * Anderson acceleration (type II) of a fixed point x = G(x), residual
 * f = G(x) - x, over the last m differences dF_i of residuals and dG_i of
 * map values: x_new = G(x_k) - sum_i gamma_i dG_i with gamma minimising
 * |f_k - sum_i gamma_i dF_i| (GMRES on a linear map).
 *   gram[i*m + j] = <dF_i, dF_j>,  b[i] = <dF_i, f_k>  (the caller's inner
 *   product, summed over processors);  gamma[m] out.
 * The normal equations are solved with the columns scaled to unit norm
 * and 1e-10 added to the diagonal; a column of zero norm takes gamma 0.
 * Returns VHE_OK, or VHE_EBADARG (m outside [0, VHE_ANDERSON_MAX], NULL).
 */
#define VHE_ANDERSON_MAX 16
int vhe_anderson_gamma(int m, const double *gram, const double *b,
                       double *gamma);

/* ---- Fractions into bounds (bound.c) -----------------------------------
 *
 * vhe_bound_fractions: nS fraction fields a[k] over nCells cells with
 *   volumes V, carried one by one (so each may leave [0, 1] a little and
 *   their sum exceed 1), brought into bounds by moving volume over internal
 *   faces (own/nei; the faces of cell c are cellFaces[cellStart[c] ..
 *   cellStart[c+1]-1], those from nInt on boundary faces, skipped): a
 *   fraction below 0 takes what it lacks from the
 *   neighbours holding that field, in proportion to what they hold; a
 *   cell whose fields sum above 1 gives the excess to its neighbours with
 *   room (1 - sum), in proportion to the room, each field's part in
 *   proportion to its fraction.  Each move dV over face f adds +-dV/dt to
 *   flux[k][f] (positive from owner to neighbour), so that the fields stay
 *   the fluxes' update.  Up to nSweeps passes of each kind; s (nCells) is
 *   work space and ends as the sum.  Volumes are kept to round-off.
 *   Returns the volume moved.
 */
double vhe_bound_fractions(long nCells, long nInt, const int *own,
                           const int *nei, const long *cellStart,
                           const int *cellFaces, const double *V, int nS,
                           double *const *a, double *const *flux, double dt,
                           double *s, int nSweeps);

/* vhe_bound_downwind: one fraction field a (after its fluxes' update) put
 *   back into [0, 1] the way the flux went wrong: (above) a cell above
 *   1 + tol passes the excess on through its downwind faces
 *   (outflow phi > 0 from the cell), in proportion to their outflow and up
 *   to a full face (dVf = phi dt); (below) a cell below -tol lets less out
 *   through its downwind faces, in proportion to their outflow and down to
 *   none (dVf = 0).  (isoAdvector's conservative bounding, Roenby et al.
 *   2016.)  dVf [m^3] is the volume over each face over the step
 *   (positive out of the owner), phi the volume flux [m^3/s]; both stay in
 *   step with a.  Faces from nInt on are boundary faces (own only): what
 *   passes through one leaves a (the caller gives a coupled face's volume
 *   to the cell on its other side).  Only cells with check[c] != 0 (all if check is
 *   NULL).  Up to nSweeps passes; what is left (no downwind room) is for
 *   vhe_bound_fractions.  Returns the volume moved.
 */
double vhe_bound_downwind(long nCells, long nInt, const int *own,
                          const int *nei, const long *cellStart,
                          const int *cellFaces, const double *V,
                          const double *phi, double *dVf, double *a,
                          double dt, const unsigned char *check, int above,
                          int below, double tol, int nSweeps);

/* ---- A cell cut by an isosurface (cut.c) ---------------------------------
 *
 * A polyhedral cell: npoints points x (3 per point), nfaces faces, face k's
 * points (indices into the cell's points) face_pts[face_start[k] ..
 * face_start[k+1]), listed with the right-hand normal out of the cell
 * unless flip[k] (OpenFOAM: the cell is the face's neighbour); x0 a point
 * inside (the cell centre: the volume sums' origin).
 */
struct vhe_cell {
    int npoints;
    const double *x;
    int nfaces;
    const int *face_start;
    const int *face_pts;
    const unsigned char *flip;
    double x0[3];
};

/* The part of a cell where the point field f > iso (f linear along the
 * edges): status 0 cut, 1 none of the cell, -1 all of it; its volume [m^3]
 * (vhe_cell_cut_fraction: its fraction of the cell); the cut's area vector,
 * out of the part, and its centre. */
struct vhe_cut {
    int status;
    double iso;
    double volume;
    double area[3];
    double centre[3];
};

/* vhe_polygon_fan: a polygon of np points p (3 per point, in order
 *   round it): its mean point m and its area vector S, the sum over its
 *   fan of triangles about m of (p_i - m) x (p_i+1 - m)/2 (right-hand
 *   order; exact for a plane polygon, OpenFOAM's face area otherwise). */
void vhe_polygon_fan(int np, const double *p, double m[3], double S[3]);

/* vhe_cell_cut: the part where f > iso.  Returns 0, or -1 for a face of
 *   more than 32 points. */
int vhe_cell_cut(const struct vhe_cell *cell, const double *f, double iso,
                 struct vhe_cut *out);

/* vhe_cell_cut_fraction: the iso value whose part holds the fraction alpha
 *   of the cell (volume V), to tol in the fraction.  A field of unknown
 *   form (g <= 0): the bracketing pair of point values by bisection, then
 *   the cubic the fraction is on it, checked on the cell
 *   (isoCutCell::vofCutCell's method, without its allocations).  A linear
 *   field whose gradient has magnitude g (a plane): Newton from guess
 *   (ignored outside the point values), the fraction's derivative being
 *   -|cut area|/(g V), kept in its bracket.  out->volume is the fraction
 *   reached.  Returns 0, 1 when tol was not reached, -1 for a cell the cut
 *   cannot handle. */
int vhe_cell_cut_fraction(const struct vhe_cell *cell, const double *f,
                          double V, double alpha, double tol, double g,
                          double guess, struct vhe_cut *out);

/* ---- The volume a moving plane carries through a face (sweep.c) --------
 *
 * vhe_face_sweep: a face of n points x (3 per point, in order round it),
 * the fluid behind the plane through x0 of unit normal nrm, (x - x0).nrm
 * < 0, the plane moving along nrm at Un [m/s].  Returns the volume that
 * crosses the face over dt with the face flux phi [m^3/s] (face area magSf):
 * phi/magSf times the integral over [0, dt] of the face's area where
 * (x - x0).nrm < Un t (isoAdvector's time-integrated face flux; exact for
 * a plane face: two-point Gauss between the times the plane reaches the
 * face's points).  |Un| <= Untol: the plane at rest.  0 for a face of
 * fewer than 3 or more than 32 points.
 */
double vhe_face_sweep(int n, const double *x, const double x0[3],
                      const double nrm[3], double Un, double dt,
                      double phi, double magSf, double Untol);

#ifdef __cplusplus
}
#endif

#endif /* VHE_H */
