/* core/expr: the load expressions - every operator and function against C,
 * precedence and grouping, the variables and what a program uses, and
 * the refusals with the column they name. */
#include "test_support.h"

#include "core/expr.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

static const double VARS[EXPR_VARIABLES] = {0.25, 2.0, -3.0, 0.5}; /* t, x, y, z */

static double value_of(const char *text) {
    Expr e;
    ExprError err;
    if (!expr_compile(text, &e, &err))
        fail_msg("'%s' refused at column %d: %s", text, err.column, err.message);
    return expr_eval(&e, VARS);
}

/* exact where C's own expression gives the same operations in the same order */
static void test_arithmetic(void **state) {
    (void)state;
    assert_true(value_of("20*t") == 20 * 0.25);
    assert_true(value_of("1 + 2 * 3") == 7.0);
    assert_true(value_of("(1 + 2) * 3") == 9.0);
    assert_true(value_of("8 / 4 / 2") == 1.0);  /* left to right */
    assert_true(value_of("10 - 4 - 3") == 3.0); /* left to right */
    assert_true(value_of("2^3^2") == 512.0);    /* right to left */
    assert_true(value_of("-2^2") == -4.0);      /* ^ before unary minus */
    assert_true(value_of("2^-1") == 0.5);
    assert_true(value_of("--3") == 3.0);
    assert_true(value_of("+x") == 2.0);
    assert_true(value_of("1.5e-3 * 2") == 3e-3);
    assert_true(value_of(".5") == 0.5);
    assert_true(value_of("x*y - z/t") == 2.0 * -3.0 - 0.5 / 0.25);
    assert_true(value_of("  \t1\t+ 1 ") == 2.0);
    assert_true(value_of("pi") == M_PI);
}

static void test_functions(void **state) {
    (void)state;
    const double t = VARS[0];
    assert_true(value_of("sin(t)") == sin(t));
    assert_true(value_of("cos(t)") == cos(t));
    assert_true(value_of("tan(t)") == tan(t));
    assert_true(value_of("asin(t)") == asin(t));
    assert_true(value_of("acos(t)") == acos(t));
    assert_true(value_of("atan(t)") == atan(t));
    assert_true(value_of("sinh(t)") == sinh(t));
    assert_true(value_of("cosh(t)") == cosh(t));
    assert_true(value_of("tanh(t)") == tanh(t));
    assert_true(value_of("exp(-t/2e-5)") == exp(-t / 2e-5));
    assert_true(value_of("log(x)") == log(2.0));
    assert_true(value_of("log10(1000)") == 3.0);
    assert_true(value_of("sqrt(x)") == sqrt(2.0));
    assert_true(value_of("abs(y)") == 3.0);
    assert_true(value_of("floor(-t)") == -1.0);
    assert_true(value_of("ceil(t)") == 1.0);
    assert_true(value_of("atan2(y, x)") == atan2(-3.0, 2.0));
    assert_true(value_of("pow(x, 10)") == 1024.0);
    assert_true(value_of("min(x, y)") == -3.0);
    assert_true(value_of("max(x, y)") == 2.0);
    assert_true(value_of("step(0)") == 1.0 && value_of("step(-1e-300)") == 0.0);
    assert_true(value_of("min(max(t/1e-1, 0), 1) * 5") == 5.0); /* a clipped ramp */
    assert_true(isnan(value_of("sqrt(y)")));                    /* NaN propagates */
}

