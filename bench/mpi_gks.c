/* The GKS step on several processes (issue 28): the viscous periodic box
 * of `nspd bench gks` (gks_bench) with its rows split into one slab per
 * rank. Prints the cell updates per second of the whole grid, the time of
 * a step and the share of it spent in the ghost-row exchanges and the
 * reductions (the largest over the ranks).
 *     mpiexec -n RANKS build/bench_mpi_gks CELLS STEPS    (OMP_NUM_THREADS threads a rank) */
#include "core/comm.h"
#include "core/status.h"
#include "flow/gks/solver.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    NspdComm world = comm_init(&argc, &argv);
    if (argc != 3) {
        if (world.rank == 0) fprintf(stderr, "usage: bench_mpi_gks CELLS STEPS\n");
        comm_finalize();
        return 2;
    }
    GksBenchResult r;
    const int status = gks_bench(atoi(argv[1]), omp_get_max_threads(), atoi(argv[2]), &world, &r);
    if (status != NSPD_OK) {
        fprintf(stderr, "rank %d: %s\n", world.rank, nspd_error_message());
    } else if (world.rank == 0) {
        printf("cells %lld ranks %d threads %d steps %d: %.4g cell updates/s, %.3f ms/step, "
               "exchange + reductions %.3f ms/step (%.1f %%)\n",
               (long long)r.cells, world.size, r.threads, r.steps, r.cell_updates_per_s,
               1e3 * r.seconds / r.steps, 1e3 * r.comm_seconds / r.steps,
               100.0 * r.comm_seconds / r.seconds);
    }
    comm_finalize();
    return status == NSPD_OK ? 0 : 1;
}
