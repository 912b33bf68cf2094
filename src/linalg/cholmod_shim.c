/* Thin C99 shim around CHOLMOD's int interface for pecplas_linalg_cholmod.
 *
 * cholmod_common is a large C struct whose layout Fortran cannot reproduce portably, so it
 * lives in an opaque handle allocated here. The matrix is never copied: a cholmod_sparse
 * header is laid over the caller's CSC arrays (0-based int, rows sorted, stype = 1 so only
 * the upper triangle is read, whether the full matrix or only its upper part is stored).
 * Beyond binding, one decision is made here so that the program and a bare benchmark of
 * the same matrix order it alike: the fill-reducing ordering (pecplas_cholmod_analyse).
 */
#include <stdlib.h>
#include <string.h>
#if defined(__has_include)
#if __has_include(<suitesparse/cholmod.h>)
#include <suitesparse/cholmod.h>
#else
#include <cholmod.h>
#endif
#else
#include <cholmod.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

/* threads_shim.c: in between, CHOLMOD's OpenMP regions and BLAS calls on this thread get
 * the threads the program's configuration gives them */
void pecplas_threads_calls_begin(void);
void pecplas_threads_calls_end(void);

/* Requested fill-reducing ordering: the project's rule, CHOLMOD's own default strategy, or
 * one CHOLMOD ordering code (CHOLMOD_AMD, CHOLMOD_METIS, CHOLMOD_NESDIS, ...). */
enum { PECPLAS_ORDER_RULE = -1, PECPLAS_ORDER_CHOLMOD_DEFAULT = -2, PECPLAS_ORDER_METIS_NODES = -3 };

typedef struct {
    cholmod_common c;
    cholmod_factor *L;
    cholmod_dense *X, *Y, *E; /* solve workspaces kept between solves */
    int ordering;             /* requested ordering, see the enum above */
    int nodes_metis;          /* the last analysis used metis_on_nodes */
    int nd_pending;           /* the rule tries METIS at the second factorisation */
    long nfact;               /* numeric factorisations since the last analysis */
} pecplas_cholmod;

/* Header over caller-owned CSC arrays (values may be NULL for a pattern). */
static cholmod_sparse wrap(int n, const int *colptr, const int *rowind, const double *x) {
    cholmod_sparse a;
    memset(&a, 0, sizeof a);
    a.nrow = (size_t)n;
    a.ncol = (size_t)n;
    a.nzmax = (size_t)colptr[n];
    a.p = (void *)colptr;
    a.i = (void *)rowind;
    a.x = (void *)x;
    a.stype = 1;
    a.itype = CHOLMOD_INT;
    a.xtype = x ? CHOLMOD_REAL : CHOLMOD_PATTERN;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
}

/* The ordering of a new handle: the project's rule, unless PECPLAS_ORDERING names AMD or
 * METIS (METIS on the graph of nodes) instead. For benchmarks only (as PECPLAS_THREAD_PARTS in
 * threads_shim.c): it lets the thread benchmark weigh the serial METIS ordering against the
 * factorisation flops it saves at each thread count (doc/bench/threads.md); any other value
 * is ignored. */
static int bench_ordering(void) {
    const char *v = getenv("PECPLAS_ORDERING");
    if (v && strcmp(v, "AMD") == 0) return CHOLMOD_AMD;
    if (v && strcmp(v, "METIS") == 0) return PECPLAS_ORDER_METIS_NODES;
    return PECPLAS_ORDER_RULE;
}

/* New handle. ldl = 0: supernodal LL' (production); ldl = 1: simplicial LDL' (used to tell
 * a singular matrix from an indefinite one). Fill-reducing ordering by the project's rule
 * (pecplas_cholmod_analyse); the one used is read back with pecplas_cholmod_ordering. */
void *pecplas_cholmod_new(int ldl) {
    pecplas_cholmod *h = calloc(1, sizeof *h);
    if (!h) return NULL;
    cholmod_start(&h->c);
    h->c.print = 0; /* errors are reported by the caller from the status */
    h->c.supernodal = ldl ? CHOLMOD_SIMPLICIAL : CHOLMOD_SUPERNODAL;
    h->c.final_ll = ldl ? 0 : 1;
    h->ordering = bench_ordering();
#if CHOLMOD_MAIN_VERSION >= 4 && defined(_OPENMP)
    h->c.nthreads_max = omp_get_max_threads(); /* the program's thread setting */
#endif
    return h;
}

