/* The material point of the correspondence solid (paper 003 Sec. 2, 4: an
 * "isothermal large-deformation inelastic solid", J2 plasticity with linear
 * isotropic hardening, ductile and brittle bond damage), 2D, one bond (or
 * one point) at a time; the construction of
 * ../shared/notes/correspondence_and_penalty.md 1c.5-1c.8.
 *
 * Kinematics (1c.5, 1c.6): with the bond's F and Fdot,
 *     F = R U (polar),  R = rotation by theta = atan2(F21 - F12, F11 + F22)
 *     D = sym(Fdot F^-1),  d_hat = R^T D R          (unrotated rate of deformation)
 *     sigma = R sigma_hat R^T,  P = J sigma F^-T    (Cauchy, first Piola-Kirchhoff)
 * The unrotated stress sigma_hat is integrated with the hypoelastic law, so
 * the objective rate is Green-Naghdi's (Peridigm's and PdShell's choice,
 * there through the Flanagan-Taylor incremental R). In 2D the rotation is
 * about z only and has this closed form, exact for any F with det F > 0
 * (F = R(phi) U gives F21 - F12 = sin(phi) tr U, F11 + F22 = cos(phi) tr U,
 * tr U > 0): no rotation history to store and no singular case.
 *
 * Constitutive update (1c.7), strain increment de = d_hat dt:
 *     sigma_tr = sigma_n + 2 G dev(de) + K tr(de) I,  s_tr = dev sigma_tr
 *     q_tr = sqrt(3/2 s_tr : s_tr),  f = q_tr - (sigma_Y + H eqps_n)
 *     f <= 0: elastic;  else deqps = f / (3 G + H),
 *     sigma_{n+1} = sigma_tr - 3 G deqps s_tr / q_tr,  eqps += deqps
 * With linear hardening the one-step return is the exact backward-Euler
 * solution; along a path whose deviatoric direction is fixed (uniaxial
 * stress or strain) it is the exact solution of the rate equations, for any
 * step size (tests/unit/solid/correspondence/test_j2.c, C7).
 * 2D: plane strain keeps de_zz = 0 and sigma_zz in the 3D update; plane
 * stress finds de_zz with sigma_zz = 0 by Newton's method on the consistent
 * tangent (1c.7, PdShell's loop)
 *     C33 = K + (4/3) G theta - 2 G theta_bar n_zz^2,  theta = 1 - 3 G deqps / q_tr,
 *     theta_bar = 3 G / (3 G + H) - (1 - theta),  n = s_tr / |s_tr|
 * (elastic: theta = 1, theta_bar = 0, C33 = K + 4G/3), safeguarded by a
 * bracket (sigma_zz(de_zz) is increasing but has a kink at first yield).
 *
 * Damage (1c.8): ductile on the bond's eqps, brittle on its maximum
 * principal Cauchy stress; the caller keeps them non-decreasing (max with
 * the previous value).
 *
 * Stress is [xx, yy, zz, xy] everywhere (4 doubles); in-plane strain
 * increments are [xx, yy, xy] with the tensor shear (not engineering);
 * 2x2 matrices are row-major [a11, a12, a21, a22]. */
#ifndef NSPD_SOLID_CORRESPONDENCE_J2_KERNEL_H
#define NSPD_SOLID_CORRESPONDENCE_J2_KERNEL_H

#include "core/kernel.h"

#include <math.h>

typedef struct {
    double bulk, shear;      /* K, G (Pa) */
    double yield, hardening; /* sigma_Y, H = d sigma_y / d eqps (Pa); yield <= 0 or >= 1e300:
                                elastic only */
    int plane_stress;        /* 0: plane strain (d_zz = 0); 1: plane stress (sigma_zz = 0) */
} J2Material;

/* Newton iterations of the plane-stress loop at most: converged ones take
 * 2-4 (quadratic convergence once on one branch of the kink); the bound
 * only stops a pathological input. */
#define J2_PLANE_STRESS_MAX_ITER 30

/* PdShell's width of the brittle ramp (the last 1 % below sigma_cr), the
 * default of j2_damage_brittle's `ramp`. */
#define J2_BRITTLE_RAMP 0.01

