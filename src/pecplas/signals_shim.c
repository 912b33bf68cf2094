/* C side of pecplas_signals: sigaction and a sig_atomic_t flag, which Fortran cannot
 * declare portably. No logic beyond binding: the decisions are made on the Fortran side.
 */
#include <signal.h>
#include <string.h>

static volatile sig_atomic_t pecplas_signal_caught = 0;

static void pecplas_on_signal(int sig) { pecplas_signal_caught = sig; }

/* SIGTERM, SIGINT and SIGHUP set the flag; SA_RESETHAND restores the default action, so a
 * second signal of the same kind ends the process at once. Returns 0 on success. */
int pecplas_install_signal_handlers(void) {
    static const int sigs[3] = {SIGTERM, SIGINT, SIGHUP};
    struct sigaction sa;
    int i;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = pecplas_on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND | SA_RESTART;
    for (i = 0; i < 3; i++)
        if (sigaction(sigs[i], &sa, NULL) != 0) return -1;
    return 0;
}

/* The number of the last signal caught since the handlers were installed, 0 if none. */
int pecplas_signal_number(void) { return (int)pecplas_signal_caught; }

/* Forgets a caught signal (tests). */
void pecplas_signal_clear(void) { pecplas_signal_caught = 0; }
