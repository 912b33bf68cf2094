/* Thread control for pecplas_linalg_threads: the OpenMP team of our element loops, the
 * threads of CHOLMOD's own OpenMP regions (capped through omp_serial.c) and the threads of the
 * BLAS calls under CHOLMOD's supernodal factorisation and solve.
 *
 * The BLAS is whatever libblas.so resolves to (Debian alternatives), so its thread setter is
 * looked up at run time: a BLAS without one (reference BLAS) is single-threaded anyway and
 * the build does not depend on it.
 *
 * Threads per BLAS call: CHOLMOD 3 factorises supernode by supernode, with one BLAS call
 * (dsyrk, dgemm) per descendant update and dpotrf + dtrsm per supernode: over a million calls
 * at 1e6 equations, most of them small. While pecplas_threads_calls_begin is in force on the
 * calling thread (CHOLMOD's factorisation and solve, cholmod_shim.c), each call of dgemm_,
 * dsyrk_, dtrsm_, dpotrf_, dgemv_ and dtrsv_ passes through the definitions below before the
 * BLAS's own (dlsym RTLD_NEXT). They lift the cap on CHOLMOD's own parallel regions for the
 * call (omp_serial.c), so that a BLAS threading through OpenMP keeps its threads, and, when
 * a work per thread is configured (blas_work > 0: PECPLAS_THREAD_PARTS, for benchmarks), give
 * the call
 *     threads = min(blas_threads, max(1, floor(flops / blas_work)))
 * and count the calls. The program's rule configures blas_work = 0: every call gets
 * blas_threads, which measured as fast as any split by size (doc/bench/threads.md). The
 * definitions are found first by the dynamic linker for CHOLMOD's calls (as GOMP_parallel in
 * omp_serial.c); outside begin/end they pass every call on untouched.
 *
 * State: the policy is process-wide (the BLAS thread count is too); the flag that activates
 * it is thread-local, so only the thread inside CHOLMOD chooses counts.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef void (*set_threads_fn)(int);
typedef int (*get_int_fn)(void);

/* Known BLAS thread setters, in the order they are tried. */
static const char *const BLAS_SETTERS[] = {"openblas_set_num_threads", "bli_thread_set_num_threads",
                                           "MKL_Set_Num_Threads"};
static const char *const BLAS_NAMES[] = {"OpenBLAS", "BLIS", "MKL"};

/* omp_serial.c */
void pecplas_omp_cap_begin(int n);
void pecplas_omp_cap_end(void);
int pecplas_omp_cap_suspend(void);
void pecplas_omp_cap_resume(int c);

static struct {
    int loops;        /* OpenMP team of the program's own loops */
    int regions;      /* threads of CHOLMOD's OpenMP regions */
    int blas;         /* most threads of one BLAS call */
    double work;      /* flops per BLAS thread (0: every call gets `blas`) */
    set_threads_fn setter;
    int current;      /* count last given to the setter (0: unknown) */
    double stats[4];  /* calls, calls given > 1 thread, flops, flops of those calls */
} policy = {1, 1, 1, 0.0, NULL, 0, {0, 0, 0, 0}};

static _Thread_local int active = 0;

static set_threads_fn find_setter(int *k) {
    for (int i = 0; i < 3; i++) {
        set_threads_fn f = (set_threads_fn)dlsym(RTLD_DEFAULT, BLAS_SETTERS[i]);
        if (f) {
            *k = i + 1;
            return f;
        }
    }
    *k = 0;
    return NULL;
}

/* The thread configuration: loops for the program's OpenMP loops, regions for CHOLMOD's
 * parallel regions, blas threads at most for one BLAS call, one per work flops of the call
 * (work = 0: every call gets blas). Returns the index (1-based) of the BLAS whose setter was
 * found, 0 when none is loaded. */
int pecplas_threads_configure(int loops, int regions, int blas, double work) {
    int k;
    policy.loops = loops < 1 ? 1 : loops;
    policy.regions = regions < 1 ? 1 : regions;
    policy.blas = blas < 1 ? 1 : blas;
    policy.work = work > 0.0 ? work : 0.0;
    policy.setter = find_setter(&k);
    if (policy.setter) policy.setter(policy.blas);
    policy.current = policy.blas;
#ifdef _OPENMP /* after the BLAS's setter, which may set OpenMP's count with its own */
    omp_set_num_threads(policy.loops);
    omp_set_dynamic(0);
#endif
    return k;
}

/* Name of BLAS number k as returned by pecplas_threads_configure ("" for 0). */
const char *pecplas_threads_blas_name(int k) { return (k >= 1 && k <= 3) ? BLAS_NAMES[k - 1] : ""; }

/* How the BLAS threads: "pthreads", "OpenMP", "none" (built single-threaded), "" unknown. */
const char *pecplas_threads_blas_threading(void) {
    get_int_fn f = (get_int_fn)dlsym(RTLD_DEFAULT, "openblas_get_parallel");
    if (!f) return "";
    switch (f()) {
    case 0: return "none";
    case 1: return "pthreads";
    case 2: return "OpenMP";
    default: return "";
    }
}

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

/* From here until pecplas_threads_calls_end, on this thread: CHOLMOD's parallel regions get
 * the configured threads, its BLAS calls their share. */
void pecplas_threads_calls_begin(void) {
    pecplas_omp_cap_begin(policy.regions);
    active = policy.work > 0.0 && policy.blas > 1 && policy.setter;
}

/* Ends pecplas_threads_calls_begin: the BLAS and OpenMP counts are the configured ones again
 * (a BLAS that threads through OpenMP sets the OpenMP count with its own). */