/* The material of Young's modulus E, Poisson's ratio nu, yield stress
 * sigma_Y and linear hardening modulus H (all Pa but nu):
 * K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)). */
NSPD_KERNEL J2Material j2_material(double young, double poisson, double yield, double hardening,
                                   int plane_stress) {
    J2Material m;
    m.bulk = young / (3.0 * (1.0 - 2.0 * poisson));
    m.shear = young / (2.0 * (1.0 + poisson));
    m.yield = yield;
    m.hardening = hardening;
    m.plane_stress = plane_stress;
    return m;
}

/* Whether m yields at all (a yield stress <= 0 or >= 1e300 means elastic). */
NSPD_KERNEL int j2_is_plastic(const J2Material *m) {
    return m->yield > 0.0 && m->yield < 1e300;
}

/* R of the polar decomposition F = R U (1c.6): the rotation by
 * theta = atan2(F21 - F12, F11 + F22), written without trigonometry:
 * cos theta = a / r, sin theta = b / r with a = F11 + F22, b = F21 - F12,
 * r = sqrt(a^2 + b^2) (a^2 + b^2 = |F|^2 + 2 det F > 0 for det F > 0).
 * The libm atan2, cos and sin this replaces were a third of the
 * correspondence step (two rotations per bond per step; PERFORMANCE.md). */
NSPD_KERNEL void j2_polar_rotation_2d(const double F[4], double R[4]) {
    const double a = F[0] + F[3], b = F[2] - F[1];
    const double inv = 1.0 / sqrt(a * a + b * b);
    const double c = a * inv, s = b * inv;
    R[0] = c, R[1] = -s, R[2] = s, R[3] = c;
}

/* The unrotated strain increment de = R^T sym(Fdot F^-1) R dt, [xx, yy, xy]
 * (1c.5), R from F (j2_polar_rotation_2d). Returns 0 (and de = 0) when
 * det F <= 0: an inverted bond, which the caller treats as failed; else 1.
 * F is the configuration the rate belongs to: for a step n -> n+1 with
 * Fdot = (F_{n+1} - F_n) / dt, the midpoint F_{n+1/2} (a rigid rotation
 * then gives D = 0 exactly; with F_{n+1} it gives D = (1 - cos dtheta) / dt I). */
NSPD_KERNEL int j2_unrotated_increment_2d(const double F[4], const double Fdot[4], double dt,
                                          double de[3]) {
    /* branch-free (both answers formed, one kept), so that the loop over
     * bond pairs around it vectorises; the kept answer's bits are those of
     * the branchy form */
    const double det = F[0] * F[3] - F[1] * F[2];
    const int upright = det > 0.0;
    /* L = Fdot F^-1 with F^-1 = adj(F) / det */
    const double a = dt / det;
    const double l11 = (Fdot[0] * F[3] - Fdot[1] * F[2]) * a;
    const double l12 = (Fdot[1] * F[0] - Fdot[0] * F[1]) * a;
    const double l21 = (Fdot[2] * F[3] - Fdot[3] * F[2]) * a;
    const double l22 = (Fdot[3] * F[0] - Fdot[2] * F[1]) * a;
    const double dxx = l11, dyy = l22, dxy = 0.5 * (l12 + l21);
    double R[4];
    j2_polar_rotation_2d(F, R);
    const double c = R[0], s = R[2];
    /* d_hat_ab = e_a'^T D e_b' with e_1' = (c, s), e_2' = (-s, c), R's columns */
    const double e0 = c * c * dxx + 2.0 * c * s * dxy + s * s * dyy;
    const double e1 = s * s * dxx - 2.0 * c * s * dxy + c * c * dyy;
    const double e2 = c * s * (dyy - dxx) + (c * c - s * s) * dxy;
    de[0] = upright ? e0 : 0.0;
    de[1] = upright ? e1 : 0.0;
    de[2] = upright ? e2 : 0.0;
    return upright;
}

/* One radial return (1c.7) from sigma_n, eqps_n for the 3D increment
 * (de[0], de[1], dzz, shear de[2]) into sigma (may alias sigma_n); returns
 * deqps and the tangent d sigma_zz / d de_zz in *c33. */
