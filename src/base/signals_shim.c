/* C side of pecplas_base_signals: sigaction and a sig_atomic_t flag, which Fortran cannot
 * declare portably, and the crash guard (a handler that may only call write and _exit).
 * The decisions are made on the Fortran side.
 */
#include <signal.h>
#include <string.h>
#include <unistd.h>

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

/* A guard around a library call that reads a file the program did not write in this run
 * (a restart file): HDF5 may crash on a damaged file (seen: a segmentation fault inside
 * H5Fopen and H5Aexists on randomly damaged results files). While the guard is up, a crash
 * signal writes `message` and ends the process with exit code 2 (an input error) instead
 * of a bare crash; nothing has been written by the run at that point. guard_end puts the
 * previous actions back (the Fortran runtime's own backtrace handler among them). */
static const int pecplas_guard_sigs[4] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL};
static struct sigaction pecplas_guard_old[4];
static char pecplas_guard_text[1024];
static size_t pecplas_guard_len = 0;

static void pecplas_on_crash(int sig) {
    (void)sig;
    (void)!write(2, pecplas_guard_text, pecplas_guard_len);
    _exit(2);
}

/* message: its first len bytes (a newline is added). Returns 0 on success. */
int pecplas_guard_begin(const char *message, int len) {
    struct sigaction sa;
    int i;
    if (len < 0) len = 0;
    if ((size_t)len > sizeof pecplas_guard_text - 2) len = (int)sizeof pecplas_guard_text - 2;
    memcpy(pecplas_guard_text, message, (size_t)len);
    pecplas_guard_text[len] = '\n';
    pecplas_guard_len = (size_t)len + 1;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = pecplas_on_crash;
    sigemptyset(&sa.sa_mask);
    for (i = 0; i < 4; i++)
        if (sigaction(pecplas_guard_sigs[i], &sa, &pecplas_guard_old[i]) != 0) return -1;
    return 0;
}

void pecplas_guard_end(void) {
    int i;
    for (i = 0; i < 4; i++) sigaction(pecplas_guard_sigs[i], &pecplas_guard_old[i], NULL);
}
