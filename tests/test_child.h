/* test_child.h: one case of a C test run in a forked child, for the tests that
 * call the library with input that may crash it (test_hostile_api,
 * test_library_hostile). A crash, an abort or a sanitizer's report then fails
 * that case alone, and the test goes on to the next. */
#ifndef GW_TEST_CHILD_H
#define GW_TEST_CHILD_H

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "granwave.h"

typedef int (*case_fn)(void);

/* child_run: BODY in a child with stdout and stderr into a file and 120 s of
 * alarm; *ST gets its wait status (exit 0 when BODY returned 0) and BUF
 * (N > 0 bytes) what it printed. -1 when no child could be made. */
static inline int child_run(case_fn body, int *st, char *buf, size_t n)
{
    char out[] = "/tmp/gw_test_child.XXXXXX";
    int fd = mkstemp(out);
    buf[0] = '\0';
    if (fd < 0)
        return -1;
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        alarm(120);
        int rc = body();
        fflush(stdout);
        exit(rc == 0 ? 0 : 1); /* exit, not _exit: LeakSanitizer checks the child */
    }
    *st = 0;
    if (pid > 0)
        waitpid(pid, st, 0);
    ssize_t got = pid > 0 ? pread(fd, buf, n - 1, 0) : 0;
    buf[got > 0 ? got : 0] = '\0';
    close(fd);
    unlink(out);
    return pid > 0 ? 0 : -1;
}

/* child_case: BODY as one case of a test (child_run), counted in *NCASES,
 * and in *NFAIL with a FAIL line on stdout naming LABEL when it crashed,
 * exited non-zero or printed anything (the library prints nothing). */
static inline void child_case(const char *label, case_fn body, int *nfail, int *ncases)
{
    int st = 0;
    char buf[2048];
    ++*ncases;
    if (child_run(body, &st, buf, sizeof buf) != 0) {
        ++*nfail;
        printf("FAIL: %s: no child (mkstemp or fork)\n", label);
        return;
    }
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0 || buf[0]) {
        ++*nfail;
        if (WIFSIGNALED(st))
            printf("FAIL: %s: killed by signal %d (%s)\n", label, WTERMSIG(st), buf);
        else
            printf("FAIL: %s: exit %d, printed \"%s\"\n", label, WEXITSTATUS(st), buf);
    }
}

/* A table of cases: each runs in its own child (child_case: 120 s, as the
 * sanitizer build is ~10x slower) and passes when it returns 0 and prints
 * nothing (the library prints nothing; a body prints only why it failed). The
 * test's main is then child_cases_run(TABLE, count), which prints the tally
 * and gives the test's exit status. */
typedef struct child_row {
    const char *label;
    case_fn fn;
} child_row;

/* child_casef: child_case with its label made as printf makes it (a table's
 * rows run over one body, a row chosen before each, or one body over a
 * table of calls: "ROW: CALL") */
static inline void child_casef(case_fn body, int *nfail, int *ncases, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static inline void child_casef(case_fn body, int *nfail, int *ncases, const char *fmt, ...)
{
    char label[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(label, sizeof label, fmt, ap);
    va_end(ap);
    child_case(label, body, nfail, ncases);
}

/* The tally of a test's cases and its exit status. */
static inline int child_cases_end(int nfail, int ncases)
{
    printf("%d of %d cases failed\n", nfail, ncases);
    return nfail ? 1 : 0;
}

static inline int child_cases_run(const child_row *rows, size_t n)
{
    int nfail = 0, ncases = 0;
    for (size_t k = 0; k < n; k++)
        child_case(rows[k].label, rows[k].fn, &nfail, &ncases);
    return child_cases_end(nfail, ncases);
}

/* In a child: report a failed expectation on stdout (which fails the case). */
#define EXPECT(cond)                                                                                  \
    do {                                                                                              \
        if (!(cond)) {                                                                                \
            printf("%s:%d: expected %s\n", __FILE__, __LINE__, #cond);                               \
            return 1;                                                                                 \
        }                                                                                             \
    } while (0)

/* A refusal: GW_EINVAL and one line that contains WHAT (the argument named);
 * else says what came, on stdout (which fails the case). */
static inline int refused(int rc, const gw_err *e, const char *what)
{
    if (rc != GW_EINVAL || !strstr(e->msg, what) || strchr(e->msg, '\n')) {
        printf("status %d, message '%s' (wanted GW_EINVAL naming '%s')\n", rc, e->msg, what);
        return 0;
    }
    return 1;
}

#endif
