/* OpenBLAS's kernels (pecplas_linalg_blas_core): what the library chose and a re-execution of
 * the program with OPENBLAS_CORETYPE set.
 *
 * An OpenBLAS built with DYNAMIC_ARCH picks its kernels in its library constructor, before
 * main runs, from OPENBLAS_CORETYPE or its own CPU detection; a version that does not know
 * the CPU falls back to old SSE kernels (Prescott) at half the speed. Setting the variable
 * from within the program is too late, so the program runs itself again, once, with it set:
 * execv of /proc/self/exe with the same arguments (read back from /proc/self/cmdline) and the
 * same environment plus OPENBLAS_CORETYPE and the marker PECPLAS_BLAS_CORE_FROM. The process
 * keeps its id (mpirun and batch systems see the same process). The functions are looked up
 * at run time: a BLAS other than OpenBLAS has none of them. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef char *(*text_fn)(void);

static const char *openblas_text(const char *name) {
    text_fn f = (text_fn)dlsym(RTLD_DEFAULT, name);
    const char *s = f ? f() : NULL;
    return s ? s : "";
}

/* The core whose kernels OpenBLAS uses ("Prescott", "SkylakeX", ...) into out[size], "" when
 * the BLAS is not OpenBLAS (blank-padded for Fortran). */
void pecplas_blas_core_name(char *out, int size) {
    const char *s = openblas_text("openblas_get_corename");
    int n = (int)strlen(s);
    for (int i = 0; i < size; i++) out[i] = i < n ? s[i] : ' ';
}

/* 1 when OpenBLAS was built with DYNAMIC_ARCH (OPENBLAS_CORETYPE then chooses its kernels). */
int pecplas_blas_core_dynamic(void) {
    return strstr(openblas_text("openblas_get_config"), "DYNAMIC_ARCH") != NULL;
}

/* The best OpenBLAS kernel set this CPU (and its operating system) supports: 2 for SkylakeX
 * (AVX-512 F, BW, DQ, VL with AVX2 and FMA), 1 for Haswell (AVX2 and FMA), 0 for neither. */
int pecplas_blas_core_level(void) {
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    int haswell = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    int skylakex = haswell && __builtin_cpu_supports("avx512f") &&
                   __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512vl");
    return skylakex ? 2 : (haswell ? 1 : 0);
#else
    return 0;
#endif
}

/* Runs the program again with OPENBLAS_CORETYPE=core and PECPLAS_BLAS_CORE_FROM=from.
 * Returns only when that fails (the environment is then as before): -1. */
int pecplas_blas_core_reexec(const char *core, const char *from) {
    static char buf[1 << 16];
    char *argv[1024];
    FILE *f = fopen("/proc/self/cmdline", "rb");
    if (!f) return -1;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    int complete = feof(f);
    fclose(f);
    if (n == 0 || !complete) return -1; /* arguments too long to read back: keep this run */
    buf[n] = '\0';
    int argc = 0;
    for (size_t i = 0; i < n; i += strlen(buf + i) + 1) {
        if (argc == 1023) return -1; /* more arguments than argv holds: keep this run */
        argv[argc++] = buf + i;
    }
    argv[argc] = NULL;
    if (setenv("OPENBLAS_CORETYPE", core, 1) != 0) return -1;
    if (setenv("PECPLAS_BLAS_CORE_FROM", from, 1) != 0) {
        unsetenv("OPENBLAS_CORETYPE");
        return -1;
    }
    fflush(NULL);
    execv("/proc/self/exe", argv);
    unsetenv("OPENBLAS_CORETYPE");
    unsetenv("PECPLAS_BLAS_CORE_FROM");
    return -1;
}