void pecplas_cholmod_delete(void *handle) {
    pecplas_cholmod *h = handle;
    if (!h) return;
    cholmod_free_factor(&h->L, &h->c);
    cholmod_free_dense(&h->X, &h->c);
    cholmod_free_dense(&h->Y, &h->c);
    cholmod_free_dense(&h->E, &h->c);
    cholmod_finish(&h->c);
    free(h);
}

/* Requests an ordering for the next analyses: -1 the project's rule (the default), -2
 * CHOLMOD's own default strategy, -3 METIS on the graph of nodes, else a CHOLMOD ordering
 * code (benchmarks compare them). */
void pecplas_cholmod_set_ordering(void *handle, int ordering) {
    ((pecplas_cholmod *)handle)->ordering = ordering;
}

/* METIS nested dissection of the graph of nodes. Adjacent equations whose columns in the
 * full pattern of A are the same set (the degrees of freedom of one node) are merged into one
 * vertex; the graph METIS_NodeND orders then has about half the vertices and a quarter of
 * the edges of the equation graph CHOLMOD's own METIS call would order, which makes nested
 * dissection cheap enough to pay at 1e5-1e6 equations. On success perm[k] is the equation
 * eliminated k-th (0-based) and 1 is returned; 0 on failure (out of memory, METIS error). */
static int metis_on_nodes(cholmod_common *c, cholmod_sparse *a, int *perm) {
    int n = (int)a->nrow, ok = 0;
    cholmod_sparse *s = cholmod_copy(a, 0, 0, c); /* both triangles, pattern with diagonal */
    int *first = malloc(sizeof(int) * ((size_t)n + 1)), *group = malloc(sizeof(int) * (size_t)n);
    int *mark = malloc(sizeof(int) * (size_t)n), *cperm = malloc(sizeof(int) * (size_t)n);
    cholmod_sparse *g = NULL;
    if (!s || !first || !group || !mark || !cperm) goto done;
    const int *sp = s->p, *si = s->i;
    int ng = 0;
    for (int i = 0; i < n; i++) mark[i] = -1;
    for (int j = 0; j < n; j++) { /* a new vertex unless column j equals column j-1 */
        int same = j > 0 && sp[j + 1] - sp[j] == sp[j] - sp[j - 1];
        for (int q = sp[j]; same && q < sp[j + 1]; q++) same = mark[si[q]] == j - 1;
        for (int q = sp[j]; q < sp[j + 1]; q++) mark[si[q]] = j;
        if (!same) first[ng++] = j;
        group[j] = ng - 1;
    }
    first[ng] = n;
    /* upper triangle of the vertex graph, each edge once (stamps in mark) */
    size_t nz = 0;
    for (int i = 0; i < n; i++) mark[i] = -1;
    for (int v = 0; v < ng; v++)
        for (int q = sp[first[v]]; q < sp[first[v] + 1]; q++) {
            int w = group[si[q]];
            if (w < v && mark[w] != v) { mark[w] = v; nz++; }
        }
    g = cholmod_allocate_sparse((size_t)ng, (size_t)ng, nz, 0, 1, 1, CHOLMOD_PATTERN, c);
    if (!g) goto done;
    int *gp = g->p, *gi = g->i;
    nz = 0;
    for (int i = 0; i < n; i++) mark[i] = -1;
    for (int v = 0; v < ng; v++) {
        gp[v] = (int)nz;
        for (int q = sp[first[v]]; q < sp[first[v] + 1]; q++) {
            int w = group[si[q]];
            if (w < v && mark[w] != v) { mark[w] = v; gi[nz++] = w; }
        }
    }
    gp[ng] = (int)nz;
    cholmod_free_sparse(&s, c); /* before METIS, which needs the memory */
    if (!cholmod_metis(g, NULL, 0, 0, cperm, c)) goto done;
    int k = 0;
    for (int q = 0; q < ng; q++)
        for (int j = first[cperm[q]]; j < first[cperm[q] + 1]; j++) perm[k++] = j;
    ok = k == n;
done:
    cholmod_free_sparse(&s, c);
    cholmod_free_sparse(&g, c);
    free(first);
    free(group);
    free(mark);
    free(cperm);
    return ok;
}

/* Analysis with one requested ordering (not the rule); perm: METIS_NODES' scratch. */
static cholmod_factor *analyse_with(pecplas_cholmod *h, cholmod_sparse *a, int ordering,
                                    int *perm) {
    h->nodes_metis = 0;
    if (ordering == PECPLAS_ORDER_METIS_NODES) {
        h->nodes_metis = perm && metis_on_nodes(&h->c, a, perm);
        h->c.status = CHOLMOD_OK;
        ordering = h->nodes_metis ? CHOLMOD_GIVEN : CHOLMOD_AMD; /* METIS failed: AMD */
    }
    h->c.nmethods = ordering == PECPLAS_ORDER_CHOLMOD_DEFAULT ? 0 : 1;
    h->c.method[0].ordering = ordering == PECPLAS_ORDER_CHOLMOD_DEFAULT ? CHOLMOD_GIVEN : ordering;
    return cholmod_analyze_p(a, h->nodes_metis ? perm : NULL, NULL, 0, &h->c);
}

