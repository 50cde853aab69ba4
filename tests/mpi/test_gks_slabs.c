/* ctest-labels: mpi
 * The GKS flow on several processes (flow/gks/solver.h, issue 28): run by
 * mpiexec on 1 to 4 ranks (cmake/NspdTests.cmake), on every process grid
 * of that many blocks (px x py: 1 x P, the slabs of rows, to P x 1, the
 * columns). Every rank advances its block; rank 0 also runs the whole grid
 * on its own. After the steps, the blocks' interior states gathered and
 * placed must be the
 * one-process states bit for bit, and so must the totals (row sums added
 * in global row order), the time (each step's dt a max over ranks), the
 * step count and the first-order fallbacks (integer sums), and the six
 * primitive fields gathered for the writers (gks_solver_primitive_whole), on:
 *  - a shock tube along x with slip walls on y (uniform grid);
 *  - a viscous periodic box (Sutherland air): the y wrap between the
 *    first and last ranks;
 *  - a vortex crossing a stretched y axis between an isothermal no-slip
 *    floor and a moving adiabatic lid, with a subsonic inflow and outflow:
 *    the slabs' ghost widths from the whole stretched axis, the walls'
 *    mass and energy flux corrections on the whole grid's faces only;
 *  - a strong blast between slip walls and open faces, whose front makes
 *    limited slopes fall back to first order: the fallbacks of a block's
 *    edge columns and rows are counted once, as on one process.
 * A rank count that leaves fewer than two rows on a rank is refused by
 * every rank with NSPD_ERR_INPUT. */
#include "core/comm.h"
#include "core/status.h"
#include "flow/gks/solver.h"
#include "flow/vortex.h"

#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static NspdComm world;
static int failures = 0;

static void check(bool ok, const char *what, const char *name) {
    const int64_t bad = comm_max_i64(&world, ok ? 0 : 1);
    if (bad) {
        failures++;
        if (world.rank == 0) fprintf(stderr, "FAIL %s: %s\n", name, what);
    }
}

static void shock_tube(void *ctx, double x, double y, FlowPrim *out) {
    (void)ctx, (void)y;
    *out = x < 0.5 ? (FlowPrim){1.0, 0.0, 0.0, 1.0} : (FlowPrim){0.125, 0.0, 0.0, 0.1};
}

static void taylor_green(void *ctx, double x, double y, FlowPrim *out) {
    (void)ctx;
    const double u0 = 0.3 * sqrt(1.4);
    *out = (FlowPrim){1.0, u0 * sin(2.0 * M_PI * x) * cos(2.0 * M_PI * y),
                      -u0 * cos(2.0 * M_PI * x) * sin(2.0 * M_PI * y),
                      1.0 + 0.25 * u0 * u0 * (cos(4.0 * M_PI * x) + cos(4.0 * M_PI * y))};
}

/* A strong blast off the centre: its front makes
 * limited slopes fall back to first order, in block edge columns too. */
static void blast(void *ctx, double x, double y, FlowPrim *out) {
    (void)ctx;
    const double r2 = (x - 0.4) * (x - 0.4) + (y - 0.45) * (y - 0.45);
    /* rho and p ratios of 1e3 and 1e8 */
    *out = r2 < 0.04 ? (FlowPrim){1.0, 0.0, 0.0, 1e4} : (FlowPrim){1e-3, 0.0, 0.0, 1e-4};
}

static FlowVortex vortex;

static void config_blast(GksConfig *c) {
    gks_config_default(c);
    gks_config_uniform_grid(c, 0.0, 1.0, 28, 0.0, 1.0, 26);
    FlowBc wall = {.kind = BC_SLIP_WALL}, open = {.kind = BC_EXTRAPOLATION};
    gks_config_set_bc(c, FLOW_FACE_XLO, &wall);
    gks_config_set_bc(c, FLOW_FACE_XHI, &open);
    gks_config_set_bc(c, FLOW_FACE_YLO, &open);
    gks_config_set_bc(c, FLOW_FACE_YHI, &wall);
    c->init_fn = blast;
}

static void config_tube(GksConfig *c) {
    gks_config_default(c);
    gks_config_uniform_grid(c, 0.0, 1.0, 100, 0.0, 0.08, 8);
    FlowBc wall = {.kind = BC_SLIP_WALL}, open = {.kind = BC_EXTRAPOLATION};
    gks_config_set_bc(c, FLOW_FACE_XLO, &open);
    gks_config_set_bc(c, FLOW_FACE_XHI, &open);
    gks_config_set_bc(c, FLOW_FACE_YLO, &wall);
    gks_config_set_bc(c, FLOW_FACE_YHI, &wall);
    c->init_fn = shock_tube;
}

