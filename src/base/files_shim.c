/* C side of pecplas_base_files: stat() and getpid(), whose types Fortran cannot declare
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

#include <stdio.h>
#include <sys/statvfs.h>

/* Bytes an unprivileged process may still write in the file system holding `path`
 * (a file or directory), or -1 when unknown. */
long long pecplas_free_bytes(const char *path) {
    struct statvfs s;
    if (statvfs(path, &s) != 0) return -1;
    return (long long)s.f_bavail * (long long)s.f_frsize;
}

/* Ends the process at once with `code`, without the exit handlers of the libraries (the
 * HDF5 library's handler crashes on a file it could not flush). */
void pecplas_exit_now(int code) {
    fflush(NULL);
    _exit(code);
}
