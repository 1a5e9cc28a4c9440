/* A stand-in for a broken driver, loaded with LD_PRELOAD: one GL entry point, named by
 * $OASIS_BROKEN_ENTRY, misbehaves as $OASIS_BROKEN_MODE says:
 *   abort       the call aborts the process (SIGABRT), as a driver's assertion would
 *   segv        the call dereferences null (SIGSEGV)
 *   hang        the call never returns
 *   noop        the call does nothing and returns (work silently not done: a wrong picture)
 *   abort-nth   aborts in the $OASIS_BROKEN_NTH-th process to call it (counted in the file
 *               $OASIS_BROKEN_COUNTER, one byte a process), works in every other: a flaky driver
 * libepoxy finds eglGetProcAddress with dlsym, and every GL entry point through it (or dlsym), so
 * interposing dlsym is enough to reach any of them. Everything else passes through unchanged. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

typedef void* (*DlsymFunction)(void*, const char*);
typedef void (*Procedure)(void);
typedef Procedure (*GetProcAddressFunction)(const char*);

static DlsymFunction realDlsym(void) {
    static DlsymFunction real;
    if (!real) real = (DlsymFunction)dlvsym(RTLD_NEXT, "dlsym", "GLIBC_2.34");
    if (!real) real = (DlsymFunction)dlvsym(RTLD_NEXT, "dlsym", "GLIBC_2.2.5");
    return real;
}

static GetProcAddressFunction realGetProcAddress;
/* The real entry point behind the broken one, which abort-nth calls where it does not abort. */
typedef void (*SixIntegers)(uintptr_t, uintptr_t, uintptr_t, uintptr_t, uintptr_t, uintptr_t);
static SixIntegers realEntry;

static int isBroken(const char* name) {
    const char* entry = getenv("OASIS_BROKEN_ENTRY");
    return name && entry && *entry && strcmp(name, entry) == 0;
}

/* Called in place of the broken entry point, whatever its arguments: on x86-64 the first six
 * integer or pointer arguments arrive in registers, so taking six and passing them on forwards a
 * void entry point such as glDispatchCompute(GLuint, GLuint, GLuint) unchanged (not one with
 * floating-point arguments). */
static void brokenEntry(uintptr_t a, uintptr_t b, uintptr_t c, uintptr_t d, uintptr_t e, uintptr_t f) {
    const char* mode = getenv("OASIS_BROKEN_MODE");
    if (!mode || strcmp(mode, "abort") == 0) abort();
    if (strcmp(mode, "segv") == 0) {
        volatile int* nowhere = NULL;
        *nowhere = 1;
    }
    if (strcmp(mode, "hang") == 0)
        for (;;) pause();
    if (strcmp(mode, "abort-nth") == 0) {
        static int counted;
        const char* counter = getenv("OASIS_BROKEN_COUNTER");
        const char* nth = getenv("OASIS_BROKEN_NTH");
        if (!counted && counter && *counter && nth) {
            counted = 1;
            int fd = open(counter, O_WRONLY | O_CREAT | O_APPEND, 0644);
            struct stat info;
            if (fd >= 0 && write(fd, "x", 1) == 1 && fstat(fd, &info) == 0 && info.st_size == atoi(nth)) abort();
            if (fd >= 0) close(fd);
        }
        if (realEntry) realEntry(a, b, c, d, e, f);
    }
    /* noop: nothing done */
}

static Procedure stoodInGetProcAddress(const char* name) {
    if (isBroken(name)) {
        if (realGetProcAddress) realEntry = (SixIntegers)realGetProcAddress(name);
        return (Procedure)brokenEntry;
    }
    return realGetProcAddress ? realGetProcAddress(name) : NULL;
}

void* dlsym(void* handle, const char* name) {
    DlsymFunction real = realDlsym();
    void* found = real ? real(handle, name) : NULL;
    if (!found || !name) return found;
    if (isBroken(name)) {
        realEntry = (SixIntegers)found;
        return (void*)brokenEntry;
    }
    if (strcmp(name, "eglGetProcAddress") == 0) {
        realGetProcAddress = (GetProcAddressFunction)found;
        return (void*)stoodInGetProcAddress;
    }
    return found;
}