static void test_logic(void **state) {
    (void)state;
    assert_true(value_of("t < 1") == 1.0 && value_of("t > 1") == 0.0);
    assert_true(value_of("t <= 0.25") == 1.0 && value_of("t >= 0.26") == 0.0);
    assert_true(value_of("x == 2") == 1.0 && value_of("x != 2") == 0.0);
    assert_true(value_of("!0") == 1.0 && value_of("!x") == 0.0);
    assert_true(value_of("t > 0 && x > 0") == 1.0 && value_of("t > 0 && y > 0") == 0.0);
    assert_true(value_of("y > 0 || x > 0") == 1.0 && value_of("y > 0 || z > 1") == 0.0);
    assert_true(value_of("1 + 1 < 3") == 1.0); /* a sum before a comparison */
    assert_true(value_of("t < 1e-1 ? 5*t/1e-1 : 5") == 5.0);
    assert_true(value_of("t < 1 ? 5*t : 5") == 1.25);
    /* ?: groups to the right: a ? b : (c ? d : e) */
    assert_true(value_of("x < 0 ? 1 : y < 0 ? 2 : 3") == 2.0);
    assert_true(value_of("(t < 1 ? 2 : 3) * 10") == 20.0);
    assert_true(value_of("1e6*exp(-t/2e-5)*(x > 0)") == 1e6 * exp(-0.25 / 2e-5));
}

static void test_uses(void **state) {
    (void)state;
    Expr e;
    ExprError err;
    assert_true(expr_compile("20*t", &e, &err));
    assert_true(e.uses == 1u << EXPR_T && !expr_uses_position(&e));
    assert_true(expr_compile("3", &e, &err));
    assert_true(e.uses == 0 && !expr_uses_position(&e));
    assert_true(expr_compile("t*z", &e, &err));
    assert_true(e.uses == ((1u << EXPR_T) | (1u << EXPR_Z)) && expr_uses_position(&e));
    /* a program is a value: a copy evaluates the same */
    assert_true(expr_compile("sin(x) * t", &e, &err));
    Expr copy;
    memcpy(&copy, &e, sizeof e);
    assert_true(expr_eval(&copy, VARS) == sin(2.0) * 0.25);
}

/* compiling `text` fails at `column` with a message containing `what` */
static void refused(const char *text, int column, const char *what) {
    Expr e;
    ExprError err;
    if (expr_compile(text, &e, &err)) fail_msg("'%s' was accepted", text);
    if (err.column != column || !strstr(err.message, what))
        fail_msg("'%s': column %d '%s'; expected column %d with '%s'", text, err.column,
                 err.message, column, what);
}

static void test_refusals(void **state) {
    (void)state;
    refused("", 1, "ends too early");
    refused("20*", 4, "ends too early");
    refused("20*w", 4, "unknown name 'w'");
    refused("2*tt", 3, "unknown name 'tt'");
    refused("sine(t)", 1, "unknown function 'sine'");
    refused("sin(t, x)", 1, "sin takes 1 argument, got 2");
    refused("min(t)", 1, "min takes 2 arguments, got 1");
    refused("sin()", 1, "got 0");
    refused("(1 + 2", 7, "expected ')'");
    refused("1 + 2)", 6, "unexpected ')' after");
    refused("t = 1", 3, "unexpected '='");
    refused("t ? 1", 6, "expected ':'");
    refused("0x10", 1, "not a decimal number");
    refused("1e", 2, "unexpected 'e'");
    refused("2 $ 3", 3, "unexpected '$'");
    refused("sin(t x)", 7, "expected ',' or ')'");
    /* the limits, not a crash */
    char deep[200];
    memset(deep, '(', 60);
    strcpy(deep + 60, "1");
    memset(deep + 61, ')', 60);
    deep[121] = '\0';
    Expr e;
    ExprError err;
    assert_true(expr_compile(deep, &e, &err)); /* parentheses alone take no stack */
    char wide[600] = "";
    for (int k = 0; k < 40; k++) strcat(wide, "(1+");
    /* the 33rd pending value: just after the 33rd "(1" (column 99) */
    refused(wide, 99, "nests too deeply");
    char longest[700];
    memset(longest, '1', 600);
    longest[600] = '\0';
    refused(longest, EXPR_MAX_TEXT + 1, "too long");
    char many[EXPR_MAX_TEXT] = "t";
    for (int k = 0; k < 130; k++) strcat(many, "+t");
    /* the 129th operation: the "+" after the 65th t (column 130) */
    refused(many, 130, "too long; expected at most 128 operations");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arithmetic), cmocka_unit_test(test_functions),
        cmocka_unit_test(test_logic),      cmocka_unit_test(test_uses),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
