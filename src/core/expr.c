#include "core/expr.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum {
    OP_CONST,
    OP_VAR,
    OP_NEG,
    OP_NOT,
    OP_ADD,
    OP_SUB,
    OP_MUL,
    OP_DIV,
    OP_POW,
    OP_LT,
    OP_LE,
    OP_GT,
    OP_GE,
    OP_EQ,
    OP_NE,
    OP_AND,
    OP_OR,
    OP_SELECT, /* c ? a : b, from the stack's a, b, c */
    /* one argument */
    OP_SIN,
    OP_COS,
    OP_TAN,
    OP_ASIN,
    OP_ACOS,
    OP_ATAN,
    OP_SINH,
    OP_COSH,
    OP_TANH,
    OP_EXP,
    OP_LOG,
    OP_LOG10,
    OP_SQRT,
    OP_ABS,
    OP_FLOOR,
    OP_CEIL,
    OP_STEP,
    /* two arguments */
    OP_ATAN2,
    OP_POWF,
    OP_MIN,
    OP_MAX
};

typedef struct {
    const char *name;
    int op, arguments;
} Function;

static const Function FUNCTIONS[] = {
    {"sin", OP_SIN, 1},   {"cos", OP_COS, 1},     {"tan", OP_TAN, 1},     {"asin", OP_ASIN, 1},
    {"acos", OP_ACOS, 1}, {"atan", OP_ATAN, 1},   {"sinh", OP_SINH, 1},   {"cosh", OP_COSH, 1},
    {"tanh", OP_TANH, 1}, {"exp", OP_EXP, 1},     {"log", OP_LOG, 1},     {"log10", OP_LOG10, 1},
    {"sqrt", OP_SQRT, 1}, {"abs", OP_ABS, 1},     {"floor", OP_FLOOR, 1}, {"ceil", OP_CEIL, 1},
    {"step", OP_STEP, 1}, {"atan2", OP_ATAN2, 2}, {"pow", OP_POWF, 2},    {"min", OP_MIN, 2},
    {"max", OP_MAX, 2}};

static const char *const VARIABLES[EXPR_VARIABLES] = {"t", "x", "y", "z"};

/* The compiler's state: the text, the position, the program being
 * emitted and the depth its stack will reach. */
typedef struct {
    const char *text, *at;
    Expr *out;
    int depth, max_depth;
    ExprError *err;
    bool failed;
} Parser;

