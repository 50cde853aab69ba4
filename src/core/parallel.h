/* When a loop is worth a thread team.
 *
 * Forking and joining an OpenMP team costs microseconds, and idle threads
 * spin while they wait: a loop over a few hundred points runs faster on the
 * calling thread, and on an oversubscribed machine (tests run side by side)
 * far faster. Every parallel loop over points or cells carries
 *     #pragma omp parallel for ... if (n >= PARALLEL_MIN_ITEMS)
 * with n the items of work: a loop over points that walks each point's
 * bonds counts the bonds (the correspondence solid's force and damage
 * passes: a body of 3,900 points has 43,000 bonds, worth two threads).
 * Results do not change: no loop's result depends on the thread count. */
#ifndef NSPD_CORE_PARALLEL_H
#define NSPD_CORE_PARALLEL_H

enum { PARALLEL_MIN_ITEMS = 4096 };

#endif
