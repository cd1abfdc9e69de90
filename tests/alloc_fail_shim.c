/*
 * alloc_fail_shim.c: an LD_PRELOAD library that makes one chosen call of the C
 * library fail, to test what granwave does when its environment fails under it
 * (tests/test_alloc_failure.sh). Not linked into anything; glibc only.
 *
 * Environment:
 *   GW_FAIL_ALLOC=K   the K-th call (from 1, counted from the start of main, every
 *                     thread) to malloc, calloc, realloc, posix_memalign, aligned_alloc,
 *                     memalign or valloc returns NULL with errno ENOMEM. Calls
 *                     made inside glibc (strdup, fopen, printf's buffers) count
 *                     too: glibc calls malloc through its own interposable symbol.
 *                     One call fails; the calls after it succeed again.
 *   GW_FAIL_IO=NAME:K the K-th call to NAME fails: fopen (NULL, errno EIO),
 *                     fwrite (0 items, the stream's error flag set, errno ENOSPC),
 *                     fflush, fclose (EOF, errno EIO; fclose still closes the
 *                     stream, as a failed close does), rename, fsync (-1, EIO),
 *                     link (-1, EPERM, as where no hard link can be made).
 *   GW_FAIL_LINK_ALL=1 every link fails (EPERM): a file system without hard
 *                     links, or Linux's protected_hardlinks for another's file.
 *   GW_FAIL_WHO=FILE  at the failing call, write to FILE the file name of the
 *                     library (or program) that asked: the first frame of the
 *                     call's stack outside this shim and the C library (so a
 *                     test can tell a failure inside FFTW, HDF5 or SUNDIALS).
 *   GW_FAIL_COUNT=FILE at exit, append one line "alloc N fopen N fwrite N fflush N
 *                     fclose N rename N fsync N link N" (the calls made) to FILE, so a
 *                     test can learn a run's counts before sweeping K over them.
 *
 * The real allocator is reached through glibc's __libc_* entry points (no dlsym
 * for malloc, which itself allocates); the stdio and file calls through dlsym.
 * Counting starts when main is entered (the shim wraps __libc_start_main): the
 * libraries' constructors before it (OpenMPI, HDF5, the loader's own) are not
 * granwave's code and are never made to fail.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <execinfo.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void *__libc_memalign(size_t, size_t);

enum { F_ALLOC, F_FOPEN, F_FWRITE, F_FFLUSH, F_FCLOSE, F_RENAME, F_FSYNC, F_LINK, F_N };
static const char *const names[F_N] = {"alloc",  "fopen",  "fwrite", "fflush",
                                       "fclose", "rename", "fsync",  "link"};

/* The shim's own state: process-wide by nature (one preload per process). */
static atomic_long calls[F_N];
static long fail_at[F_N]; /* 0: never */
static atomic_int ready;  /* the environment has been read */
static atomic_int started; /* main has been entered: count from here */
static int no_links;       /* GW_FAIL_LINK_ALL: every link fails */

static long env_long(const char *s)
{
    char *end;
    long v = strtol(s, &end, 10);
    return end != s && *end == '\0' && v > 0 ? v : 0;
}

/* Read the environment once. getenv does not allocate, so this is safe from
 * inside the first malloc. */
static void setup(void)
{
    if (atomic_load(&ready))
        return;
    const char *a = getenv("GW_FAIL_ALLOC");
    if (a)
        fail_at[F_ALLOC] = env_long(a);
    const char *io = getenv("GW_FAIL_IO");
    if (io) {
        const char *colon = strchr(io, ':');
        for (int i = 1; colon && i < F_N; i++)
            if ((size_t)(colon - io) == strlen(names[i]) && !strncmp(io, names[i], (size_t)(colon - io)))
                fail_at[i] = env_long(colon + 1);
    }
    no_links = getenv("GW_FAIL_LINK_ALL") != NULL;
    atomic_store(&ready, 1);
}

/* Called at the failing call: a breakpoint for a debugger (gdb -ex 'break
 * alloc_fail_here') to see who asked. */
__attribute__((noinline)) void alloc_fail_here(int kind);
__attribute__((noinline)) void alloc_fail_here(int kind)
{
    __asm__ volatile("" ::"r"(kind) : "memory");
}

/* GW_FAIL_WHO: the caller's object, written with write(2) (no allocation of
 * ours: backtrace may allocate once, which this failing call does not see). */
static void record_who(void)
{
    const char *path = getenv("GW_FAIL_WHO");
    if (!path)
        return;
    void *frames[32];
    int n = backtrace(frames, 32);
    Dl_info self, libc, d;
    /* frames[0] is in this shim; stdout points into the C library's data */
    if (n < 1 || !dladdr(frames[0], &self) || !dladdr(stdout, &libc))
        return;
    const char *who = "?";
    for (int i = 1; i < n; i++)
        if (dladdr(frames[i], &d) && d.dli_fbase != self.dli_fbase && d.dli_fbase != libc.dli_fbase) {
            who = d.dli_fname;
            break;
        }
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ssize_t w = write(fd, who, strlen(who));
        (void)w;
        close(fd);
    }
}