static bool fail(Parser *p, const char *where, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static bool fail(Parser *p, const char *where, const char *fmt, ...) {
    if (p->failed) return false; /* the first error is the one reported */
    p->failed = true;
    p->err->column = (int)(where - p->text) + 1;
    va_list args;
    va_start(args, fmt);
    vsnprintf(p->err->message, sizeof p->err->message, fmt, args);
    va_end(args);
    return false;
}

static void skip_space(Parser *p) {
    while (*p->at == ' ' || *p->at == '\t') p->at++;
}

/* Appends an instruction that changes the stack's depth by `change`. */
static bool emit(Parser *p, int op, double value, int change) {
    if (p->out->count >= EXPR_MAX_OPS)
        return fail(p, p->at, "the expression is too long; expected at most %d operations",
                    EXPR_MAX_OPS);
    p->out->code[p->out->count] = (uint8_t)op;
    p->out->value[p->out->count] = value;
    p->out->count++;
    p->depth += change;
    if (p->depth > EXPR_MAX_STACK)
        return fail(p, p->at, "the expression nests too deeply; expected at most %d pending values",
                    EXPR_MAX_STACK);
    if (p->depth > p->max_depth) p->max_depth = p->depth;
    return true;
}

/* Consumes `token` if the text continues with it. */
static bool accept(Parser *p, const char *token) {
    skip_space(p);
    const size_t n = strlen(token);
    if (strncmp(p->at, token, n) != 0) return false;
    /* '<' must not take the '<' of '<=', nor '!' the one of '!=' */
    if (n == 1 && (token[0] == '<' || token[0] == '>' || token[0] == '!' || token[0] == '=') &&
        p->at[1] == '=')
        return false;
    p->at += n;
    return true;
}

static bool parse_expr(Parser *p);

static bool parse_call(Parser *p, const Function *f, const char *name_at) {
    int given = 0;
    if (!accept(p, ")")) {
        do {
            if (!parse_expr(p)) return false;
            given++;
        } while (accept(p, ","));
        if (!accept(p, ")"))
            return fail(p, p->at, "expected ',' or ')' in the call of %s", f->name);
    }
    if (given != f->arguments)
        return fail(p, name_at, "%s takes %d argument%s, got %d", f->name, f->arguments,
                    f->arguments == 1 ? "" : "s", given);
    return emit(p, f->op, 0.0, 1 - f->arguments);
}

static bool parse_name(Parser *p) {
    const char *start = p->at;
    while (isalnum((unsigned char)*p->at) || *p->at == '_') p->at++;
    const size_t n = (size_t)(p->at - start);
    if (accept(p, "(")) {
        for (size_t k = 0; k < sizeof FUNCTIONS / sizeof FUNCTIONS[0]; k++)
            if (strlen(FUNCTIONS[k].name) == n && strncmp(FUNCTIONS[k].name, start, n) == 0)
                return parse_call(p, &FUNCTIONS[k], start);
        return fail(p, start,
                    "unknown function '%.*s'; expected one of sin cos tan asin acos atan sinh "
                    "cosh tanh exp log log10 sqrt abs floor ceil step atan2 pow min max",
                    (int)n, start);
    }
    for (int v = 0; v < EXPR_VARIABLES; v++)
        if (n == 1 && start[0] == VARIABLES[v][0]) {
            p->out->uses |= 1u << v;
            return emit(p, OP_VAR, (double)v, 1);
        }
    if (n == 2 && strncmp(start, "pi", 2) == 0) return emit(p, OP_CONST, M_PI, 1);
    return fail(p, start, "unknown name '%.*s'; expected t, x, y, z, pi or a function call", (int)n,
                start);
}

static bool parse_primary(Parser *p) {
    skip_space(p);
    const char c = *p->at;
    if (isdigit((unsigned char)c) || (c == '.' && isdigit((unsigned char)p->at[1]))) {
        char *end;
        const double v = strtod(p->at, &end);
        /* strtod also reads hexadecimal (0x1p3): only decimals are numbers here */
        for (const char *q = p->at; q < end; q++)
            if (!strchr("0123456789.eE+-", *q))
                return fail(p, p->at, "'%.*s' is not a decimal number", (int)(end - p->at), p->at);
        p->at = end;
        return emit(p, OP_CONST, v, 1);
    }
    if (isalpha((unsigned char)c) || c == '_') return parse_name(p);
    if (accept(p, "(")) {
        if (!parse_expr(p)) return false;
        if (!accept(p, ")")) return fail(p, p->at, "expected ')'");
        return true;
    }
    if (c == '\0') return fail(p, p->at, "the expression ends too early; expected a value");
    return fail(p, p->at, "unexpected '%c'; expected a number, a name or '('", c);
}

static bool parse_unary(Parser *p);

static bool parse_power(Parser *p) {
    if (!parse_primary(p)) return false;
    if (accept(p, "^")) {
        if (!parse_unary(p)) return false;
        return emit(p, OP_POW, 0.0, -1);
    }
    return true;
}

static bool parse_unary(Parser *p) {
    if (accept(p, "-")) return parse_unary(p) && emit(p, OP_NEG, 0.0, 0);
    if (accept(p, "+")) return parse_unary(p);
    if (accept(p, "!")) return parse_unary(p) && emit(p, OP_NOT, 0.0, 0);
    return parse_power(p);
}

/* operand (token operand)*, left to right: the binary levels */
static bool parse_left(Parser *p, bool (*operand)(Parser *), const char *const *tokens,
                       const int *ops, int count) {
    if (!operand(p)) return false;
    for (;;) {
        int op = -1;
        for (int k = 0; k < count && op < 0; k++)
            if (accept(p, tokens[k])) op = ops[k];
        if (op < 0) return true;
        if (!operand(p) || !emit(p, op, 0.0, -1)) return false;
    }
}

static bool parse_product(Parser *p) {
    static const char *const T[] = {"*", "/"};
    static const int OPS[] = {OP_MUL, OP_DIV};
    return parse_left(p, parse_unary, T, OPS, 2);
}

static bool parse_sum(Parser *p) {
    static const char *const T[] = {"+", "-"};
    static const int OPS[] = {OP_ADD, OP_SUB};
    return parse_left(p, parse_product, T, OPS, 2);
}

static bool parse_comparison(Parser *p) {
    if (!parse_sum(p)) return false;
    static const struct {
        const char *token;
        int op;
    } CMP[] = {{"<=", OP_LE}, {">=", OP_GE}, {"==", OP_EQ},
               {"!=", OP_NE}, {"<", OP_LT},  {">", OP_GT}};
    for (size_t k = 0; k < sizeof CMP / sizeof CMP[0]; k++)
        if (accept(p, CMP[k].token)) return parse_sum(p) && emit(p, CMP[k].op, 0.0, -1);
    return true;
}

static bool parse_and(Parser *p) {
    static const char *const T[] = {"&&"};
    static const int OPS[] = {OP_AND};
    return parse_left(p, parse_comparison, T, OPS, 1);
}

static bool parse_or(Parser *p) {
    static const char *const T[] = {"||"};
    static const int OPS[] = {OP_OR};
    return parse_left(p, parse_and, T, OPS, 1);
}

/* c ? a : b leaves c, a and b on the stack, b on top; OP_SELECT replaces
 * the three by a or b. */
static bool parse_expr(Parser *p) {
    if (!parse_or(p)) return false;
    if (!accept(p, "?")) return true;
    if (!parse_expr(p)) return false;
    if (!accept(p, ":")) return fail(p, p->at, "expected ':' of the '?'");
    if (!parse_expr(p)) return false;
    return emit(p, OP_SELECT, 0.0, -2);
}

bool expr_compile(const char *text, Expr *out, ExprError *err) {
    memset(out, 0, sizeof *out);
    *err = (ExprError){0};
    Parser p = {.text = text, .at = text, .out = out, .err = err};
    if (strlen(text) > EXPR_MAX_TEXT)
        return fail(&p, text + EXPR_MAX_TEXT,
                    "the expression is too long; expected at most %d "
                    "characters",
                    EXPR_MAX_TEXT);
    if (!parse_expr(&p)) return false;
    skip_space(&p);
    if (*p.at != '\0') return fail(&p, p.at, "unexpected '%c' after the expression", *p.at);
    return true;
}

static double truth(bool b) {
    return b ? 1.0 : 0.0;
}

double expr_eval(const Expr *e, const double vars[EXPR_VARIABLES]) {
    double s[EXPR_MAX_STACK + 1];
    int n = 0; /* values on the stack; s[n - 1] is the top */
    for (int k = 0; k < e->count; k++) {
        const double a = n >= 2 ? s[n - 2] : 0.0, b = n >= 1 ? s[n - 1] : 0.0;
        switch (e->code[k]) {
        case OP_CONST:
            s[n++] = e->value[k];
            break;
        case OP_VAR:
            s[n++] = vars[(int)e->value[k]];
            break;
        case OP_NEG:
            s[n - 1] = -b;
            break;
        case OP_NOT:
            s[n - 1] = truth(b == 0.0);
            break;
        case OP_ADD:
            s[--n - 1] = a + b;
            break;
        case OP_SUB:
            s[--n - 1] = a - b;
            break;
        case OP_MUL:
            s[--n - 1] = a * b;
            break;
        case OP_DIV:
            s[--n - 1] = a / b;
            break;
        case OP_POW:
        case OP_POWF:
            s[--n - 1] = pow(a, b);
            break;
        case OP_LT:
            s[--n - 1] = truth(a < b);
            break;
        case OP_LE:
            s[--n - 1] = truth(a <= b);
            break;
        case OP_GT:
            s[--n - 1] = truth(a > b);
            break;
        case OP_GE:
            s[--n - 1] = truth(a >= b);
            break;
        case OP_EQ:
            s[--n - 1] = truth(a == b);
            break;
        case OP_NE:
            s[--n - 1] = truth(a != b);
            break;
        case OP_AND:
            s[--n - 1] = truth(a != 0.0 && b != 0.0);
            break;
        case OP_OR:
            s[--n - 1] = truth(a != 0.0 || b != 0.0);
            break;
        case OP_SELECT: /* c, then-value, else-value on the stack, else on top */
            n -= 2;
            s[n - 1] = s[n - 1] != 0.0 ? s[n] : s[n + 1];
            break;
        case OP_SIN:
            s[n - 1] = sin(b);
            break;
        case OP_COS:
            s[n - 1] = cos(b);
            break;
        case OP_TAN:
            s[n - 1] = tan(b);
            break;
        case OP_ASIN:
            s[n - 1] = asin(b);
            break;
        case OP_ACOS:
            s[n - 1] = acos(b);
            break;
        case OP_ATAN:
            s[n - 1] = atan(b);
            break;
        case OP_SINH:
            s[n - 1] = sinh(b);
            break;
        case OP_COSH:
            s[n - 1] = cosh(b);
            break;
        case OP_TANH:
            s[n - 1] = tanh(b);
            break;
        case OP_EXP:
            s[n - 1] = exp(b);
            break;
        case OP_LOG:
            s[n - 1] = log(b);
            break;
        case OP_LOG10:
            s[n - 1] = log10(b);
            break;
        case OP_SQRT:
            s[n - 1] = sqrt(b);
            break;
        case OP_ABS:
            s[n - 1] = fabs(b);
            break;
        case OP_FLOOR:
            s[n - 1] = floor(b);
            break;
        case OP_CEIL:
            s[n - 1] = ceil(b);
            break;
        case OP_STEP:
            s[n - 1] = truth(b >= 0.0);
            break;
        case OP_ATAN2:
            s[--n - 1] = atan2(a, b);
            break;
        case OP_MIN:
            s[--n - 1] = fmin(a, b);
            break;
        case OP_MAX:
            s[--n - 1] = fmax(a, b);
            break;
        default:
            return (double)NAN; /* not a program expr_compile made */
        }
    }
    return n == 1 ? s[0] : (double)NAN;
}
