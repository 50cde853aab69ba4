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
 * Results do not change: no loop's result depends on the thread count.
 * Such a clause, or --threads 1, costs a region no team at all under GCC
 * (parallel.c: nspd's own GOMP_parallel runs a region of one thread on the
 * calling thread); libgomp alone gives it a team of one, 1.1-1.4 us. */
#ifndef NSPD_CORE_PARALLEL_H
#define NSPD_CORE_PARALLEL_H

enum { PARALLEL_MIN_ITEMS = 4096 };

/* 1 where a parallel region of one thread runs without a team (parallel.c
 * is in charge of the runtime's regions), 0 where the runtime makes its
 * own team of one (another OpenMP runtime, or a link that left it out). */
int parallel_region_skips_team(void);

#endif
