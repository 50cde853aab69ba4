// A number type that counts every +, -, *, / and sqrt done on it (a
// negation, fabs, fmax and comparisons are not counted): a kernel header
// included after `#define double Counted` runs its arithmetic through it,
// so its flops are counted, not estimated. Used by bench/flops/*.cpp.
#ifndef NSPD_BENCH_COUNTED_HPP
#define NSPD_BENCH_COUNTED_HPP

#include <cmath>
#include <cstring>

static long flops = 0; // the count since it was last set

struct Counted {
    double v;
    Counted() : v(0) {}
    Counted(double x) : v(x) {}
    explicit operator double() const { return v; }
};
using D = Counted;

#define ARITHMETIC(o)                                                                              \
    inline D operator o(D a, D b) { return flops++, D(a.v o b.v); }                                \
    inline D operator o(D a, double b) { return flops++, D(a.v o b); }                             \
    inline D operator o(double a, D b) { return flops++, D(a o b.v); }                             \
    inline D operator o(D a, int b) { return flops++, D(a.v o b); }                                \
    inline D operator o(int a, D b) { return flops++, D(a o b.v); }
ARITHMETIC(+)
ARITHMETIC(-)
ARITHMETIC(*)
ARITHMETIC(/)
#define COMPARE(o)                                                                                 \
    inline bool operator o(D a, D b) { return a.v o b.v; }                                         \
    inline bool operator o(D a, double b) { return a.v o b; }                                      \
    inline bool operator o(double a, D b) { return a o b.v; }                                      \
    inline bool operator o(D a, int b) { return a.v o b; }
COMPARE(<)
COMPARE(>)
COMPARE(<=)
COMPARE(>=)
COMPARE(==)
COMPARE(!=)
inline D operator-(D a) { return D(-a.v); }
inline D &operator+=(D &a, D b) { return flops++, a.v += b.v, a; }
inline D &operator-=(D &a, D b) { return flops++, a.v -= b.v, a; }
inline D &operator*=(D &a, D b) { return flops++, a.v *= b.v, a; }
inline D sqrt(D a) { return flops++, D(std::sqrt(a.v)); }
inline D fabs(D a) { return D(std::fabs(a.v)); }
inline D fmax(D a, D b) { return D(std::fmax(a.v, b.v)); }


#endif