static void config_box(GksConfig *c) {
    gks_config_default(c);
    gks_config_uniform_grid(c, 0.0, 1.0, 24, 0.0, 1.0, 24);
    FlowBc per = {.kind = BC_PERIODIC};
    for (int face = 0; face < 4; face++) gks_config_set_bc(c, face, &per);
    c->viscosity = VISCOSITY_SUTHERLAND;
    c->mu_ref = 1e-3;
    c->T_ref = 0.0035;
    c->sutherland_S = 0.0013;
    c->init_fn = taylor_green;
}

static void config_channel(GksConfig *c) {
    gks_config_default(c);
    c->x0 = 0.0, c->y0 = 0.0;
    c->segment_count[0] = 1;
    c->segments[0][0] = (GridSegment){.length = 2.0, .cells = 40};
    c->segment_count[1] = 2;
    c->segments[1][0] = (GridSegment){.length = 0.5, .h_start = 0.01, .h_end = 0.05};
    c->segments[1][1] = (GridSegment){.length = 0.5, .h_start = 0.05, .h_end = 0.02};
    c->viscosity = VISCOSITY_CONSTANT;
    c->mu_ref = 2e-3;
    const FlowPrim free = {1.0, 0.5, 0.0, 1.0 / 1.4};
    FlowBc in = {.kind = BC_SUBSONIC_INFLOW, .state = free};
    FlowBc out = {.kind = BC_SUBSONIC_OUTFLOW, .pressure = 1.0 / 1.4};
    FlowBc floor = {.kind = BC_NOSLIP_ISOTHERMAL, .wall_temperature = 1.0 / 1.4 / 287.0};
    FlowBc lid = {.kind = BC_NOSLIP_ADIABATIC, .wall_velocity = 0.2};
    gks_config_set_bc(c, FLOW_FACE_XLO, &in);
    gks_config_set_bc(c, FLOW_FACE_XHI, &out);
    gks_config_set_bc(c, FLOW_FACE_YLO, &floor);
    gks_config_set_bc(c, FLOW_FACE_YHI, &lid);
    vortex = (FlowVortex){.x0 = 0.6,
                          .y0 = 0.45,
                          .strength = 2.0,
                          .gamma = 1.4,
                          .rho_inf = 1.0,
                          .u_inf = 0.5,
                          .p_inf = 1.0 / 1.4};
    c->init_fn = flow_isentropic_vortex;
    c->init_ctx = &vortex;
}

/* The interior of the four fields, rows in order, x fastest. */
static void interior(const GksSolver *s, double *out) {
    GksFields f = gks_solver_fields((GksSolver *)s);
    const Grid *g = gks_solver_grid(s);
    for (int v = 0; v < 4; v++)
        for (int j = 0; j < g->ny; j++)
            for (int i = 0; i < g->nx; i++)
                out[((int64_t)j * g->nx + i) * 4 + v] = f.w[v][grid_index(g, i, j)];
}