NSPD_KERNEL double j2_return(const J2Material *m, const double de[3], double dzz,
                             const double sigma_n[4], double eqps_n, double sigma[4], double *c33) {
    const double K = m->bulk, G = m->shear, H = m->hardening;
    const double tr = de[0] + de[1] + dzz, third = tr / 3.0;
    /* trial stress and its deviator */
    const double t0 = sigma_n[0] + 2.0 * G * (de[0] - third) + K * tr;
    const double t1 = sigma_n[1] + 2.0 * G * (de[1] - third) + K * tr;
    const double t2 = sigma_n[2] + 2.0 * G * (dzz - third) + K * tr;
    const double t3 = sigma_n[3] + 2.0 * G * de[2];
    const double p = (t0 + t1 + t2) / 3.0;
    const double s0 = t0 - p, s1 = t1 - p, s2 = t2 - p, s3 = t3;
    const double ss = s0 * s0 + s1 * s1 + s2 * s2 + 2.0 * s3 * s3; /* s : s */
    const double q = sqrt(1.5 * ss);
    const double f = q - (m->yield + H * eqps_n);
    /* both branches formed and one kept (a loop over bond pairs vectorises
     * around this); the elastic one's 0/0 where s_tr = 0 is never kept */
    const int plastic = j2_is_plastic(m) && f > 0.0;
    const double deqps = f / (3.0 * G + H);
    const double theta = 1.0 - 3.0 * G * deqps / q;
    const double theta_bar = 3.0 * G / (3.0 * G + H) - (1.0 - theta);
    const double nzz2 = s2 * s2 / ss; /* n = s_tr / |s_tr|, |s_tr|^2 = s : s */
    sigma[0] = plastic ? p + theta * s0 : t0;
    sigma[1] = plastic ? p + theta * s1 : t1;
    sigma[2] = plastic ? p + theta * s2 : t2;
    sigma[3] = plastic ? theta * s3 : t3;
    *c33 = plastic ? K + 4.0 / 3.0 * G * theta - 2.0 * G * theta_bar * nzz2 : K + 4.0 / 3.0 * G;
    return plastic ? deqps : 0.0;
}

/* The plane-stress Newton loop of j2_update_zz, one iteration at a time,
 * so that a loop over bond pairs can take a fixed number of them in SIMD
 * lanes (each lane stops as the scalar loop would: j2_zz_iterate leaves a
 * finished state as it is) and leave the few unfinished to the scalar
 * loop. out, deqps and z are the answer once done. */
typedef struct {
    double z, lo, hi, out[4], deqps;
    /* flags and the count as doubles (0 or 1; whole numbers): in SIMD lanes
     * beside the numbers, GCC 12 does not mix int masks with double ones */
    double have_lo, have_hi, it, done;
} J2ZzNewton;

/* The elastic answer (exact when the step stays elastic) and an empty
 * bracket. */
NSPD_KERNEL void j2_zz_start(const J2Material *m, const double de[3], const double sigma_n[4],
                             J2ZzNewton *s) {
    const double lambda = m->bulk - 2.0 / 3.0 * m->shear;
    s->z = -(sigma_n[2] + lambda * (de[0] + de[1])) / (lambda + 2.0 * m->shear);
    s->lo = s->hi = 0.0;
    s->have_lo = s->have_hi = 0.0;
    s->it = 0.0;
    s->done = 0.0;
    NSPD_UNROLL(4)
    for (int q = 0; q < 4; q++) s->out[q] = 0.0;
    s->deqps = 0.0;
}

/* One iteration: the radial return at s->z; done when |sigma_zz| <= 1e-12
 * (|sigma| + sigma_Y) or after J2_PLANE_STRESS_MAX_ITER iterations, else
 * the bracket (sigma_zz increases with de_zz) and the next z, Newton on
 * C33 or, when that leaves the bracket (the kink at first yield),
 * bisection. Branch-free (selects): nothing changes once done. */