/* AMD's flops per entry of L from which nested dissection is tried too: the test CHOLMOD's
 * default strategy uses (it then runs METIS on the equation graph). From ND_NOW on the gain
 * is large (2-D Q8 blocks at 1e6 equations: 1100 flops per entry, METIS halves the flops and
 * saves ~4 s per factorisation for ~4 s of ordering: a single factorisation loses ~0.5 s, a
 * Newton run gains from the second on); between the two it is ~10 % (Q4 blocks: 550-650),
 * which pays only over several factorisations (doc/bench/ordering.md). */
#define PECPLAS_ND_FLOPS_PER_ENTRY 500.0
#define PECPLAS_ND_NOW_FLOPS_PER_ENTRY 1000.0

/* METIS on the graph of nodes for the analysed pattern `a`; kept when it has fewer flops
 * than the current analysis (AMD), which stays otherwise. */
static void try_nested_dissection(pecplas_cholmod *h, cholmod_sparse *a) {
    double fl = h->c.fl, lnz = h->c.lnz;
    int *perm = malloc(sizeof(int) * a->nrow);
    cholmod_factor *nd = perm ? analyse_with(h, a, PECPLAS_ORDER_METIS_NODES, perm) : NULL;
    if (nd && h->nodes_metis && h->c.fl < fl) {
        cholmod_free_factor(&h->L, &h->c);
        h->L = nd;
    } else { /* AMD stays */
        cholmod_free_factor(&nd, &h->c);
        h->nodes_metis = 0;
        h->c.fl = fl;
        h->c.lnz = lnz;
        h->c.status = CHOLMOD_OK;
    }
    free(perm);
}

/* Symbolic analysis (ordering + supernodes) of the pattern; replaces any earlier one.
 * The project's rule: AMD, the fastest ordering; when it leaves PECPLAS_ND_NOW_FLOPS_PER_ENTRY
 * or more flops per entry of L, also METIS on the graph of nodes at once, and the ordering
 * with the smaller flop count is kept; from PECPLAS_ND_FLOPS_PER_ENTRY on, the same test is
 * made at the second numeric factorisation of the pattern (a run that factorises once, such
 * as a linear one, does not pay for METIS). CHOLMOD's default strategy makes the 500 test at
 * once but runs METIS on the equation graph, which at 1e6 equations takes two to three
 * times longer, and keeps the smaller nnz(L) (doc/bench/ordering.md). */
int pecplas_cholmod_analyse(void *handle, int n, const int *colptr, const int *rowind) {
    pecplas_cholmod *h = handle;
    cholmod_sparse a = wrap(n, colptr, rowind, NULL);
    int *perm = NULL;
    cholmod_free_factor(&h->L, &h->c);
    h->nd_pending = 0;
    h->nfact = 0;
    if (h->ordering != PECPLAS_ORDER_RULE) {
        if (h->ordering == PECPLAS_ORDER_METIS_NODES) perm = malloc(sizeof(int) * (size_t)n);
        h->L = analyse_with(h, &a, h->ordering, perm);
        free(perm);
    } else {
        h->L = analyse_with(h, &a, CHOLMOD_AMD, NULL);
        if (h->L && h->c.fl >= PECPLAS_ND_NOW_FLOPS_PER_ENTRY * h->c.lnz)
            try_nested_dissection(h, &a);
        else if (h->L && h->c.fl >= PECPLAS_ND_FLOPS_PER_ENTRY * h->c.lnz)
            h->nd_pending = 1;
    }
    return h->L ? h->c.status : (h->c.status < 0 ? h->c.status : CHOLMOD_INVALID);
}

/* Numeric factorisation on the analysed pattern. Returns Common->status
 * (CHOLMOD_NOT_POSDEF = 1 when a pivot is not positive; see pecplas_cholmod_minor). */
