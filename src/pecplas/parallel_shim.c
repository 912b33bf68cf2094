/* MPI for pecplas_parallel, in C so that no Fortran module depends on an MPI module.
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
