/* The Sedov-Taylor point blast (Sedov, "Similarity and Dimensional
 * Methods in Mechanics", 1959, ch. IV): energy E released at a point,
 * line or plane of a gas of density rho0 at rest and no pressure drives a
 * strong shock at r_s = xi0 (E t^2 / rho0)^(1 / (nu + 2)). xi0 comes from
 * the energy integral of the self-similar profiles behind the shock,
 * integrated here from the strong-shock jump conditions inwards. */
#ifndef NSPD_FLOW_SEDOV_H
#define NSPD_FLOW_SEDOV_H

/* xi0 for geometry nu (1 planar, E per area, the two sides of the plane;
 * 2 cylindrical, E per length; 3 spherical) and 1 < gamma < 3:
 * cylindrical 1.004022 and spherical 1.032777 at gamma 1.4. */
double sedov_front_constant(int nu, double gamma);

/* The shock radius at time t. */
double sedov_front_radius(int nu, double gamma, double energy, double rho0, double t);

#endif
