/* nspd radial: a blast's converged 1D reference (flow/radial.h) - a charge
 * of radius R0 in a planar, cylindrical or spherical gas at rest, solved on
 * a fine uniform grid; the profile at --time as CSV on stdout, or with
 * --probes the pressure history at those radii (one row per step). */
#include "app/commands.h"
#include "app/options.h"
#include "core/status.h"
#include "flow/radial.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_PROBES = 16 };
/* A gas state RHO,U,P with positive density and pressure. */
static bool parse_state(const char *text, RadialState *s) {
    double v[3];
    if (!option_parse_triple(text, v)) return false;
    *s = (RadialState){.rho = v[0], .u = v[1], .p = v[2]};
    return s->rho > 0 && s->p > 0;
}

static bool parse_probes(const char *text, double *r, int *count) {
    *count = 0;
    const char *p = text;
    while (*p && *count < MAX_PROBES) {
        char *end;
        r[*count] = strtod(p, &end);
        if (end == p || !(r[*count] > 0)) return false;
        (*count)++;
        if (*end == '\0') return true;
        if (*end != ',') return false;
        p = end + 1;
    }
    return false;
}

/* "nspd radial: WHAT 'ARG'" and the synopsis; exit status 2 */
static int usage_error(const char *what, const char *arg) {
    fprintf(stderr, "nspd radial: %s '%s'\n", what, arg);
    command_usage(stderr, command_help("radial"), false);
    return EXIT_BAD_INPUT;
}

int cmd_radial(int argc, char **argv) {
    RadialConfig cfg = {
        .nu = 2, .gamma = 1.4, .length = 1.5, .cells = 20000, .outer_wall = true, .cfl = 0.4};
    RadialState charge = {1, 0, 1}, ambient = {1, 0, 1e-4};
    double r0 = 0.25, time = 0.5, probes[MAX_PROBES];
    int probe_count = 0;
    if (argc % 2) return usage_error("every option takes a value; got none for", argv[argc - 1]);
    for (int i = 0; i < argc; i += 2) {
        const char *k = argv[i], *v = argv[i + 1];
        bool ok = true;
        if (strcmp(k, "--geometry") == 0) {
            cfg.nu = strcmp(v, "planar") == 0        ? 1
                     : strcmp(v, "cylindrical") == 0 ? 2
                     : strcmp(v, "spherical") == 0   ? 3
                                                     : 0;
            ok = cfg.nu != 0;
        } else if (strcmp(k, "--gamma") == 0)
            ok = option_parse_number(v, &cfg.gamma);
        else if (strcmp(k, "--charge") == 0)
            ok = parse_state(v, &charge);
        else if (strcmp(k, "--ambient") == 0)
            ok = parse_state(v, &ambient);
        else if (strcmp(k, "--radius") == 0)
            ok = option_parse_number(v, &r0) && r0 > 0;
        else if (strcmp(k, "--length") == 0)
            ok = option_parse_number(v, &cfg.length);
        else if (strcmp(k, "--cells") == 0) {
            char *end;
            cfg.cells = strtol(v, &end, 10);
            ok = *end == '\0';
        } else if (strcmp(k, "--time") == 0)
            ok = option_parse_number(v, &time) && time > 0;
        else if (strcmp(k, "--outer") == 0) {
            ok = strcmp(v, "wall") == 0 || strcmp(v, "open") == 0;
            cfg.outer_wall = strcmp(v, "wall") == 0;
        } else if (strcmp(k, "--cfl") == 0)
            ok = option_parse_number(v, &cfg.cfl);
        else if (strcmp(k, "--probes") == 0)
            ok = parse_probes(v, probes, &probe_count);
        else
            return usage_error("unknown option", k);
        if (!ok) {
            fprintf(stderr, "nspd radial: bad value '%s' for %s\n", v, k);
            return EXIT_BAD_INPUT;
        }
    }
    RadialSolver s;
    if (radial_create(&cfg, &ambient, &s) != NSPD_OK) {
        fprintf(stderr, "nspd radial: %s\n", nspd_error_message());
        return EXIT_BAD_INPUT;
    }
    radial_set_charge(&s, r0, &charge, &ambient);
    const double h = cfg.length / (double)cfg.cells;
    long probe_cell[MAX_PROBES];
    for (int k = 0; k < probe_count; k++) {
        probe_cell[k] = (long)(probes[k] / h);
        if (probe_cell[k] >= cfg.cells) {
            radial_free(&s);
            fprintf(stderr, "nspd radial: probe r = %g lies outside (0, %g)\n", probes[k],
                    cfg.length);
            return EXIT_BAD_INPUT;
        }
    }
    static const char *names[] = {"", "planar", "cylindrical", "spherical"};
    printf("# nspd radial: %s, gamma %g, %ld cells on (0, %g), charge r < %g\n", names[cfg.nu],
           cfg.gamma, cfg.cells, cfg.length, r0);
    int st = NSPD_OK;
    if (probe_count) {
        /* the history: a row per step, the probe cells' pressure */
        printf("t");
        for (int k = 0; k < probe_count; k++) printf(",p(r=%g)", probes[k]);
        printf("\n");
        while (st == NSPD_OK && s.time < time) {
            const long before = s.steps;
            st = radial_step(&s, time);
            if (st == NSPD_OK && s.steps > before) {
                printf("%.9g", s.time);
                for (int k = 0; k < probe_count; k++)
                    printf(",%.9g", radial_state(&s, probe_cell[k]).p);
                printf("\n");
            }
        }
    } else {
        st = radial_advance(&s, time);
        if (st == NSPD_OK) {
            printf("r,rho,u,p\n");
            for (long i = 0; i < cfg.cells; i++) {
                const RadialState w = radial_state(&s, i);
                printf("%.9g,%.9g,%.9g,%.9g\n", ((double)i + 0.5) * h, w.rho, w.u, w.p);
            }
        }
    }
    double mass, energy;
    radial_totals(&s, &mass, &energy);
    fprintf(stderr, "nspd radial: t = %g after %ld steps; mass %.15g, energy %.15g\n", s.time,
            s.steps, mass, energy);
    radial_free(&s);
    if (st != NSPD_OK) {
        fprintf(stderr, "nspd radial: %s\n", nspd_error_message());
        return EXIT_RUN_FAILED;
    }
    return 0;
}