/* 1 when this call of kind k is the one to fail. */
static int hit(int k)
{
    if (!atomic_load(&started))
        return 0;
    setup();
    long n = atomic_fetch_add(&calls[k], 1) + 1;
    if (fail_at[k] && n == fail_at[k]) {
        alloc_fail_here(k);
        record_who();
        return 1;
    }
    return 0;
}

void *malloc(size_t n)
{
    if (hit(F_ALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_malloc(n);
}

void *calloc(size_t a, size_t b)
{
    if (hit(F_ALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_calloc(a, b);
}

void *realloc(void *p, size_t n)
{
    if (hit(F_ALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_realloc(p, n);
}

void *memalign(size_t align, size_t n)
{
    if (hit(F_ALLOC)) {
        errno = ENOMEM;
        return NULL;
    }
    return __libc_memalign(align, n);
}

void *aligned_alloc(size_t align, size_t n)
{
    return memalign(align, n);
}

void *valloc(size_t n)
{
    return memalign((size_t)sysconf(_SC_PAGESIZE), n);
}

int posix_memalign(void **out, size_t align, size_t n)
{
    if (align < sizeof(void *) || (align & (align - 1)))
        return EINVAL;
    void *p = memalign(align, n);
    if (!p)
        return ENOMEM;
    *out = p;
    return 0;
}

/* The next definition of a function: dlsym's object pointer copied into a
 * function pointer, as POSIX allows and ISO C has no cast for. */
typedef FILE *open_fn(const char *, const char *);
typedef size_t write_fn(const void *, size_t, size_t, FILE *);
typedef int stream_fn(FILE *);
typedef int rename_fn(const char *, const char *);
typedef int fd_fn(int);
#define REAL(var, type, name)                                                                      \
    type *var;                                                                                     \
    do {                                                                                           \
        void *sym_ = dlsym(RTLD_NEXT, name);                                                       \
        memcpy(&var, &sym_, sizeof var);                                                           \
    } while (0)

FILE *fopen(const char *path, const char *mode)
{
    if (hit(F_FOPEN)) {
        errno = EIO;
        return NULL;
    }
    REAL(real, open_fn, "fopen");
    return real(path, mode);
}

FILE *fopen64(const char *path, const char *mode)
{
    if (hit(F_FOPEN)) {
        errno = EIO;
        return NULL;
    }
    REAL(real, open_fn, "fopen64");
    return real(path, mode);
}

size_t fwrite(const void *p, size_t size, size_t n, FILE *f)
{
    if (hit(F_FWRITE)) {
        f->_flags |= _IO_ERR_SEEN; /* what ferror reads: the stream has failed */
        errno = ENOSPC;
        return 0;
    }
    REAL(real, write_fn, "fwrite");
    return real(p, size, n, f);
}

int fflush(FILE *f)
{
    if (f && hit(F_FFLUSH)) {
        f->_flags |= _IO_ERR_SEEN;
        errno = EIO;
        return EOF;
    }
    REAL(real, stream_fn, "fflush");
    return real(f);
}

int fclose(FILE *f)
{
    int fail = hit(F_FCLOSE);
    REAL(real, stream_fn, "fclose");
    int rc = real(f);
    if (fail) {
        errno = EIO;
        return EOF;
    }
    return rc;
}

int rename(const char *from, const char *to)
{
    if (hit(F_RENAME)) {
        errno = EIO;
        return -1;
    }
    REAL(real, rename_fn, "rename");
    return real(from, to);
}

int link(const char *from, const char *to)
{
    if (hit(F_LINK) || (no_links && atomic_load(&started))) { /* as a file system without hard links */
        errno = EPERM;
        return -1;
    }
    REAL(real, rename_fn, "link");
    return real(from, to);
}

int fsync(int fd)
{
    if (hit(F_FSYNC)) {
        errno = EIO;
        return -1;
    }
    REAL(real, fd_fn, "fsync");
    return real(fd);
}

/* glibc's entry to main, wrapped to start counting there. */
typedef int main_fn(int, char **, char **);
typedef int start_fn(main_fn *, int, char **, void (*)(void), void (*)(void), void (*)(void), void *);
static main_fn *real_main;

static int counted_main(int argc, char **argv, char **envp)
{
    atomic_store(&started, 1);
    return real_main(argc, argv, envp);
}

int __libc_start_main(main_fn *main, int argc, char **argv, void (*init)(void), void (*fini)(void),
                      void (*rtld_fini)(void), void *stack_end)
{
    REAL(real, start_fn, "__libc_start_main");
    real_main = main;
    return real(counted_main, argc, argv, init, fini, rtld_fini, stack_end);
}

/* Report the counts at exit (also after exit(), not after a signal). */
__attribute__((destructor)) static void report(void)
{
    const char *path = getenv("GW_FAIL_COUNT");
    if (!path)
        return;
    char line[256];
    int len = 0;
    for (int i = 0; i < F_N; i++)
        len += snprintf(line + len, sizeof line - (size_t)len, "%s%s %ld", i ? " " : "", names[i],
                        atomic_load(&calls[i]));
    snprintf(line + len, sizeof line - (size_t)len, "\n");
    REAL(real_open, open_fn, "fopen");
    REAL(real_close, stream_fn, "fclose");
    FILE *f = real_open(path, "a");
    if (f) {
        fputs(line, f);
        real_close(f);
    }
}
