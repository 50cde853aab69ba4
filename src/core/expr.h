/* Loads that vary: a small, safe arithmetic expression of t, x, y, z
 * ("20*t", "1e6*exp(-t/2e-5)*(x > 0)", "t < 1e-4 ? 5*t/1e-4 : 5"),
 * compiled once into a flat postfix program and evaluated by a fixed
 * stack machine. Nothing is executed but arithmetic: no names outside the
 * table below, no calls into the host, no allocation, no I/O, so a
 * program is a plain value (copyable to a device) and evaluating it is
 * thread-safe.
 *
 * Grammar (precedence low to high; ^ and ?: group to the right, the rest
 * to the left):
 *     expr    := or ('?' expr ':' expr)?
 *     or      := and ('||' and)*
 *     and     := cmp ('&&' cmp)*
 *     cmp     := sum (('<' | '<=' | '>' | '>=' | '==' | '!=') sum)?
 *     sum     := product (('+' | '-') product)*
 *     product := unary (('*' | '/') unary)*
 *     unary   := ('-' | '+' | '!') unary | power
 *     power   := primary ('^' unary)?
 *     primary := NUMBER | NAME | NAME '(' expr (',' expr)* ')' | '(' expr ')'
 * so -2^2 is -4 and 2^-1 is 0.5. Comparisons and logic give 1 or 0; a
 * value is true where it is not 0. Both branches of ?: are evaluated (no
 * side effects exist), which keeps the program branch-free.
 * Variables: t (s), x, y, z (m, a point's reference position); constant pi.
 * Functions: sin cos tan asin acos atan sinh cosh tanh exp log log10 sqrt
 * abs floor ceil (one argument), atan2 pow min max (two), and step(s),
 * the Heaviside step (1 where s >= 0, else 0). */
#ifndef NSPD_CORE_EXPR_H
#define NSPD_CORE_EXPR_H

#include <stdbool.h>
#include <stdint.h>

enum {
    EXPR_MAX_OPS = 128,  /* instructions of one program */
    EXPR_MAX_STACK = 32, /* values on the machine's stack at once */
    EXPR_MAX_TEXT = 512  /* characters of one expression */
};

/* The variables in the order expr_eval takes them. */
enum { EXPR_T, EXPR_X, EXPR_Y, EXPR_Z, EXPR_VARIABLES };

typedef struct {
    uint8_t code[EXPR_MAX_OPS]; /* the instructions, postfix */
    double value[EXPR_MAX_OPS]; /* a constant's value; a variable's index */
    int count;                  /* instructions */
    unsigned uses;              /* bit v: variable v appears (1 << EXPR_T, ...) */
} Expr;

/* Where compiling failed: the 1-based column of `text` and what was
 * expected there. */
typedef struct {
    int column;
    char message[160];
} ExprError;

/* Compiles `text` into *out. False, with *err filled, for text that is not
 * an expression of the grammar above, names an unknown variable or
 * function, calls one with the wrong number of arguments, or needs more
 * than EXPR_MAX_OPS instructions or EXPR_MAX_STACK values. */
bool expr_compile(const char *text, Expr *out, ExprError *err);

/* The program's value at vars[EXPR_T .. EXPR_Z] (NaN and infinities
 * propagate as IEEE arithmetic makes them). */
double expr_eval(const Expr *e, const double vars[EXPR_VARIABLES]);

/* Whether the value depends on x, y or z (else it is one value per time). */
static inline bool expr_uses_position(const Expr *e) {
    return (e->uses & ~(1u << EXPR_T)) != 0;
}

#endif
