/* Thread control for pecplas_linalg_threads: the OpenMP team of our element loops (and of
 * CHOLMOD, which shares the OpenMP runtime) and the threads of the BLAS under CHOLMOD's
 * supernodal factorisation. The BLAS is whatever libblas.so resolves to (Debian
 * alternatives), so its thread setter is looked up at run time: a BLAS without one
 * (reference BLAS) is single-threaded anyway and the build does not depend on it.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdlib.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef void (*set_threads_fn)(int);

/* Known BLAS thread setters, in the order they are tried. */
static const char *const BLAS_SETTERS[] = {"openblas_set_num_threads", "bli_thread_set_num_threads",
                                           "MKL_Set_Num_Threads"};
static const char *const BLAS_NAMES[] = {"OpenBLAS", "BLIS", "MKL"};

/* Sets n threads for OpenMP and for the BLAS. Returns the index (1-based) of the BLAS
 * whose setter was called, 0 when none is loaded.
 * Test hook: PECPLAS_TEST_BLAS_THREADS=M (M >= 1) gives the BLAS M threads whatever n is, so
 * that test/python/test_threads.py can hold the BLAS at one thread and require the program's
 * own parallel loops to give the same bits on 1 and 2 threads. */
int pecplas_threads_set(int n) {
    if (n < 1) n = 1;
#ifdef _OPENMP
    omp_set_num_threads(n);
    omp_set_dynamic(0);
#endif
    int nblas = n;
    const char *hook = getenv("PECPLAS_TEST_BLAS_THREADS");
    if (hook && atoi(hook) >= 1) nblas = atoi(hook);
    for (int k = 0; k < 3; k++) {
        set_threads_fn f = (set_threads_fn)dlsym(RTLD_DEFAULT, BLAS_SETTERS[k]);
        if (f) {
            f(nblas);
            return k + 1;
        }
    }
    return 0;
}

/* Name of BLAS number k as returned by pecplas_threads_set ("" for 0). */
const char *pecplas_threads_blas_name(int k) { return (k >= 1 && k <= 3) ? BLAS_NAMES[k - 1] : ""; }

/* Threads an OpenMP region would use now (1 without OpenMP). */
int pecplas_threads_max(void) {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

/* Processors available to the program (1 without OpenMP). */
int pecplas_threads_procs(void) {
#ifdef _OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}

/* 1 when the program was built with OpenMP. */
int pecplas_threads_openmp(void) {
#ifdef _OPENMP
    return 1;
#else
    return 0;
#endif
}
