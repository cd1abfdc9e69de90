/*
 * granwave.c: the `granwave <command>` program. Each command lives with its
 * module; this file only dispatches, and checks that stdout was written (exit
 * 1 otherwise). Exit codes: 0 ok, 1 run failure (solver, output), 2 bad input
 * (one line on stderr naming the input).
 */
#include <errno.h>
#include <signal.h>
#include <sys/resource.h>
#include <stdio.h>
#include <string.h>

#include "gw_chain.h"
#include "chain_commands.h"
#include "sweep_cmd.h"
#if GW_HAVE_LAYER
#include "gw_layer.h"
#include "layer_commands.h"
#endif

static int cmd_sweep(int argc, char **argv)
{
    const gw_sweep_model *const models[] = {
        &gw_chain_sweep_model,
#if GW_HAVE_LAYER && defined(GW_LAYER_SWEEP_MODEL)
        &GW_LAYER_SWEEP_MODEL,
#endif
    };
    return gw_cmd_sweep(argc, argv, models, (int)(sizeof models / sizeof models[0]));
}

typedef struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command;

static const command commands[] = {
    {"chain", gw_cmd_chain, "one collision of a bead column with a wall"},
    {"falcon", gw_cmd_falcon, "the Falcon et al. (1998) rigid-wall study (main job)"},
    {"dispersion", gw_cmd_dispersion, "small-amplitude dispersion of a precompressed chain (FFTW)"},
    {"wavespeed", gw_cmd_wavespeed, "deformation-wave speed against v_imp, three estimators"},
    {"softwall", gw_cmd_softwall, "soft walls: F_max(N), saturation number N_d, sheets"},
    {"drop", gw_cmd_drop, "the whole drop: a column released above the sensor, its bounces over 10 ms"},
    {"sweep", cmd_sweep, "a grid of cases from a config file (resumable; threads or MPI)"},
#if GW_HAVE_LAYER
    GW_LAYER_COMMANDS
#endif
};

#define GW_STACK_MIN (256 * 1024)

static void usage(FILE *fp)
{
    fprintf(fp, "granwave %s: wave propagation in granular matter (ODE systems, SUNDIALS)\n\n"
                "usage: granwave <command> [options]   (granwave <command> --help)\n\ncommands:\n",
            gw_version());
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(fp, "  %-14s %s\n", commands[i].name, commands[i].summary);
    fprintf(fp, "  %-14s %s\n", "version", "print the version");
}

/* One check for every command and for --help and --version: output that did
 * not reach stdout (a full disk, /dev/full, a closed pipe or descriptor) is a
 * run failure, never exit 0. */
static int stdout_checked(const char *cmd, int code)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        int e = errno ? errno : EIO;
        fprintf(stderr, "granwave%s%s: stdout: write failed: %s\n", cmd ? " " : "", cmd ? cmd : "", strerror(e));
        if (code == 0)
            code = 1;
    }
    return code;
}

int main(int argc, char **argv)
{
    /* Past a file-size limit (ulimit -f), a write fails with EFBIG instead of
     * SIGXFSZ killing the program with its temporaries left: the output set
     * then removes them and says which file (Python ignores SIGXFSZ already) */
    signal(SIGXFSZ, SIG_IGN);
    /* A stack limit far below the usual 8 MiB (ulimit -s 64) overflowed in
     * layer-impact --out (SIGSEGV): the main thread's and, through glibc's
     * default, the worker threads' stacks. Measured to run every command from
     * 96 KiB; refused below 256 KiB before anything is done. */
    struct rlimit rl;
    if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < GW_STACK_MIN) {
        fprintf(stderr, "granwave: the stack limit (ulimit -s %lu KiB) is below the %d KiB granwave needs; "
                        "raise it (ulimit -s 8192)\n", (unsigned long)(rl.rlim_cur / 1024), GW_STACK_MIN / 1024);
        return 2;
    }
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    const char *cmd = argv[1];
    int help = strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0;
    int version = strcmp(cmd, "version") == 0 || strcmp(cmd, "--version") == 0;
    /* `granwave help CMD` is `granwave CMD --help`; anything else after help or
     * version is refused (it was ignored: `help chain` printed the command list) */
    if ((help && argc > 3) || (version && argc > 2)) {
        gw_err e;
        gw_err_set(&e, GW_EINVAL, "unexpected argument '%s' after %s (see granwave --help)", argv[help ? 3 : 2], cmd);
        fprintf(stderr, "granwave: %s\n", e.msg);
        return 2;
    }
    if (help && argc == 2) {
        usage(stdout);
        return stdout_checked(NULL, 0);
    }
    if (version) {
        printf("granwave %s\n", gw_version());
        return stdout_checked(NULL, 0);
    }
    if (help)
        cmd = argv[2];
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(commands[i].name, cmd) == 0) {
            char *help_argv[] = {"--help", NULL};
            int code = help ? commands[i].run(1, help_argv) : commands[i].run(argc - 2, argv + 2);
            return stdout_checked(cmd, code);
        }
    gw_err e; /* through gw_err_set: a control character in the name is escaped, one line */
    gw_err_set(&e, GW_EINVAL, "unknown command '%s' (see granwave --help)", cmd);
    fprintf(stderr, "granwave: %s\n", e.msg);
    return 2;
}
