/* Branch-free exp, log and erfc for the GKS kernels.
 *
 * The flux loop runs over a row of faces under `omp simd`; a call to libm's
 * exp or erfc would keep it scalar (glibc's vector variants are only declared
 * under -ffast-math, which nspd does not use). These versions are plain
 * arithmetic and bit operations, so they vectorise, and they give the same
 * bits in the vector body and in the scalar remainder.
 *
 * gks_exp: Cody-Waite reduction x = k ln2 + r, |r| <= ln2/2, degree-12
 *   Taylor polynomial (truncation 2e-16), 2^k assembled in the exponent
 *   field. Relative error < 3e-16 on [-708, 709]; inputs below -708
 *   (including -inf) return exp(-708) ~ 3e-308, i.e. zero for every use here.
 * gks_erfcx: erfcx(z) = exp(z^2) erfc(z) for z >= 0 as t P(s), t = 3/(3+z),
 *   s = 2t - 1, P a 22-term Chebyshev series fitted (Chebyshev interpolation
 *   in long double against erfcl) for this project. erfc(z) = erfcx(z) exp(-z^2)
 *   then has relative error < 5e-15 for z < 6 and < 7e-14 up to underflow,
 *   the excess being the rounding of z^2 inside exp(-z^2), shared with the
 *   half-space moments that use the same exponential.
 * gks_log: x = m 2^e with m in [sqrt(1/2), sqrt(2)), log m = 2 atanh(s),
 *   s = (m-1)/(m+1), odd series to s^19. Relative error < 4e-16 for normal
 *   positive x; used only for the power-law viscosity.
 * Their polynomial and recurrence steps are fused multiply-adds (NSPD_FMA,
 * core/kernel.h) where the target has them; the bounds above hold both
 * ways (tests/unit/flow/gks/test_moments.c). */
#ifndef NSPD_FLOW_GKS_SPECIAL_FUNCTIONS_H
#define NSPD_FLOW_GKS_SPECIAL_FUNCTIONS_H

#include "core/kernel.h"

#include <stdint.h>
#include <string.h>

NSPD_KERNEL double gks_bits_to_double(uint64_t b) {
    double d;
    memcpy(&d, &b, sizeof d);
    return d;
}

NSPD_KERNEL uint64_t gks_double_to_bits(double d) {
    uint64_t b;
    memcpy(&b, &d, sizeof b);
    return b;
}

NSPD_KERNEL double gks_exp(double x) {
    const double shifter = 0x1.8p52; /* adding it rounds to an integer held in the low bits */
    /* Cody-Waite split of ln 2 (fdlibm's): ln2_hi has 21 trailing zero bits,
     * so k * ln2_hi is exact for |k| < 2^21 without relying on FMA. */
    const double ln2_hi = 0x1.62e42feep-1, ln2_lo = 0x1.a39ef35793c76p-33;
    x = x < -708.0 ? -708.0 : x;
    x = x > 709.0 ? 709.0 : x;
    const double kt = x * 0x1.71547652b82fep0 + shifter;
    const double k = kt - shifter;
    const double r = (x - k * ln2_hi) - k * ln2_lo;
    double p = 1.0 / 479001600.0;
    p = NSPD_FMA(p, r, 1.0 / 39916800.0);
    p = NSPD_FMA(p, r, 1.0 / 3628800.0);
    p = NSPD_FMA(p, r, 1.0 / 362880.0);
    p = NSPD_FMA(p, r, 1.0 / 40320.0);
    p = NSPD_FMA(p, r, 1.0 / 5040.0);
    p = NSPD_FMA(p, r, 1.0 / 720.0);
    p = NSPD_FMA(p, r, 1.0 / 120.0);
    p = NSPD_FMA(p, r, 1.0 / 24.0);
    p = NSPD_FMA(p, r, 1.0 / 6.0);
    p = NSPD_FMA(p, r, 0.5);
    p = NSPD_FMA(p, r, 1.0);
    p = NSPD_FMA(p, r, 1.0);
    /* The low bits of kt are k (two's complement); shifted into the exponent
     * field with the bias they give 2^k (k >= -1021 after the clamp). */
    const uint64_t scale = (gks_double_to_bits(kt) + 1023u) << 52;
    return p * gks_bits_to_double(scale);
}

NSPD_KERNEL double gks_erfcx(double z) {
    static const double c[22] = {
        4.71146074660290654e-01,  3.77158949691565791e-01,  1.18036033447495455e-01,
        2.83623466996951514e-02,  4.87175775760554558e-03,  4.59852387876545759e-04,
        -2.14302223810550047e-05, -1.30144736992396957e-05, -8.80928358286486630e-07,
        2.74648004797485009e-07,  4.41599189927534287e-08,  -6.39840838690649666e-09,
        -1.67683571936394600e-09, 1.94733544867588236e-10,  6.24744145921579737e-11,
        -8.12455789518670260e-12, -2.33031514068808849e-12, 4.19105325013589383e-13,
        8.19325942047926891e-14,  -2.33536260878872894e-14, -2.25193226597763075e-15,
        1.34597762783145075e-15};
    const double t = 3.0 / (3.0 + z), s = 2.0 * t - 1.0, s2 = 2.0 * s;
    double b1 = 0.0, b2 = 0.0;
    NSPD_UNROLL(24)
    for (int k = 21; k >= 1; k--) {
        const double b = NSPD_FMA(s2, b1, -b2) + c[k];
        b2 = b1;
        b1 = b;
    }
    return t * (NSPD_FMA(s, b1, -b2) + c[0]);
}

NSPD_KERNEL double gks_log(double x) {
    const uint64_t bits = gks_double_to_bits(x);
    /* Split x = m 2^e with m in [sqrt(1/2), sqrt(2)): offset the bits so that
     * the exponent rounds at sqrt(2) instead of 2. */
    const uint64_t off = bits - 0x3fe6a09e667f3bcdu;
    const int64_t e = (int64_t)off >> 52;
    const double m = gks_bits_to_double(bits - ((uint64_t)e << 52));
    const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
    double p = 1.0 / 19.0;
    p = NSPD_FMA(p, s2, 1.0 / 17.0);
    p = NSPD_FMA(p, s2, 1.0 / 15.0);
    p = NSPD_FMA(p, s2, 1.0 / 13.0);
    p = NSPD_FMA(p, s2, 1.0 / 11.0);
    p = NSPD_FMA(p, s2, 1.0 / 9.0);
    p = NSPD_FMA(p, s2, 1.0 / 7.0);
    p = NSPD_FMA(p, s2, 1.0 / 5.0);
    p = NSPD_FMA(p, s2, 1.0 / 3.0);
    p = NSPD_FMA(p, s2, 1.0);
    /* Cody-Waite split of ln 2 (fdlibm's): ln2_hi has 21 trailing zero bits,
     * so k * ln2_hi is exact for |k| < 2^21 without relying on FMA. */
    const double ln2_hi = 0x1.62e42feep-1, ln2_lo = 0x1.a39ef35793c76p-33;
    const double ed = (double)e;
    return ed * ln2_hi + (2.0 * s * p + ed * ln2_lo);
}

#endif
