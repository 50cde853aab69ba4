/* Sums of doubles that do not depend on their order (issue 28).
 *
 * A floating-point sum depends on the order of its terms, so a total that
 * several processes share (a dot product of a Krylov solver whose vector
 * is divided between them) would change with the number of processes.
 * ExactSum adds every term exactly, into a fixed-point integer that spans
 * every double (a long accumulator in the manner of Kulisch's: 32-bit
 * digits in 64-bit words, so 2^31 terms add before a carry is needed), and
 * rounds only once, when the value is read. Integer additions are
 * associative, so the total is the same bits for any order of the terms,
 * any split of them between threads or processes, and any number of
 * processes (exact_sum_reduce adds the accumulators with an integer
 * MPI_SUM, which is exact).
 *
 * The price is an add of three words per term instead of one floating
 * add: meant for reductions of thousands of terms a step (the penalty
 * coupling's conjugate gradients), not for a flux loop. */
#ifndef NSPD_CORE_EXACT_SUM_H
#define NSPD_CORE_EXACT_SUM_H

#include "core/comm.h"

#include <stdint.h>

/* Digits of 32 bits: bit b of digit k has the value 2^(32 k + b -
 * EXACT_SUM_BIAS), so the smallest subnormal is bit 52 of digit 0 and the
 * largest double's top bit lies in digit 67; two more hold the carries of
 * 2^31 terms of either sign. */
enum { EXACT_SUM_DIGITS = 70, EXACT_SUM_BIAS = 1126 };

typedef struct {
    int64_t digit[EXACT_SUM_DIGITS];
    /* terms that were not finite: NaNs, +inf, -inf (counts, so that they
     * too add in any order) */
    int64_t nan, pos_inf, neg_inf;
    int64_t adds; /* since the last carry (a carry every 2^30 adds) */
} ExactSum;

void exact_sum_clear(ExactSum *s);
/* s += x, exactly. */
void exact_sum_add(ExactSum *s, double x);
/* dst += src (both exact: a sum split between threads, then joined). */
void exact_sum_merge(ExactSum *dst, const ExactSum *src);
/* The sum rounded to the nearest double (ties to even; a sum below the
 * normal range rounds twice, within one unit of its last place); NaN if a term was NaN or +inf and
 * -inf were both added, +-inf if one of those was, or if the sum overflows. The same bits for the
 * same exact sum, however it was formed. */
double exact_sum_value(const ExactSum *s);
/* The accumulators s[0..count) of every rank of c added, on every rank
 * (collective: an integer reduction per four; allocates nothing). */
int exact_sum_reduce(const NspdComm *c, ExactSum *s, int count);

#endif
