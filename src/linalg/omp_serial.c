/* Capped OpenMP regions inside CHOLMOD's factorisation: how many threads its parallel regions
 * get is the program's decision (pecplas_threads_configure), not CHOLMOD's.
 *
 * Why: CHOLMOD 3 opens a parallel region (`parallel for num_threads(4) if (size > 1024)`) for
 * each large supernode it clears and assembles, tens of thousands per factorisation at 1e6
 * equations, and asks for 4 threads whatever the program's setting. With one thread libgomp
 * still builds a team of one for each and ends it with a futex wake system call: ~0.25 s of
 * system time per factorisation at 1e6 equations, about 18 % of a refactorisation at 2.5e5
 * (doc/theory.md §5). With several, the team's threads spin between regions on the cores the
 * BLAS threads under the factorisation need.
 *
 * While a cap is in force on the calling thread (pecplas_omp_cap_begin(n)), GOMP_parallel,
 * the entry point GCC emits for `omp parallel`, gets at most n threads; a region that would
 * have one (n = 1, or its `if` clause false: GCC then asks for 1) runs its body directly on
 * that thread, as an orphaned construct: the body then sees one thread
 * (omp_get_num_threads() = 1), its worksharing loops cover the whole range and its barriers
 * return at once, which is what a team of one does. Any other call is passed to libgomp's
 * GOMP_parallel unchanged. pecplas_omp_serial_begin/end are the cap of one.
 *
 * State: one thread-local cap (the dynamic linker resolves CHOLMOD's calls to this
 * definition, which carries no context); other threads are never affected.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>

typedef void (*gomp_parallel_fn)(void (*)(void *), void *, unsigned, unsigned);

static _Thread_local unsigned cap = 0; /* 0: no cap */

/* Until pecplas_omp_cap_end, parallel regions started on this thread get at most n threads
 * (n >= 1; one runs the region on this thread alone). */
void pecplas_omp_cap_begin(int n) { cap = n < 1 ? 1u : (unsigned)n; }
void pecplas_omp_cap_end(void) { cap = 0; }

/* The cap in force on this thread, lifted until pecplas_omp_cap_resume: a BLAS that threads
 * through OpenMP (OpenBLAS's OpenMP build) gets the threads its own setting gives it, not
 * CHOLMOD's cap (threads_shim.c brackets each BLAS call made under the cap). */
int pecplas_omp_cap_suspend(void) {
    int c = (int)cap;
    cap = 0;
    return c;
}
void pecplas_omp_cap_resume(int c) { cap = (unsigned)c; }

/* Until pecplas_omp_serial_end, GOMP_parallel called from this thread runs serially. */
void pecplas_omp_serial_begin(void) { pecplas_omp_cap_begin(1); }
void pecplas_omp_serial_end(void) { pecplas_omp_cap_end(); }

void GOMP_parallel(void (*fn)(void *), void *data, unsigned num_threads, unsigned flags) {
    static gomp_parallel_fn next = NULL; /* libgomp's, looked up once (any thread) */
    if (cap) {
        if (cap == 1 || num_threads == 1) { /* a team of one */
            fn(data);
            return;
        }
        if (num_threads == 0 || num_threads > cap) num_threads = cap;
    }
    gomp_parallel_fn f = __atomic_load_n(&next, __ATOMIC_ACQUIRE);
    if (!f) {
        f = (gomp_parallel_fn)dlsym(RTLD_NEXT, "GOMP_parallel");
        __atomic_store_n(&next, f, __ATOMIC_RELEASE);
    }
    if (f)
        f(fn, data, num_threads, flags);
    else /* no libgomp behind us: a team of one */
        fn(data);
}
