/* The GKS flux kernel with every NSPD_FMA unfused (a b + c, rounded
 * twice): the reference test_flux_fma.c holds the fused kernel to. */
#define NSPD_NO_FMA
#include "flow/gks/flux_kernel.h"

void flux_unfused(const double wl[4], const double nl[4], const double tl[4], const double wr[4],
                  const double nr[4], const double tr[4], const double n0[4], const double t0[4],
                  double dt, const GksParams *par, double f[4]);

void flux_unfused(const double wl[4], const double nl[4], const double tl[4], const double wr[4],
                  const double nr[4], const double tr[4], const double n0[4], const double t0[4],
                  double dt, const GksParams *par, double f[4]) {
    gks_flux_kernel(wl, nl, tl, wr, nr, tr, n0, t0, dt, par, par->law, f);
}