void pecplas_threads_calls_end(void) {
    pecplas_omp_cap_end();
    if (active && policy.current != policy.blas) {
        policy.setter(policy.blas);
        policy.current = policy.blas;
    }
    active = 0;
#ifdef _OPENMP
    if (omp_get_max_threads() != policy.loops) omp_set_num_threads(policy.loops);
#endif
}

/* Counters of the BLAS calls made between begin and end since the last reset (only while a
 * work per thread is configured):
 * out = calls, calls given more than one thread, flops, flops of those calls. */
void pecplas_threads_calls_stats(double *out, int reset) {
    for (int i = 0; i < 4; i++) {
        out[i] = policy.stats[i];
        if (reset) policy.stats[i] = 0.0;
    }
}

/* Gives the BLAS the threads for a call of `flops` (only on the active thread). */
static inline void share(double flops) {
    if (!active) return;
    double t = flops / policy.work;
    int n = t >= policy.blas ? policy.blas : (t >= 2.0 ? (int)t : 1);
    if (n != policy.current) {
        policy.setter(n);
        policy.current = n;
    }
    policy.stats[0] += 1.0;
    policy.stats[2] += flops;
    if (n > 1) {
        policy.stats[1] += 1.0;
        policy.stats[3] += flops;
    }
}

/* The BLAS's own definition of `name` (the next one after ours), looked up once. */
static void *next_symbol(void **slot, const char *name) {
    void *f = __atomic_load_n(slot, __ATOMIC_ACQUIRE);
    if (!f) {
        f = dlsym(RTLD_NEXT, name);
        if (!f) {
            fprintf(stderr, "pecplas: no BLAS/LAPACK routine %s found\n", name);
            abort();
        }
        __atomic_store_n(slot, f, __ATOMIC_RELEASE);
    }
    return f;
}

/* The Fortran BLAS/LAPACK entry points (32-bit integers, as CHOLMOD's int interface and the
 * Debian BLAS use; the hidden lengths of the character arguments are not read by the BLAS and
 * not passed on). */
typedef void (*gemm_fn)(const char *, const char *, const int *, const int *, const int *,
                        const double *, const double *, const int *, const double *, const int *,
                        const double *, double *, const int *);
typedef void (*syrk_fn)(const char *, const char *, const int *, const int *, const double *,
                        const double *, const int *, const double *, double *, const int *);
typedef void (*trsm_fn)(const char *, const char *, const char *, const char *, const int *,
                        const int *, const double *, const double *, const int *, double *,
                        const int *);
typedef void (*potrf_fn)(const char *, const int *, double *, const int *, int *);
typedef void (*gemv_fn)(const char *, const int *, const int *, const double *, const double *,
                        const int *, const double *, const int *, const double *, double *,
                        const int *);
typedef void (*trsv_fn)(const char *, const char *, const char *, const int *, const double *,
                        const int *, double *, const int *);

void dgemm_(const char *ta, const char *tb, const int *m, const int *n, const int *k,
            const double *alpha, const double *a, const int *lda, const double *b,
            const int *ldb, const double *beta, double *c, const int *ldc) {
    static void *next = NULL;
    share(2.0 * *m * *n * *k);
    int cap = pecplas_omp_cap_suspend();
    ((gemm_fn)next_symbol(&next, "dgemm_"))(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
    pecplas_omp_cap_resume(cap);
}

void dsyrk_(const char *uplo, const char *trans, const int *n, const int *k, const double *alpha,
            const double *a, const int *lda, const double *beta, double *c, const int *ldc) {
    static void *next = NULL;
    share(1.0 * *n * *n * *k);
    int cap = pecplas_omp_cap_suspend();
    ((syrk_fn)next_symbol(&next, "dsyrk_"))(uplo, trans, n, k, alpha, a, lda, beta, c, ldc);
    pecplas_omp_cap_resume(cap);
}

void dtrsm_(const char *side, const char *uplo, const char *transa, const char *diag,
            const int *m, const int *n, const double *alpha, const double *a, const int *lda,
            double *b, const int *ldb) {
    static void *next = NULL;
    int left = *side == 'L' || *side == 'l';
    share(left ? 1.0 * *m * *m * *n : 1.0 * *m * *n * *n);
    int cap = pecplas_omp_cap_suspend();
    ((trsm_fn)next_symbol(&next, "dtrsm_"))(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
    pecplas_omp_cap_resume(cap);
}

void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info) {
    static void *next = NULL;
    share(1.0 * *n * *n * *n / 3.0);
    int cap = pecplas_omp_cap_suspend();
    ((potrf_fn)next_symbol(&next, "dpotrf_"))(uplo, n, a, lda, info);
    pecplas_omp_cap_resume(cap);
}

void dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
            const int *lda, const double *x, const int *incx, const double *beta, double *y,
            const int *incy) {
    static void *next = NULL;
    share(2.0 * *m * *n);
    int cap = pecplas_omp_cap_suspend();
    ((gemv_fn)next_symbol(&next, "dgemv_"))(trans, m, n, alpha, a, lda, x, incx, beta, y, incy);
    pecplas_omp_cap_resume(cap);
}

void dtrsv_(const char *uplo, const char *trans, const char *diag, const int *n, const double *a,
            const int *lda, double *x, const int *incx) {
    static void *next = NULL;
    share(1.0 * *n * *n);
    int cap = pecplas_omp_cap_suspend();
    ((trsv_fn)next_symbol(&next, "dtrsv_"))(uplo, trans, diag, n, a, lda, x, incx);
    pecplas_omp_cap_resume(cap);
}