NSPD_KERNEL void j2_zz_iterate(const J2Material *m, const double de[3], const double sigma_n[4],
                               double eqps_n, J2ZzNewton *s) {
    const double yield = j2_is_plastic(m) ? m->yield : 0.0;
    double out[4], c33;
    const double deqps = j2_return(m, de, s->z, sigma_n, eqps_n, out, &c33);
    const double r = out[2];
    const double size =
        sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] + 2.0 * out[3] * out[3]);
    /* Written for SIMD lanes: the comparisons quiet (NSPD_GT, ...: the
     * same answers, NaN false), since an ordered one may trap and GCC then
     * keeps it under its branch; and the flags doubles, 1 or 0, each from
     * one comparison and combined by exact products and differences: GCC 12
     * vectorises neither int masks beside doubles nor a mask selected by a
     * mask. */
    const double converged = NSPD_LE(fabs(r), 1e-12 * (size + yield)) ? 1.0 : 0.0;
    const double stop = s->it == (double)J2_PLANE_STRESS_MAX_ITER ? 1.0 : converged;
    const double active = s->done == 0.0 ? 1.0 : 0.0;
    const double finish = active * stop, go_on = active - finish;
    const double rise = go_on * (NSPD_GT(r, 0.0) ? 1.0 : 0.0), fall = go_on - rise;
    NSPD_UNROLL(4)
    for (int q = 0; q < 4; q++) s->out[q] = finish != 0.0 ? out[q] : s->out[q];
    s->deqps = finish != 0.0 ? deqps : s->deqps;
    const double hi = rise != 0.0 ? s->z : s->hi, lo = fall != 0.0 ? s->z : s->lo;
    const double have_hi = rise != 0.0 ? 1.0 : s->have_hi;
    const double have_lo = fall != 0.0 ? 1.0 : s->have_lo;
    double next = s->z - r / c33;
    const double inside = NSPD_GT(next, lo) ? (NSPD_LT(next, hi) ? 1.0 : 0.0) : 0.0;
    next = have_lo * have_hi * (1.0 - inside) != 0.0 ? 0.5 * (lo + hi) : next;
    s->lo = lo, s->hi = hi, s->have_lo = have_lo, s->have_hi = have_hi;
    s->z = go_on != 0.0 ? next : s->z;
    s->it = s->it + go_on;
    s->done = s->done + finish;
}

/* One hypoelastic step with J2 radial return and linear isotropic hardening
 * (1c.7) on the unrotated Cauchy stress sigma[4] and the equivalent plastic
 * strain *eqps, for the in-plane increment de[3] ([xx, yy, xy], tensor
 * shear). Plane strain: de_zz = 0. Plane stress: de_zz such that
 * sigma_zz = 0, by Newton on C33 (j2_zz_iterate) until converged;
 * sigma_zz of the input is not assumed zero. Returns the plastic increment
 * deqps (0 if elastic) and, in *dzz, de_zz (0 in plane strain): the
 * thickness's logarithmic strain grows by it, and plane-stress forces
 * scale with the thickness (j2_piola_2d). */
NSPD_KERNEL double j2_update_zz(const J2Material *m, const double de[3], double sigma[4],
                                double *eqps, double *dzz) {
    const double eqps_n = *eqps;
    double z = 0.0; /* de_zz: 0 in plane strain */
    double out[4], c33, deqps;
    if (!m->plane_stress) {
        deqps = j2_return(m, de, 0.0, sigma, eqps_n, out, &c33);
    } else {
        J2ZzNewton s;
        j2_zz_start(m, de, sigma, &s);
        while (s.done == 0.0) j2_zz_iterate(m, de, sigma, eqps_n, &s);
        for (int q = 0; q < 4; q++) out[q] = s.out[q];
        deqps = s.deqps, z = s.z;
    }
    sigma[0] = out[0], sigma[1] = out[1], sigma[2] = out[2], sigma[3] = out[3];
    *eqps = eqps_n + deqps;
    *dzz = z;
    return deqps;
}

/* j2_update_zz without the out-of-plane increment. */
NSPD_KERNEL double j2_update(const J2Material *m, const double de[3], double sigma[4],
                             double *eqps) {
    double dzz;
    return j2_update_zz(m, de, sigma, eqps, &dzz);
}