static void run(const char *name, void (*configure)(GksConfig *), int steps, int px) {
    GksConfig c;
    configure(&c);
    char label[128];
    snprintf(label, sizeof label, "%s, %d x %d blocks", name, px, world.size / px);
    name = label;
    GksSolver *whole = NULL, *slab = NULL;
    if (world.rank == 0 && gks_solver_create(&whole, &c) != NSPD_OK) {
        fprintf(stderr, "%s: %s\n", name, nspd_error_message());
        exit(1);
    }
    c.comm = &world;
    c.processes[0] = px;
    c.processes[1] = world.size / px;
    check(gks_solver_create(&slab, &c) == NSPD_OK, "create on blocks", name);
    check(gks_solver_advance(slab, 1e9, steps) == NSPD_OK, "advance on slabs", name);
    /* check() is collective: every rank calls it, rank 0 with the answer */
    check(!whole || gks_solver_advance(whole, 1e9, steps) == NSPD_OK, "advance whole", name);
    const Grid *g = gks_solver_grid(slab), *wg = gks_solver_whole_grid(slab);
    int first[2], count[2];
    gks_solver_block(slab, world.rank, first, count);
    check(count[0] == g->nx && count[1] == g->ny && g->ax[0].lo == wg->ax[0].face[first[0]] &&
              g->ax[1].lo == wg->ax[1].face[first[1]],
          "block extents", name);
    const int64_t cells = (int64_t)wg->nx * wg->ny;
    double *mine = malloc((size_t)g->nx * (size_t)g->ny * 4 * sizeof(double));
    double *blocks = malloc((size_t)cells * 4 * sizeof(double));
    double *all = malloc((size_t)cells * 4 * sizeof(double));
    double *ref = malloc((size_t)cells * 4 * sizeof(double));
    interior(slab, mine);
    comm_allgatherv(&world, mine, g->nx * g->ny * 4, blocks);
    /* the blocks, in rank order, placed in the whole grid */
    const double *at = blocks;
    for (int r = 0; r < world.size; r++) {
        gks_solver_block(slab, r, first, count);
        for (int j = 0; j < count[1]; j++, at += 4 * count[0])
            memcpy(all + 4 * ((int64_t)(first[1] + j) * wg->nx + first[0]), at,
                   4 * (size_t)count[0] * sizeof(double));
    }
    double t_slab[4], t_whole[4] = {0};
    gks_solver_totals(slab, t_slab);
    /* verdicts of rank 0 (the others hold no whole grid: true), then
     * every rank takes part in each collective check */
    bool same = true, totals = true, time = true, counted = true, fallbacks = true;
    if (whole) {
        interior(whole, ref);
        gks_solver_totals(whole, t_whole);
        for (int64_t k = 0; k < cells * 4 && same; k++)
            if (memcmp(&all[k], &ref[k], sizeof(double))) {
                fprintf(stderr, "%s: first difference at cell %lld field %lld: %.17g vs %.17g\n",
                        name, (long long)(k / 4), (long long)(k % 4), all[k], ref[k]);
                same = false;
            }
        totals = memcmp(t_slab, t_whole, sizeof t_slab) == 0;
        const double ts = gks_solver_time(slab), tw = gks_solver_time(whole);
        time = memcmp(&ts, &tw, sizeof ts) == 0;
        counted = gks_solver_step_count(slab) == gks_solver_step_count(whole);
        fallbacks = gks_solver_fallbacks_total(slab) == gks_solver_fallbacks_total(whole);
        printf("%s (%d ranks): %lld cells, %lld steps to t = %.6g, mass %.17g, fallbacks %lld\n",
               name, world.size, (long long)cells, (long long)gks_solver_step_count(whole),
               gks_solver_time(whole), t_whole[0], (long long)gks_solver_fallbacks_total(whole));
    }
    check(totals, "totals", name);
    check(time, "time", name);
    check(counted, "steps", name);
    check(fallbacks, "fallbacks", name);
    check(same, "interior states", name);
    /* the writers' gather: every primitive field of the whole grid */
    double *slab_field = malloc((size_t)g->nx * (size_t)g->ny * sizeof(double));
    double *whole_field = malloc((size_t)cells * sizeof(double));
    bool fields_same = true;
    for (int field = 0; field < FLOW_FIELD_COUNT; field++) {
        check(gks_solver_primitive_whole(slab, (FlowField)field, slab_field, whole_field) ==
                  NSPD_OK,
              "gather a field", name);
        if (whole) {
            gks_solver_primitive(whole, (FlowField)field, ref);
            fields_same = fields_same && !memcmp(whole_field, ref, (size_t)cells * sizeof(double));
        }
    }
    check(fields_same, "gathered primitive fields", name);
    free(slab_field), free(whole_field);
    free(mine), free(blocks), free(all), free(ref);
    gks_solver_destroy(&slab);
    gks_solver_destroy(&whole);
}

static void too_many_ranks(void) {
    GksConfig c;
    config_tube(&c);
    c.segments[1][0] = (GridSegment){.length = 0.08, .cells = 2 * world.size - 1};
    c.comm = &world;
    c.processes[0] = 1; /* slabs: the rows are too few */
    c.processes[1] = world.size;
    GksSolver *s = NULL;
    const int status = gks_solver_create(&s, &c);
    check(world.size == 1 ? status == NSPD_OK : status == NSPD_ERR_INPUT, "too few rows refused",
          "slabs");
    if (world.rank == 0 && world.size > 1) printf("refused: %s\n", nspd_error_message());
    gks_solver_destroy(&s);
}

int main(int argc, char **argv) {
    world = comm_init(&argc, &argv);
    for (int px = 1; px <= world.size; px++) {
        if (world.size % px) continue;
        run("shock tube", config_tube, 40, px);
        run("periodic box", config_box, 30, px);
        run("channel", config_channel, 30, px);
        run("blast", config_blast, 25, px);
    }
    too_many_ranks();
    if (world.rank == 0) printf("%s\n", failures ? "FAILED" : "all bitwise equal");
    comm_finalize();
    return failures ? 1 : 0;
}
