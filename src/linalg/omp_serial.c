/* Serial execution of the OpenMP regions of CHOLMOD's factorisation in a one-thread run.
 *
 * Why: CHOLMOD 3 opens a parallel region (`parallel for num_threads(4) if (size > 1024)`) for
 * each large supernode it clears and assembles, tens of thousands per factorisation at 1e6
 * equations. With one thread libgomp still builds a team of one for each and ends it with a
 * futex wake system call (and, under dynamic adjustment, two more to read the load and the
 * CPU set): ~0.25 s of system time per factorisation at 1e6 equations, about 18 % of a
 * refactorisation at 2.5e5 (doc/theory.md §5). While pecplas_omp_serial_begin is in force on
 * the calling thread, GOMP_parallel, the entry point GCC emits for `omp parallel`, runs the
 * region's body directly on that thread, as an orphaned construct: the body then sees one
 * thread (omp_get_num_threads() = 1), its worksharing loops cover the whole range and its
 * barriers return at once, which is what a team of one does. Any other call is passed to
 * libgomp's GOMP_parallel unchanged.
 *
 * State: one thread-local flag (the dynamic linker resolves CHOLMOD's calls to this
 * definition, which carries no context); other threads are never affected.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>

typedef void (*gomp_parallel_fn)(void (*)(void *), void *, unsigned, unsigned);

static _Thread_local int serial = 0;

/* Until pecplas_omp_serial_end, GOMP_parallel called from this thread runs serially. */
void pecplas_omp_serial_begin(void) { serial = 1; }
void pecplas_omp_serial_end(void) { serial = 0; }

void GOMP_parallel(void (*fn)(void *), void *data, unsigned num_threads, unsigned flags) {
    static gomp_parallel_fn next = NULL; /* libgomp's, looked up once (any thread) */
    gomp_parallel_fn f = serial ? NULL : __atomic_load_n(&next, __ATOMIC_ACQUIRE);
    if (!serial && !f) {
        f = (gomp_parallel_fn)dlsym(RTLD_NEXT, "GOMP_parallel");
        __atomic_store_n(&next, f, __ATOMIC_RELEASE);
    }
    if (f)
        f(fn, data, num_threads, flags);
    else /* serial, or no libgomp behind us: a team of one */
        fn(data);
}