/* The Cauchy stress sigma = R sigma_hat R^T (sigma_zz unchanged). */
NSPD_KERNEL void j2_rotate_stress_2d(const double R[4], const double sigma_hat[4],
                                     double sigma[4]) {
    /* A = R sigma_hat (in-plane), then sigma = A R^T */
    const double a11 = R[0] * sigma_hat[0] + R[1] * sigma_hat[3];
    const double a12 = R[0] * sigma_hat[3] + R[1] * sigma_hat[1];
    const double a21 = R[2] * sigma_hat[0] + R[3] * sigma_hat[3];
    const double a22 = R[2] * sigma_hat[3] + R[3] * sigma_hat[1];
    sigma[0] = a11 * R[0] + a12 * R[1];
    sigma[1] = a21 * R[2] + a22 * R[3];
    sigma[2] = sigma_hat[2];
    sigma[3] = a11 * R[2] + a12 * R[3];
}

/* The first Piola-Kirchhoff stress, in-plane 2x2 row-major (1c.5):
 * sigma = R sigma_hat R^T, P = J sigma F^-T with J = det F (the in-plane
 * area ratio: plane strain keeps the thickness). J F^-T is the cofactor
 * matrix of F, so no division: P = sigma cof(F). In plane stress the
 * thickness changes too, by the stretch exp(sum de_zz) of j2_update_zz:
 * the caller multiplies P by it (bac_force, classic_force). */
NSPD_KERNEL void j2_piola_2d(const double F[4], const double sigma_hat[4], double P[4]) {
    double R[4], s[4];
    j2_polar_rotation_2d(F, R);
    j2_rotate_stress_2d(R, sigma_hat, s);
    /* cof(F) = [[F22, -F21], [-F12, F11]] */
    P[0] = s[0] * F[3] - s[3] * F[1];
    P[1] = -s[0] * F[2] + s[3] * F[0];
    P[2] = s[3] * F[3] - s[1] * F[1];
    P[3] = -s[3] * F[2] + s[1] * F[0];
}

/* fmax and fmin with libm's exact answers (the larger or smaller; a NaN
 * operand gives the other one; of two equal values, the second), written
 * as selects: GCC calls libm for fmax and fmin unless NaNs are ruled out,
 * and a call keeps the loops over bonds scalar. */
NSPD_KERNEL double j2_fmax(double a, double b) {
    return (a > b || b != b) ? a : b;
}
NSPD_KERNEL double j2_fmin(double a, double b) {
    return (a < b || b != b) ? a : b;
}

/* The maximum principal value of a (rotated, Cauchy) stress [xx, yy, zz, xy]:
 * the larger in-plane eigenvalue c + r, c = (sxx + syy) / 2,
 * r = sqrt(((sxx - syy) / 2)^2 + sxy^2), or sigma_zz if larger. */
NSPD_KERNEL double j2_max_principal(const double sigma[4]) {
    const double c = 0.5 * (sigma[0] + sigma[1]), h = 0.5 * (sigma[0] - sigma[1]);
    return j2_fmax(c + sqrt(h * h + sigma[3] * sigma[3]), sigma[2]);
}

/* Ductile bond damage (1c.8, PdShell computeDamageByPlasticStrain; paper:
 * threshold 0.18, critical 0.2): clamp((eqps - threshold) /
 * (critical - threshold), 0, 1). Needs critical > threshold. */
NSPD_KERNEL double j2_damage_ductile(double eqps, double threshold, double critical) {
    const double d = (eqps - threshold) / (critical - threshold);
    return j2_fmin(j2_fmax(d, 0.0), 1.0);
}

/* Brittle bond damage on the maximum principal Cauchy stress s1 (1c.8):
 * the paper breaks a bond "once its associated maximum principal stress
 * exceeds sigma_cr" (a step); PdShell (computeDamageByPrincipalStress) ramps
 * over the last 1 % "to enhance stability": with r = s1 / critical,
 * clamp((r - (1 - ramp)) / ramp, 0, 1), ramp = J2_BRITTLE_RAMP (0.01) by default. ramp <= 0
 * is the paper's step: 1 when s1 > critical, else 0. */
NSPD_KERNEL double j2_damage_brittle(double max_principal, double critical, double ramp) {
    const double r = max_principal / critical;
    if (!(ramp > 0.0)) return r > 1.0 ? 1.0 : 0.0;
    return j2_fmin(j2_fmax((r - (1.0 - ramp)) / ramp, 0.0), 1.0);
}

