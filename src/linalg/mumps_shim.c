/* MUMPS (dmumps_c) for pecplas_linalg_mumps, MPI build only (PECPLAS_MPI): one handle per
 * solver holds the DMUMPS_STRUC_C and copies of this rank's share of the matrix, which MUMPS
 * reads at analysis (pattern) and at each factorisation (values) in distributed assembled
 * form (ICNTL(18) = 3). The right-hand side is centralised on rank 0 and the solution is
 * broadcast back, so every rank holds the same x. The serial build compiles stubs that say
 * MUMPS is not available.
 */
#include <stdlib.h>
#include <string.h>
#ifdef PECPLAS_MPI
#include <dmumps_c.h>
#include <mpi.h>

#define ICNTL(k) icntl[(k) - 1]
#define CNTL(k) cntl[(k) - 1]
#define INFOG(k) infog[(k) - 1]
#define RINFOG(k) rinfog[(k) - 1]

typedef struct {
    DMUMPS_STRUC_C id;
    MUMPS_INT *irn, *jcn;
    double *a;
    MUMPS_INT nz;
} pecplas_mumps_t;

int pecplas_mumps_available(void) { return 1; }

/* MPI_Finalize at exit, for a program that let the first MUMPS solver start MPI. */
static void finalize_at_exit(void) {
    int done = 0;
    MPI_Finalized(&done);
    if (!done) MPI_Finalize();
}

/* Starts MPI for a program that did not (a test driver), before the ranks agree on the
 * matrix's symmetry and before the first handle. */
void pecplas_mumps_start(void) {
    int started = 0;
    MPI_Initialized(&started);
    if (!started) {
        MPI_Init(NULL, NULL);
        atexit(finalize_at_exit);
    }
}

/* sym: 0 unsymmetric, 2 general symmetric; tol: null-pivot threshold (CNTL(3)). */
void *pecplas_mumps_new(int sym, double tol, int *status) {
    pecplas_mumps_t *h = calloc(1, sizeof *h);
    if (!h) {
        *status = -13;
        return NULL;
    }
    pecplas_mumps_start();
    h->id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(MPI_COMM_WORLD);
    h->id.par = 1; /* rank 0 takes part in the factorisation */
    h->id.sym = sym;
    h->id.job = -1;
    dmumps_c(&h->id);
    *status = h->id.INFOG(1);
    if (*status < 0) return h;
    h->id.ICNTL(1) = -1; /* no messages: errors come back in INFOG(1) */
    h->id.ICNTL(2) = -1;
    h->id.ICNTL(3) = -1;
    h->id.ICNTL(4) = 0;
    h->id.ICNTL(18) = 3; /* distributed assembled matrix */
    h->id.ICNTL(24) = 1; /* null pivot detection: a mechanism is reported, not solved */
    h->id.CNTL(3) = tol;
    return h;
}

/* Analysis of this rank's entries (1-based rows and columns), n the global order. */
int pecplas_mumps_analyse(void *hv, int n, int nz, const int *irn, const int *jcn) {
    pecplas_mumps_t *h = hv;
    free(h->irn);
    free(h->jcn);
    free(h->a);
    h->nz = nz;
    h->irn = malloc(sizeof(MUMPS_INT) * (nz > 0 ? nz : 1));
    h->jcn = malloc(sizeof(MUMPS_INT) * (nz > 0 ? nz : 1));
    h->a = malloc(sizeof(double) * (nz > 0 ? nz : 1));
    if (!h->irn || !h->jcn || !h->a) return -13;
    for (int k = 0; k < nz; k++) {
        h->irn[k] = irn[k];
        h->jcn[k] = jcn[k];
    }
    h->id.n = n;
    h->id.nnz_loc = nz;
    h->id.irn_loc = h->irn;
    h->id.jcn_loc = h->jcn;
    h->id.a_loc = h->a;
    h->id.job = 1;
    dmumps_c(&h->id);
    return h->id.INFOG(1);
}

/* Numeric factorisation with this rank's values, in the order given to the analysis. */
int pecplas_mumps_factorise(void *hv, const double *a) {
    pecplas_mumps_t *h = hv;
    memcpy(h->a, a, sizeof(double) * h->nz);
    h->id.job = 2;
    dmumps_c(&h->id);
    return h->id.INFOG(1);
}

/* Solves for nrhs columns of b(n, nrhs) (rank 0's b is used); x returns on every rank. */
int pecplas_mumps_solve(void *hv, int nrhs, double *b) {
    pecplas_mumps_t *h = hv;
    h->id.nrhs = nrhs;
    h->id.lrhs = h->id.n;
    h->id.rhs = b;
    h->id.job = 3;
    dmumps_c(&h->id);
    int status = h->id.INFOG(1);
    MPI_Bcast(b, h->id.n * nrhs, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return status;
}

/* infog(1:80), rinfog(1:40); first null pivot (1-based, 0 if none) broadcast from rank 0. */
void pecplas_mumps_info(void *hv, int *infog, double *rinfog, int *null_pivot) {
    pecplas_mumps_t *h = hv;
    for (int k = 0; k < 80; k++) infog[k] = h->id.infog[k];
    for (int k = 0; k < 40; k++) rinfog[k] = h->id.rinfog[k];
    int first = 0;
    if (h->id.INFOG(28) > 0 && h->id.pivnul_list) first = h->id.pivnul_list[0];
    MPI_Bcast(&first, 1, MPI_INT, 0, MPI_COMM_WORLD);
    *null_pivot = first;
}

void pecplas_mumps_free(void *hv) {
    pecplas_mumps_t *h = hv;
    if (!h) return;
    h->id.job = -2;
    dmumps_c(&h->id);
    free(h->irn);
    free(h->jcn);
    free(h->a);
    free(h);
}

#else

int pecplas_mumps_available(void) { return 0; }
void pecplas_mumps_start(void) {}
void *pecplas_mumps_new(int sym, double tol, int *status) {
    (void)sym;
    (void)tol;
    *status = -999;
    return NULL;
}
int pecplas_mumps_analyse(void *h, int n, int nz, const int *irn, const int *jcn) {
    (void)h; (void)n; (void)nz; (void)irn; (void)jcn;
    return -999;
}
int pecplas_mumps_factorise(void *h, const double *a) {
    (void)h; (void)a;
    return -999;
}
int pecplas_mumps_solve(void *h, int nrhs, double *b) {
    (void)h; (void)nrhs; (void)b;
    return -999;
}
void pecplas_mumps_info(void *h, int *infog, double *rinfog, int *null_pivot) {
    (void)h;
    memset(infog, 0, 80 * sizeof(int));
    memset(rinfog, 0, 40 * sizeof(double));
    *null_pivot = 0;
}
void pecplas_mumps_free(void *h) { (void)h; }

#endif
