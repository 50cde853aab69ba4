/* Ctrl-C handling: the first SIGINT (or SIGTERM) only raises a flag that the
 * time loop polls after each step, so the run finishes the step, writes the
 * outputs due and exits cleanly. A second one ends the process at once. */
#ifndef NSPD_CORE_INTERRUPT_H
#define NSPD_CORE_INTERRUPT_H

#include <stdbool.h>

void interrupt_install(void);
bool interrupt_requested(void);
void interrupt_request(void); /* as if Ctrl-C were pressed: for tests */
void interrupt_clear(void);

#endif
