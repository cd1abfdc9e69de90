/*
 * gw_test_calls.h: run each of a list of calls in a child process, so that a
 * call that crashes fails its own check and not the test (test_null_calls.c,
 * test_layer_null_calls.c: exported calls given NULL pointers). A call returns
 * 1 when it did what it should (refused, returned NaN, did nothing), 0 when it
 * returned without crashing but with the wrong answer.
 */
#ifndef GW_TEST_CALLS_H
#define GW_TEST_CALLS_H

#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_test.h"

typedef struct gw_test_call {
    const char *name;
    int (*call)(void);
} gw_test_call;

/* 1 when e's message holds text. */
static inline int gw_test_said(const gw_err *e, const char *text)
{
    return strstr(e->msg, text) != NULL;
}

static inline void gw_test_each_call(const gw_test_call *calls, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        fflush(stdout);
        pid_t pid = fork();
        if (pid == 0)
            _exit(calls[i].call() ? 0 : 1);
        int st = 0;
        char what[160];
        if (pid < 0 || waitpid(pid, &st, 0) != pid) {
            snprintf(what, sizeof what, "%s: the child could not be run", calls[i].name);
            gw_test_true(0, what);
            continue;
        }
        if (WIFSIGNALED(st))
            snprintf(what, sizeof what, "%s given NULL: killed by signal %d", calls[i].name, WTERMSIG(st));
        else
            snprintf(what, sizeof what, "%s given NULL: %s", calls[i].name,
                     WEXITSTATUS(st) == 0 ? "refused or nothing done, no crash" : "no crash, but the wrong value");
        gw_test_true(WIFEXITED(st) && WEXITSTATUS(st) == 0, what);
    }
}

/* Run fn(dir) in a child process killed by SIGALRM after 60 s: a crash or a
 * hang is one failed check named by name, and the parts after it still run;
 * the child's failed checks are added to this process's count. (Not a
 * timing: each part's calls return at once.) */
typedef void gw_test_part_fn(const char *dir);

static inline void gw_test_part(const char *name, gw_test_part_fn *fn, const char *dir)
{
    fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        signal(SIGALRM, SIG_DFL);
        alarm(60);
        gw_test_failures = 0; /* the parent's count is not this part's */
        fn(dir);
        fflush(stdout);
        _exit(gw_test_failures > 100 ? 100 : gw_test_failures);
    }
    int st = 0;
    if (pid < 0 || waitpid(pid, &st, 0) != pid) {
        GW_TEST_OK(0, "%s: fork or wait failed", name);
        return;
    }
    if (WIFSIGNALED(st))
        GW_TEST_OK(0, "%s: did not return within 60 s (a hang): killed by signal %d", name, WTERMSIG(st));
    else
        gw_test_failures += WEXITSTATUS(st);
}

#endif
