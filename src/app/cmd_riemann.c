/* nspd riemann: the exact solution of a 1D Riemann problem (Toro ch. 4) as
 * cell averages on a uniform grid, CSV on stdout - the reference of the
 * shock-tube cases. */
#include "app/commands.h"
#include "app/options.h"
#include "core/status.h"
#include "flow/riemann_exact.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool parse_state(const char *text, RiemannState *s) {
    double v[3];
    if (!option_parse_triple(text, v)) return false;
    *s = (RiemannState){.rho = v[0], .u = v[1], .p = v[2]};
    return true;
}

int cmd_riemann(int argc, char **argv) {
    RiemannState left = {1, 0, 1}, right = {0.125, 0, 0.1};
    double gamma = 1.4, time = 0.2, x0 = 0.5, length = 1.0;
    long cells = 400;
    if (argc % 2) {
        fprintf(stderr, "nspd riemann: every option takes a value; got none for '%s'\n",
                argv[argc - 1]);
        command_usage(stderr, command_help("riemann"), false);
        return EXIT_BAD_INPUT;
    }
    for (int i = 0; i + 1 < argc; i += 2) {
        const char *k = argv[i], *v = argv[i + 1];
        bool ok = true;
        if (strcmp(k, "--left") == 0)
            ok = parse_state(v, &left);
        else if (strcmp(k, "--right") == 0)
            ok = parse_state(v, &right);
        else if (strcmp(k, "--gamma") == 0)
            gamma = atof(v);
        else if (strcmp(k, "--time") == 0)
            time = atof(v);
        else if (strcmp(k, "--x0") == 0)
            x0 = atof(v);
        else if (strcmp(k, "--length") == 0)
            length = atof(v);
        else if (strcmp(k, "--cells") == 0)
            cells = atol(v);
        else {
            fprintf(stderr, "nspd riemann: unknown option '%s'\n", k);
            command_usage(stderr, command_help("riemann"), false);
            return EXIT_BAD_INPUT;
        }
        if (!ok) {
            fprintf(stderr, "nspd riemann: bad value '%s' for %s; expected RHO,U,P\n", v, k);
            return EXIT_BAD_INPUT;
        }
    }
    if (!(time > 0) || cells < 1 || !(length > 0)) {
        fprintf(stderr, "nspd riemann: time, length and cells must be positive\n");
        return EXIT_BAD_INPUT;
    }
    RiemannSolution sol;
    if (riemann_exact_solve(&left, &right, gamma, &sol) != NSPD_OK) {
        fprintf(stderr, "nspd riemann: %s\n", nspd_error_message());
        return EXIT_BAD_INPUT;
    }
    printf("# exact solution, p* = %.10g, u* = %.10g, t = %g\nx,rho,u,p\n", sol.p_star, sol.u_star,
           time);
    double h = length / (double)cells;
    for (long i = 0; i < cells; i++) {
        const double xi = (double)i; /* cells is bounded far below 2^53 */
        double cons[3];
        riemann_exact_average(&sol, x0, time, xi * h, (xi + 1) * h, 64, cons);
        double u = cons[1] / cons[0], p = (gamma - 1) * (cons[2] - 0.5 * cons[1] * u);
        printf("%.9g,%.9g,%.9g,%.9g\n", (xi + 0.5) * h, cons[0], u, p);
    }
    return 0;
}
