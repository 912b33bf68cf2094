/* Build provenance for `pecplas --version`: the commit the binary was built from and the
 * SuiteSparse versions it was compiled against (the library headers' version macros; the
 * linked CHOLMOD is also asked at run time through cholmod_version).
 *
 * The commit comes from a generated header: CMake passes its path as PECPLAS_COMMIT_HEADER
 * (written at every build by cmake/BuildInfo.cmake), the Makefile writes provenance_commit.h next to
 * this file (tools/build_info.sh, git-ignored). Without either -- a plain `fpm build` outside
 * the Makefile, or a source tarball -- the commit is "unknown".
 */
#include <string.h>
#if defined(__has_include)
#if __has_include(<suitesparse/cholmod.h>)
#include <suitesparse/cholmod.h>
#include <suitesparse/umfpack.h>
#else
#include <cholmod.h>
#include <umfpack.h>
#endif
#else
#include <cholmod.h>
#include <umfpack.h>
#endif

#if defined(PECPLAS_COMMIT_HEADER)
#include PECPLAS_COMMIT_HEADER
#elif defined(__has_include)
#if __has_include("provenance_commit.h")
#include "provenance_commit.h"
#endif
#endif
#ifndef PECPLAS_COMMIT
#define PECPLAS_COMMIT "unknown"
#endif

/* Copies the commit string into buf (at most n bytes, NUL-terminated); returns its length. */
int pecplas_build_commit(char *buf, int n) {
    const char *s = PECPLAS_COMMIT;
    int len = (int)strlen(s);
    if (n <= 0) return 0;
    if (len > n - 1) len = n - 1;
    memcpy(buf, s, (size_t)len);
    buf[len] = '\0';
    return len;
}

/* Compile-time versions: v[0..2] CHOLMOD, v[3..5] UMFPACK, v[6..8] SuiteSparse;
 * v[9..11] the CHOLMOD library linked at run time. */
void pecplas_suitesparse_versions(int v[12]) {
    int linked[3] = {0, 0, 0};
    v[0] = CHOLMOD_MAIN_VERSION;
    v[1] = CHOLMOD_SUB_VERSION;
    v[2] = CHOLMOD_SUBSUB_VERSION;
    v[3] = UMFPACK_MAIN_VERSION;
    v[4] = UMFPACK_SUB_VERSION;
    v[5] = UMFPACK_SUBSUB_VERSION;
#if defined(SUITESPARSE_MAIN_VERSION)
    v[6] = SUITESPARSE_MAIN_VERSION;
    v[7] = SUITESPARSE_SUB_VERSION;
    v[8] = SUITESPARSE_SUBSUB_VERSION;
#else
    v[6] = v[7] = v[8] = 0;
#endif
    cholmod_version(linked);
    v[9] = linked[0];
    v[10] = linked[1];
    v[11] = linked[2];
}
