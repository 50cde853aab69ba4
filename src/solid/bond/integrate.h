/* Time integration of a PD body (paper 000 Eq. 30 and velocity Verlet). */
#ifndef NSPD_SOLID_BOND_INTEGRATE_H
#define NSPD_SOLID_BOND_INTEGRATE_H

#include "solid/bond/body.h"

/* Advances the body by dt with its configured integrator:
 *  euler_cromer (Eq. 30):  a = (f(u^n) + b) / rho,  v^{n+1} = v^n + a dt,
 *                          u^{n+1} = u^n + v^{n+1} dt   (one force per step);
 *  velocity_verlet:        v^{n+1/2} = v^n + a^n dt/2,  u^{n+1} = u^n + v^{n+1/2} dt,
 *                          v^{n+1} = v^{n+1/2} + a^{n+1} dt/2 (one force per step,
 *                          the first step computes a^0 too).
 * b = external[] + body force + region force densities. Boundary regions
 * then overwrite prescribed components: velocity v_d = V (and u_d advances
 * with it), displacement u_d = U, v_d = 0.
 * Returns NSPD_ERR_NUMERIC (with the first bad point and its position) if a
 * displacement or velocity is not finite. */
int pd_step(BondBody *body, double dt);
/* One step whose velocities a coupling prescribed (SolidOps.step_constrained):
 * u += dt v, the force at the new u, v += dt a (either integrator). */
int pd_step_constrained(BondBody *body, double dt);

/* The stable time step of Silling and Askari (2005):
 *     dt_i = sqrt(2 rho / sum_j k_ij),  dt = min_i dt_i
 * (k_ij as in body.h; broken bonds excluded). Multiply by a safety factor
 * (0.8 is customary) before use. */
double pd_stable_time_step(const BondBody *body);

/* The same from the configuration alone: the sum over the full family of
 * an interior point, without surface corrections (which can shorten the
 * step near a surface: an estimate for a case not built; 0 when the
 * configuration cannot give one). */
double pd_interior_stable_dt(const PdConfig *cfg);

#endif
