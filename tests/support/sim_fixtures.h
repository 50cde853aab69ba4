/* Simulations built from the case files under cases/, for verify tests. */
#ifndef NSPD_TEST_SIM_FIXTURES_H
#define NSPD_TEST_SIM_FIXTURES_H

#include "sim/sim.h"

/* Reads cases/<name> with the given --set overrides and builds the
 * simulation; fails the test on any error. */
void fixture_sim(const char *case_file, const char *const *overrides, int count, Sim *sim);

/* Builds a simulation from a case written in the test (YAML text); fails the
 * test on any error. */
void fixture_sim_text(const char *yaml, Sim *sim);

#endif
