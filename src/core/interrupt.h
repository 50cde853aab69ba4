/* Stopping a run cleanly: the first SIGINT (Ctrl-C), SIGTERM or SIGUSR1 (what
 * batch schedulers send before a job's time limit) only raises a flag that
 * the time loop polls after each step, so the run finishes the step, writes
 * a checkpoint and the outputs and exits. A second signal ends the process
 * at once. */
#ifndef NSPD_CORE_INTERRUPT_H
#define NSPD_CORE_INTERRUPT_H

#include <stdbool.h>

void interrupt_install(void);
bool interrupt_requested(void);
/* The signal that asked (its name: "SIGTERM"), or "a request" for
 * interrupt_request. */
const char *interrupt_reason(void);
void interrupt_request(void); /* as if Ctrl-C were pressed: for tests */
void interrupt_clear(void);

#endif
