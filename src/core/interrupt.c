#include "core/interrupt.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t requested; /* the signal number, or -1: interrupt_request */

static void on_signal(int sig) {
    if (requested) {
        signal(sig, SIG_DFL);
        raise(sig);
        return;
    }
    requested = sig;
}

void interrupt_install(void) {
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
    sigaction(SIGUSR1, &action, NULL);
}

bool interrupt_requested(void) {
    return requested != 0;
}

const char *interrupt_reason(void) {
    switch (requested) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    case SIGUSR1:
        return "SIGUSR1";
    default:
        return "a request";
    }
}

void interrupt_request(void) {
    requested = -1;
}

void interrupt_clear(void) {
    requested = 0;
}
