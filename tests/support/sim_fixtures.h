/* Simulations built from the case files under cases/, for verify tests. */
#ifndef NSPD_TEST_SIM_FIXTURES_H
#define NSPD_TEST_SIM_FIXTURES_H

#include "couple/ghost/model.h"
#include "flow/gks/model.h"
#include "sim/sim.h"
#include "solid/bond/model.h"

/* Reads cases/<name> with the given --set overrides and builds the
 * simulation; fails the test on any error. */
void fixture_sim(const char *case_file, const char *const *overrides, int count, Sim *sim);

/* Writes a case given as YAML text to a scratch file named after `tag`;
 * returns its path (static storage, valid until the next call). */
const char *fixture_case_file(const char *tag, const char *yaml);

/* Builds a simulation from a case written in the test (YAML text); fails the
 * test on any error. */
void fixture_sim_text(const char *yaml, Sim *sim);

/* The concrete models of a simulation, for tests that look inside them
 * (fail the test if the case has no such model; the ghost-cell coupling's
 * parts through couple/ghost/model.h's accessors). */
BondBody *fixture_body(Sim *sim);
GksSolver *fixture_flow(Sim *sim);

/* The flow's state (density, u, v, pressure, temperature) in the cell
 * that holds (x, y); fails the test for a point off the grid. */
void fixture_flow_state_at(Sim *sim, double x, double y, double out[5]);

/* The value of summary key `name` of the coupling (fails if absent). */
double fixture_coupling_summary(Sim *sim, const char *name);

/* The value of history column `name` of the flow now (fails if absent). */
double fixture_flow_history(const Sim *sim, const char *name);

/* cases/cylinder_confined_re10.yaml coarse (dx 0.2 m, antisymmetric
 * ghosts, divergence_term updated, to t = 4 s at most, steady to 1e-4
 * m/s^2, forces averaged from 0), then the `count` overrides `sets`, run
 * to its steady state (fails the test if it is not steady before the
 * end); prints `label`, the steps and the drag's parts, and returns the
 * steady drag, N/m. */
double fixture_coarse_cylinder_drag(const char *const *sets, int count, const char *label);

#endif