int pecplas_cholmod_factorise(void *handle, int n, const int *colptr, const int *rowind,
                              const double *x) {
    pecplas_cholmod *h = handle;
    if (!h->L) return CHOLMOD_INVALID;
    cholmod_sparse a = wrap(n, colptr, rowind, x);
    if (h->nd_pending && h->nfact >= 1) { /* the rule's deferred test, see above */
        cholmod_sparse pattern = wrap(n, colptr, rowind, NULL);
        h->nd_pending = 0;
        try_nested_dissection(h, &pattern);
    }
    h->nfact++;
    /* CHOLMOD 3.x asks for a fixed team, num_threads(CHOLMOD_OMP_NUM_THREADS = 4), in its
     * supernodal factorisation whatever OMP_NUM_THREADS says, and the BLAS splits each of its
     * calls among all the threads it is given: the program's thread configuration decides
     * both here (threads_shim.c, omp_serial.c). */
    pecplas_threads_calls_begin();
    cholmod_factorize(&a, h->L, &h->c);
    pecplas_threads_calls_end();
    return h->c.status;
}

/* Solves A X = B for nrhs columns stored one after another (leading dimension n). */
int pecplas_cholmod_solve(void *handle, int n, int nrhs, const double *b, double *x) {
    pecplas_cholmod *h = handle;
    if (!h->L) return CHOLMOD_INVALID;
    cholmod_dense bd;
    memset(&bd, 0, sizeof bd);
    bd.nrow = (size_t)n;
    bd.ncol = (size_t)nrhs;
    bd.nzmax = (size_t)n * (size_t)nrhs;
    bd.d = (size_t)n;
    bd.x = (void *)b;
    bd.xtype = CHOLMOD_REAL;
    bd.dtype = CHOLMOD_DOUBLE;
    pecplas_threads_calls_begin();
    int ok = cholmod_solve2(CHOLMOD_A, h->L, &bd, NULL, &h->X, NULL, &h->Y, &h->E, &h->c);
    pecplas_threads_calls_end();
    if (!ok)
        return h->c.status < 0 ? h->c.status : CHOLMOD_INVALID;
    memcpy(x, h->X->x, sizeof(double) * (size_t)n * (size_t)nrhs);
    return h->c.status;
}

/* Pivots in factor order: D(k,k) for LDL', L(k,k)^2 for LL'. Returns 0 on success. */
int pecplas_cholmod_pivots(void *handle, double *d) {
    pecplas_cholmod *h = handle;
    cholmod_factor *L = h->L;
    if (!L || L->xtype == CHOLMOD_PATTERN) return -1;
    const double *x = L->x;
    if (L->is_super) {
        const int *super = L->super, *pi = L->pi, *px = L->px;
        for (size_t s = 0; s < L->nsuper; s++) {
            int k1 = super[s], nrow = pi[s + 1] - pi[s];
            for (int j = k1; j < super[s + 1]; j++) {
                double l = x[px[s] + (j - k1) + (size_t)(j - k1) * nrow];
                d[j] = l * l;
            }
        }
    } else {
        const int *p = L->p;
        for (size_t j = 0; j < L->n; j++) {
            double l = x[p[j]];
            d[j] = L->is_ll ? l * l : l;
        }
    }
    return 0;
}

/* Fill-reducing permutation, 0-based: factor column k is equation perm[k]. */
int pecplas_cholmod_perm(void *handle, int *perm) {
    pecplas_cholmod *h = handle;
    if (!h->L || !h->L->Perm) return -1;
    memcpy(perm, h->L->Perm, sizeof(int) * h->L->n);
    return 0;
}

double pecplas_cholmod_rcond(void *handle) {
    pecplas_cholmod *h = handle;
    return h->L ? cholmod_rcond(h->L, &h->c) : 0.0;
}
int pecplas_cholmod_status(void *handle) { return ((pecplas_cholmod *)handle)->c.status; }
/* Factor column (0-based, permuted order) where factorisation stopped; n when it did not. */
int pecplas_cholmod_minor(void *handle) {
    pecplas_cholmod *h = handle;
    return h->L ? (int)h->L->minor : -1;
}
/* CHOLMOD_NATURAL 0, GIVEN 1, AMD 2, METIS 3, NESDIS 4, COLAMD 5, POSTORDERED 6. */
int pecplas_cholmod_ordering(void *handle) {
    pecplas_cholmod *h = handle;
    if (!h->L) return -1;
    return h->nodes_metis && h->L->ordering == CHOLMOD_GIVEN ? CHOLMOD_METIS : h->L->ordering;
}
/* nnz(L) and flop count of the last analysis; peak memory (bytes) since start. */
double pecplas_cholmod_lnz(void *handle) { return ((pecplas_cholmod *)handle)->c.lnz; }
double pecplas_cholmod_flops(void *handle) { return ((pecplas_cholmod *)handle)->c.fl; }
double pecplas_cholmod_peak_memory(void *handle) {
    return (double)((pecplas_cholmod *)handle)->c.memory_usage;
}
