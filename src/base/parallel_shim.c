/* MPI for pecplas_base_parallel, in C so that no Fortran module depends on an MPI module.
 * Only the MPI build (CMake -DPECPLAS_MPI=ON, `make build-mpi`) defines PECPLAS_MPI; the
 * default serial build compiles the stubs below: one rank, nothing to communicate.
 */
#include <stdio.h>
#ifdef PECPLAS_MPI
#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>
#endif

/* 1 when this build has MPI (and MUMPS), 0 otherwise. */
int pecplas_parallel_built(void) {
#ifdef PECPLAS_MPI
    return 1;
#else
    return 0;
#endif
}

/* Starts MPI when needed. Ranks other than 0 print nothing: their stdout goes to /dev/null
 * (the Fortran runtime writes to file descriptor 1, so dup2 silences it too); stderr stays,
 * so a rank that fails alone still says why. */
void pecplas_parallel_init(void) {
#ifdef PECPLAS_MPI
    int started = 0, rank = 0;
    MPI_Initialized(&started);
    if (!started) MPI_Init(NULL, NULL);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank > 0) {
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) {
            fflush(stdout);
            dup2(fd, 1);
            close(fd);
        }
    }
#endif
}

void pecplas_parallel_finalize(void) {
#ifdef PECPLAS_MPI
    int started = 0, done = 0;
    MPI_Initialized(&started);
    MPI_Finalized(&done);
    if (started && !done) MPI_Finalize();
#endif
}

int pecplas_parallel_rank(void) {
#ifdef PECPLAS_MPI
    int started = 0, rank = 0;
    MPI_Initialized(&started);
    if (started) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
#else
    return 0;
#endif
}

int pecplas_parallel_size(void) {
#ifdef PECPLAS_MPI
    int started = 0, size = 1;
    MPI_Initialized(&started);
    if (started) MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
#else
    return 1;
#endif
}

#ifdef PECPLAS_MPI
/* True when MPI runs with more than one rank (collectives are needed). */
static int several(void) {
    int started = 0, done = 0, size = 1;
    MPI_Initialized(&started);
    MPI_Finalized(&done);
    if (!started || done) return 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size > 1;
}
#endif

/* x(1:n) = its sum (op 0), minimum (op 1) or maximum (op 2) over the ranks, on every rank. */
void pecplas_parallel_reduce(double *x, int n, int op) {
#ifdef PECPLAS_MPI
    if (!several() || n < 1) return;
    MPI_Op mop = op == 1 ? MPI_MIN : (op == 2 ? MPI_MAX : MPI_SUM);
    MPI_Allreduce(MPI_IN_PLACE, x, n, MPI_DOUBLE, mop, MPI_COMM_WORLD);
#else
    (void)x;
    (void)n;
    (void)op;
#endif
}

/* The largest of `value` over the ranks, on every rank. */
int pecplas_parallel_max_int(int value) {
#ifdef PECPLAS_MPI
    if (!several()) return value;
    int out = value;
    MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out;
#else
    return value;
#endif
}
