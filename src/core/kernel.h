/* Macros for kernels: point-, cell- or face-wise bodies that compile unchanged
 * as C (inlined into the OpenMP row loops) and as CUDA device code (called by
 * one thread per point, cell or face).
 *
 * A kernel header (`*_kernel.h`) holds only NSPD_KERNEL functions on plain
 * numbers and plain arrays: no allocation, no I/O, no globals, no error
 * returns, and nothing but what a CUDA device function may call (its own
 * helpers, <math.h>, memcpy). tests/unit/core/cuda_kernels.cu and the
 * compile-only ctest unit.core.cuda_kernels hold them to that when nvcc is
 * found. */
#ifndef NSPD_CORE_KERNEL_H
#define NSPD_CORE_KERNEL_H

#include <math.h>

/* NSPD_PRAGMA(x): a #pragma from inside a macro (C99/C++11 _Pragma). */
#define NSPD_PRAGMA(x) _Pragma(#x)

#ifdef __CUDACC__
/* __host__ __device__: nvcc refuses a call to a host-only function from a
 * __global__ function, so every kernel and every helper it calls must be
 * compiled for both sides. nvcc inlines device functions on its own. */
#define NSPD_KERNEL static inline __host__ __device__
/* C++ has no `restrict`; nvcc spells it __restrict__ (same meaning: the
 * pointer is the only way to the memory it points at in this scope). */
#define NSPD_RESTRICT __restrict__
/* nvcc's front end warns (#1675) on `#pragma GCC unroll` in both of its
 * passes, and GCC, compiling the host pass, warns on nvcc's `#pragma unroll`.
 * So: nvcc's spelling in the device pass, nothing in the host pass (the CPU
 * code that counts is the C build, where the GCC spelling applies). */
#ifdef __CUDA_ARCH__
#define NSPD_UNROLL(n) NSPD_PRAGMA(unroll n)
#else
#define NSPD_UNROLL(n)
#endif
#else
/* always_inline: the kernels are called inside row loops that must
 * vectorise across cells, faces or bonds, and a call left out of line keeps
 * such a loop scalar; the attribute takes the decision away from the
 * compiler's size heuristics (the GKS flux kernel is large). */
#define NSPD_KERNEL    static inline __attribute__((always_inline))
#define NSPD_RESTRICT  restrict
/* Full unrolling of short fixed-count loops inside a kernel, so that the
 * loop vectorised around the kernel sees straight-line code. */
#define NSPD_UNROLL(n) NSPD_PRAGMA(GCC unroll n)
#endif

/* Quiet comparisons for kernels (the truth values of >, < and <=, false
 * with a NaN): in C, <math.h>'s isgreater, isless and islessequal, which
 * raise no floating-point exception, so GCC may evaluate them outside
 * their branch and if-convert a loop around them (an ordered comparison
 * may trap, and stays under its branch); on the device plain comparisons
 * (nvcc refuses the host's isgreater there, and nothing traps). */
#ifdef __CUDACC__
#define NSPD_GT(a, b) ((a) > (b))
#define NSPD_LT(a, b) ((a) < (b))
#define NSPD_LE(a, b) ((a) <= (b))
#else
#define NSPD_GT(a, b) isgreater(a, b)
#define NSPD_LT(a, b) isless(a, b)
#define NSPD_LE(a, b) islessequal(a, b)
#endif

/* NSPD_IVDEP, before a row loop: GCC may vectorise it without proving that
 * its stores do not alias its loads (the `restrict` row pointers say so).
 * Only GCC knows `#pragma GCC ivdep`; clang (and clang-tidy) would warn on
 * it as unknown, so other compilers get nothing, which is what they made of
 * the pragma anyway. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#define NSPD_IVDEP NSPD_PRAGMA(GCC ivdep)
#else
#define NSPD_IVDEP
#endif

/* NSPD_FMA(a, b, c): a b + c rounded once, where the target fuses it in
 * hardware (x86-64 with FMA, which -march=native enables on every machine
 * nspd has run on; CUDA), and a b + c rounded twice elsewhere (a software
 * fma() costs tens of cycles). The build is ISO C, so the compiler never
 * contracts on its own (-ffp-contract=off): a kernel that wants fused
 * products writes them, and its bits do not depend on where the compiler
 * would have fused them (GCC fused the GKS row loops of x and y faces
 * differently, and the vector body unlike the scalar one). Defining
 * NSPD_NO_FMA before this header gives the unfused arithmetic: the
 * reference a fused kernel is tested against. */
#if defined(__CUDACC__) || (defined(FP_FAST_FMA) && !defined(NSPD_NO_FMA))
#define NSPD_FMA(a, b, c) fma(a, b, c)
#else
#define NSPD_FMA(a, b, c) ((a) * (b) + (c))
#endif

#endif