/* One material step of a bond pair (bac_force) or a point (classic_force)
 * in 2D, from F_n = Fp to F_{n+1} = F (in-plane 2 x 2, row-major): the
 * midpoint increment (j2_unrotated_increment_2d), the J2 update (plane
 * strain: j2_return with de_zz = 0; plane stress: j2_update_zz's Newton
 * iterations, the thickness strain grown by de_zz), the maximum principal
 * stress and P2 = sigma cof(F), without the plane-stress thickness stretch
 * (j2_step_2d applies it). Where det F or det F_mid is not positive the
 * pair or point has inverted: P2 = 0, principal 0, and its state (sigma,
 * eqps, strain_zz) is left as it was. Returns 1 when inverted, else 0.
 * plane_stress must be m->plane_stress and newton a constant at each call:
 * plane strain gets no Newton loop at all, and newton > 0 takes at most
 * that many plane-stress iterations, unrolled, setting *finished to 0.0,
 * else 1.0 (a double: a mask beside the numbers in SIMD lanes), and the
 * outputs to no answer when they were not enough; newton = 0 iterates
 * to the end. Branch-free otherwise (the kept answers are formed by the
 * same expressions), so that a loop over pairs vectorises around it.
 * strain_zz is read only in plane stress. */
NSPD_KERNEL int j2_step_2d_lane(const J2Material *m, const int plane_stress, const int newton,
                                const double F[4], const double Fp[4], double sigma[4],
                                double *eqps, double *strain_zz, double P2[4], double *principal,
                                double *finished) {
    const double Fm[4] = {0.5 * (Fp[0] + F[0]), 0.5 * (Fp[1] + F[1]), 0.5 * (Fp[2] + F[2]),
                          0.5 * (Fp[3] + F[3])};
    const double dF[4] = {F[0] - Fp[0], F[1] - Fp[1], F[2] - Fp[2], F[3] - Fp[3]};
    double de[3], s[4], e, dzz = 0.0, c33;
    const int upright = F[0] * F[3] - F[1] * F[2] > 0.0;
    const int ok = upright & j2_unrotated_increment_2d(Fm, dF, 1.0, de);
    *finished = 1.0;
    if (plane_stress && newton > 0) {
        J2ZzNewton z;
        j2_zz_start(m, de, sigma, &z);
        NSPD_UNROLL(8)
        for (int t = 0; t < newton; t++) j2_zz_iterate(m, de, sigma, *eqps, &z);
        NSPD_UNROLL(4)
        for (int q = 0; q < 4; q++) s[q] = z.out[q];
        e = *eqps + z.deqps, dzz = z.z;
        *finished = z.done;
    } else if (plane_stress) {
        NSPD_UNROLL(4)
        for (int q = 0; q < 4; q++) s[q] = sigma[q];
        e = *eqps;
        j2_update_zz(m, de, s, &e, &dzz);
    } else {
        e = *eqps + j2_return(m, de, 0.0, sigma, *eqps, s, &c33);
    }
    double P[4];
    j2_piola_2d(F, s, P);
    NSPD_UNROLL(4)
    for (int q = 0; q < 4; q++) P2[q] = ok ? P[q] : 0.0;
    *principal = ok ? j2_max_principal(s) : 0.0;
    NSPD_UNROLL(4)
    for (int q = 0; q < 4; q++) sigma[q] = ok ? s[q] : sigma[q];
    *eqps = ok ? e : *eqps;
    if (plane_stress) *strain_zz = ok ? *strain_zz + dzz : *strain_zz;
    return !ok;
}

/* j2_step_2d_lane to the end, with the plane-stress thickness stretch
 * exp(strain_zz) on P. */
NSPD_KERNEL int j2_step_2d(const J2Material *m, int plane_stress, const double F[4],
                           const double Fp[4], double sigma[4], double *eqps, double *strain_zz,
                           double P[4], double *principal) {
    double finished;
    const int inverted =
        j2_step_2d_lane(m, plane_stress, 0, F, Fp, sigma, eqps, strain_zz, P, principal, &finished);
    if (plane_stress && !inverted) {
        const double thick = exp(*strain_zz);
        for (int q = 0; q < 4; q++) P[q] = thick * P[q];
    }
    return inverted;
}

#endif
