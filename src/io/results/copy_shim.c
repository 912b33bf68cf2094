/* C side of pecplas_io_results_kernel_copy: a whole-file copy made by the kernel
 * (copy_file_range), which the Fortran and HDF5 APIs do not offer. No logic beyond the
 * copy loop and its clean-up.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* Copies the file `from` to a new file `to` (which must not exist) with copy_file_range.
 * Returns 0 on success; -1 when the kernel or the file system refuses (no such system
 * call, another file system, ...) or on any other failure, `to` then removed, so that the
 * caller writes the copy itself. */
int pecplas_kernel_copy(const char *from, const char *to) {
#ifdef __linux__
    struct stat st;
    int in = open(from, O_RDONLY | O_CLOEXEC);
    if (in < 0) return -1;
    if (fstat(in, &st) != 0) {
        close(in);
        return -1;
    }
    int out = open(to, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, st.st_mode & 0777);
    if (out < 0) {
        close(in);
        return -1;
    }
    off_t left = st.st_size;
    int ok = 1;
    while (left > 0) {
        ssize_t n = copy_file_range(in, NULL, out, NULL, (size_t)left, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = 0;
            break;
        }
        left -= n;
    }
    close(in);
    if (close(out) != 0) ok = 0;
    if (!ok) {
        unlink(to);
        return -1;
    }
    return 0;
#else
    (void)from;
    (void)to;
    return -1;
#endif
}
