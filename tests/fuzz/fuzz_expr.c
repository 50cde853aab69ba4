/* fuzz_expr: the load expressions of the case file (core/expr.h). The
 * input, cut at its first NUL and at twice EXPR_MAX_TEXT bytes, is
 * compiled; the contract, asserted on every input:
 *   refused: the column lies in [1, length + 1] and the message is not
 *            empty;
 *   accepted: the program is within EXPR_MAX_OPS, compiling the text again
 *            gives the same program, and evaluating it at a few points
 *            returns (the stack machine stays inside its stack: ASan) and
 *            gives the same bits twice.
 * Anything else aborts: a finding. */
#include "fuzz_target.h"

#include "core/expr.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char text[2 * EXPR_MAX_TEXT + 1];
    size_t n = size < 2 * EXPR_MAX_TEXT ? size : 2 * EXPR_MAX_TEXT;
    memcpy(text, data, n);
    text[n] = '\0';
    n = strlen(text);
    Expr e;
    ExprError err;
    if (!expr_compile(text, &e, &err)) {
        if (err.column < 1 || (size_t)err.column > n + 1 || err.message[0] == '\0') {
            fprintf(stderr, "fuzz_expr: refusal at column %d of %zu: '%s'\n", err.column, n,
                    err.message);
            abort();
        }
        return 0;
    }
    Expr again;
    if (e.count < 1 || e.count > EXPR_MAX_OPS || !expr_compile(text, &again, &err) ||
        memcmp(&e, &again, sizeof e) != 0) {
        fprintf(stderr, "fuzz_expr: an accepted program of %d operations is not reproducible\n",
                e.count);
        abort();
    }
    static const double POINTS[3][EXPR_VARIABLES] = {
        {0.0, 0.0, 0.0, 0.0}, {1e-4, 0.5, -0.25, 2.0}, {-1e300, 1e-310, 3.0, -0.0}};
    for (int k = 0; k < 3; k++) {
        const double a = expr_eval(&e, POINTS[k]), b = expr_eval(&e, POINTS[k]);
        if (memcmp(&a, &b, sizeof a) != 0) {
            fprintf(stderr, "fuzz_expr: two evaluations differ\n");
            abort();
        }
    }
    return 0;
}
