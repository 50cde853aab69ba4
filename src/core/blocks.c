#include "core/blocks.h"

#include "core/status.h"

#include <stdint.h>

/* The inner faces of a block in a row of q blocks: none alone, one at
 * each end of two (two around a periodic axis), two in the middle. */
static int inner_faces(int q, bool periodic) {
    return q == 1 ? 0 : (q == 2 && !periodic ? 1 : 2);
}

void blocks_fewest_halo(const int n[2], const bool periodic[2], int min_width, int p, int dims[2]) {
    dims[0] = 1, dims[1] = p;
    int64_t best = INT64_MAX;
    for (int px = 1; px <= p; px++) {
        const int py = p / px;
        if (px * py != p || n[0] / px < min_width || n[1] / py < min_width) continue;
        const int64_t w = (n[0] + px - 1) / px, h = (n[1] + py - 1) / py;
        const int64_t halo = inner_faces(px, periodic[0]) * h + inner_faces(py, periodic[1]) * w;
        if (halo < best) best = halo, dims[0] = px, dims[1] = py;
    }
}

int blocks_process_grid(const int n[2], const bool periodic[2], int min_width, int p,
                        const int asked[2], const char *const what[2], int dims[2]) {
    blocks_fewest_halo(n, periodic, min_width, p, dims);
    if (asked[0] > 0) dims[0] = asked[0], dims[1] = asked[1];
    if ((int64_t)dims[0] * dims[1] != p)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "--processes %dx%d makes %lld blocks for %d process%s; expected PXxPY "
                         "with PX times PY = %d",
                         dims[0], dims[1], (long long)dims[0] * dims[1], p, p == 1 ? "" : "es", p);
    for (int a = 1; a >= 0 && p > 1; a--)
        if (n[a] / dims[a] < min_width)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%d %s over %d processes leave fewer than %d on one; expected "
                             "at most %d processes",
                             n[a], what[a], dims[a], min_width, n[a] / min_width);
    return NSPD_OK;
}

int blocks_owner(int n, int q, int i) {
    int c = (int)((int64_t)i * q / n); /* a guess within one of the block */
    while (c > 0 && blocks_cut(n, q, c) > i) c--;
    while (c < q - 1 && blocks_cut(n, q, c + 1) <= i) c++;
    return c;
}
