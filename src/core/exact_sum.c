/* Sums of doubles that do not depend on their order (exact_sum.h). */
#include "core/exact_sum.h"

#include "core/status.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

enum { WORDS = EXACT_SUM_DIGITS + 3 }; /* the digits and the three counts */

void exact_sum_clear(ExactSum *s) {
    memset(s, 0, sizeof *s);
}

/* Every digit but the last into [0, 2^32), the rest carried up: the one
 * form of a number, whatever the adds that made it. */
static void carry(int64_t *d) {
    for (int k = 0; k < EXACT_SUM_DIGITS - 1; k++) {
        const int64_t low = d[k] & INT64_C(0xffffffff);
        d[k + 1] += (d[k] - low) / INT64_C(4294967296); /* exact: a multiple of 2^32 */
        d[k] = low;
    }
}

void exact_sum_add(ExactSum *s, double x) {
    if (x == 0.0) return;
    if (!isfinite(x)) {
        if (isnan(x))
            s->nan++;
        else if (x > 0)
            s->pos_inf++;
        else
            s->neg_inf++;
        return;
    }
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    const int biased = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1); /* |x| = m 2^(place) */
    int place = -1074;                             /* a subnormal's */
    if (biased > 0) {
        m |= UINT64_C(1) << 52;
        place = biased - 1075;
    }
    const int at = place + EXACT_SUM_BIAS; /* m's lowest bit's place among the digits, >= 0 */
    const int k = at >> 5, shift = at & 31;
    /* m 2^shift, up to 85 bits, as three 32-bit digits */
    const uint64_t low = m << shift, high = shift ? m >> (64 - shift) : 0;
    const int64_t sign = bits >> 63 ? -1 : 1;
    s->digit[k] += sign * (int64_t)(low & 0xffffffffu);
    s->digit[k + 1] += sign * (int64_t)(low >> 32);
    s->digit[k + 2] += sign * (int64_t)high;
    if (++s->adds >= INT64_C(1) << 30) { /* a digit takes < 2^32 an add: carry well before 2^63 */
        carry(s->digit);
        s->adds = 0;
    }
}

void exact_sum_merge(ExactSum *dst, const ExactSum *src) {
    ExactSum add = *src;
    carry(add.digit);
    carry(dst->digit);
    for (int k = 0; k < EXACT_SUM_DIGITS; k++) dst->digit[k] += add.digit[k];
    dst->nan += add.nan;
    dst->pos_inf += add.pos_inf;
    dst->neg_inf += add.neg_inf;
    dst->adds = 0;
}

double exact_sum_value(const ExactSum *s) {
    if (s->nan || (s->pos_inf && s->neg_inf)) return (double)NAN;
    if (s->pos_inf) return (double)INFINITY;
    if (s->neg_inf) return -(double)INFINITY;
    int64_t d[EXACT_SUM_DIGITS];
    memcpy(d, s->digit, sizeof d);
    carry(d);
    const bool negative = d[EXACT_SUM_DIGITS - 1] < 0;
    if (negative) {
        for (int k = 0; k < EXACT_SUM_DIGITS; k++) d[k] = -d[k];
        carry(d);
    }
    int h = EXACT_SUM_DIGITS - 1;
    while (h >= 0 && d[h] == 0) h--;
    if (h < 0) return 0.0;
    if (d[h] >= INT64_C(1) << 32) /* beyond every double */
        return negative ? -(double)INFINITY : (double)INFINITY;
    /* the 64 bits from the top one down, the rest a sticky bit: one
     * rounding to 53 bits, to nearest, in the conversion */
    const int top_bit = 32 * h + 63 - __builtin_clzll((unsigned long long)d[h]);
    const int lo_bit = top_bit - 63; /* the window's lowest bit's place */
    uint64_t top = 0;
    bool sticky = false;
    for (int k = h; k >= 0; k--) {
        const uint64_t v = (uint64_t)d[k];
        const int place = 32 * k - lo_bit; /* the digit's lowest bit in the window */
        if (place >= 0) {
            top |= v << place;
        } else if (place > -32) {
            top |= v >> -place;
            sticky = sticky || (v & ((UINT64_C(1) << -place) - 1)) != 0;
        } else {
            sticky = sticky || v != 0;
        }
    }
    if (sticky) top |= 1;
    const double r = ldexp((double)top, lo_bit - EXACT_SUM_BIAS);
    return negative ? -r : r;
}

int exact_sum_reduce(const NspdComm *c, ExactSum *s, int count) {
    if (!comm_distributed(c)) return NSPD_OK;
    enum { BATCH = 4 }; /* accumulators a reduction: no allocation, so no rank fails alone */
    int64_t words[BATCH * WORDS];
    for (int first = 0; first < count; first += BATCH) {
        const int m = count - first < BATCH ? count - first : BATCH;
        for (int q = 0; q < m; q++) {
            ExactSum *a = &s[first + q];
            carry(a->digit); /* digits < 2^32: the ranks' sum cannot overflow */
            int64_t *w = words + q * WORDS;
            memcpy(w, a->digit, sizeof a->digit);
            w[EXACT_SUM_DIGITS] = a->nan;
            w[EXACT_SUM_DIGITS + 1] = a->pos_inf;
            w[EXACT_SUM_DIGITS + 2] = a->neg_inf;
        }
        TRY(comm_sum_i64_array(c, words, m * WORDS));
        for (int q = 0; q < m; q++) {
            ExactSum *a = &s[first + q];
            const int64_t *w = words + q * WORDS;
            memcpy(a->digit, w, sizeof a->digit);
            a->nan = w[EXACT_SUM_DIGITS];
            a->pos_inf = w[EXACT_SUM_DIGITS + 1];
            a->neg_inf = w[EXACT_SUM_DIGITS + 2];
            carry(a->digit);
            a->adds = 0;
        }
    }
    return NSPD_OK;
}
