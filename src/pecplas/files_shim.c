/* C side of pecplas_files: stat() and getpid(), whose types Fortran cannot declare
 * portably. No logic beyond binding.
 */
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* 1 when both paths exist and name the same file (same device and inode), else 0. */
int pecplas_same_file(const char *a, const char *b) {
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int pecplas_getpid(void) { return (int)getpid(); }
