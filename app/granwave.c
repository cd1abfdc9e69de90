/*
 * granwave.c: the `granwave <command>` program. Each command lives with its
 * module; this file only dispatches, and checks that stdout was written (exit
 * 1 otherwise). Exit codes: 0 ok, 1 run failure (solver, output), 2 bad input
 * (one line on stderr naming the input).
 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <cjson/cJSON.h>
#include <fftw3.h>
#include <gsl/gsl_version.h>
#include <sundials/sundials_version.h>

#include "gw_cli.h"
#include "gw_common.h"
#include "gw_version.h"
#if GW_HAVE_HDF5
#include <hdf5.h>
#endif

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
    const gw_sweep_run_part_fn parts[] = {
        gw_chain_sweep_run_part,
#if GW_HAVE_LAYER && defined(GW_LAYER_SWEEP_MODEL)
        gw_layer_sweep_run_part,
#endif
    };
    const gw_sweep_weigh *const weighs[] = {
        &gw_chain_sweep_weigh,
#if GW_HAVE_LAYER && defined(GW_LAYER_SWEEP_MODEL)
        &gw_layer_sweep_weigh,
#endif
    };
    return gw_cmd_sweep(argc, argv, models, parts, weighs, (int)(sizeof models / sizeof models[0]));
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
    fprintf(fp, "  %-14s %s\n", "version", "print the version (--json: also the libraries', as loaded)");
    fprintf(fp, "  %-14s %s\n", "help", "this list; help COMMAND: that command's options");
}

/* One check for every command and for --help and --version: output that did
 * not reach stdout (a full disk, /dev/full, a closed pipe or descriptor) is a
 * run failure, never exit 0. */
static int stdout_checked(const char *cmd, int code)
{
    errno = 0;
    if ((fflush(stdout) != 0 || ferror(stdout)) && gw_cli_stdout_failed(cmd, errno) != 0 && code == 0)
        code = 1;
    return code;
}

static const command *find_command(const char *name)
{
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (strcmp(commands[i].name, name) == 0)
            return &commands[i];
    return NULL;
}

/* a refusal of the top level's own arguments: one line, exit 2 */
static int refuse(const char *what, const char *fmt, const char *arg)
{
    gw_err e; /* through gw_err_set: a control character in arg is escaped, one line */
    gw_err_set(&e, GW_EINVAL, fmt, arg);
    fprintf(stderr, "granwave%s%s: %s\n", what ? " " : "", what ? what : "", e.msg);
    return 2;
}

/* The own --help of the two top-level commands, as every command has one
 * (`granwave version --help` and `granwave help --help` exited 2, "unexpected
 * argument" / "unknown command '--help'"); `help version` and `help help`
 * print the same, as `help COMMAND` is `COMMAND --help` for every command.
 * Both through gw_cli_help from an option table, so that --json with --help
 * prints it as JSON, as every command's. */
static int json_flag; /* the tables' dest: read by nobody, the parse is by hand */

static int version_usage(int help)
{
    gw_opt opts[] = {{.name = "json", .kind = GW_OPT_FLAG, .dest = &json_flag,
                      .help = "one JSON object with the version and those of the libraries as loaded at run time "
                              "(sundials, gsl, fftw, cjson, hdf5; null without HDF5)"},
                     {0}};
    return stdout_checked(NULL, gw_cli_help(stdout, "version", "granwave version [--json]",
                                            "Print the program's version.", opts, help));
}

static int help_usage(int help)
{
    gw_opt opts[] = {{.name = "json", .kind = GW_OPT_FLAG, .dest = &json_flag,
                      .help = "with COMMAND: that command's options as JSON (COMMAND --help --json); without: the "
                              "list of commands as JSON"},
                     {0}};
    return stdout_checked(NULL, gw_cli_help(stdout, "help", "granwave help [COMMAND] [--json]",
                                            "Without COMMAND the list of commands (as granwave --help); with COMMAND "
                                            "that\ncommand's options, as granwave COMMAND --help.", opts, help));
}

/* granwave --help --json: the commands as JSON, those of usage() */
static int usage_json(void)
{
    cJSON *o = cJSON_CreateObject(), *list = NULL;
    int ok = o && cJSON_AddStringToObject(o, "program", "granwave") &&
             cJSON_AddStringToObject(o, "version", gw_version()) &&
             cJSON_AddStringToObject(o, "usage", "granwave <command> [options]") &&
             (list = cJSON_AddArrayToObject(o, "commands")) != NULL;
    const command top[] = {{"version", NULL, "print the version (--json: also the libraries', as loaded)"},
                           {"help", NULL, "this list; help COMMAND: that command's options"}};
    const size_t nc = sizeof commands / sizeof commands[0];
    for (size_t i = 0; ok && i < nc + 2; i++) {
        const command *c = i < nc ? &commands[i] : &top[i - nc];
        cJSON *e = cJSON_CreateObject();
        ok = e && cJSON_AddItemToArray(list, e) && cJSON_AddStringToObject(e, "name", c->name) &&
             cJSON_AddStringToObject(e, "summary", c->summary);
    }
    const int code = gw_cli_json_stdout(NULL, ok ? o : NULL);
    cJSON_Delete(o);
    return stdout_checked(NULL, code);
}

static int is_help_flag(const char *a)
{
    return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0;
}

/* granwave help [COMMAND] (also --help, -h): the list, or the command's own
 * --help; anything more is refused, never ignored */
static int help(int argc, char **argv)
{
    /* --json anywhere but after "--": that help as JSON (taken out of argv) */
    int json = 0;
    for (int i = 2; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--json") == 0 && !json) {
            json = GW_CLI_HELP_JSON;
            memmove(argv + i, argv + i + 1, (size_t)(argc - i) * sizeof *argv); /* argv[argc] (NULL) too */
            argc--;
            break;
        }
    /* a second --json was taken for a command ("unknown command '--json'"):
     * said as every command says a flag given twice */
    for (int i = 2; json && i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--json") == 0)
            return refuse(argv[1], "%s: given twice", "--json");
    int ended = argc > 2 && strcmp(argv[2], "--") == 0; /* "help -- COMMAND": COMMAND is no flag */
    if (ended) {
        argv[2] = argv[1];
        argv++;
        argc--;
    }
    if (argc > 3)
        return refuse(argv[1], "unexpected argument '%s' (usage: granwave help [COMMAND] [--json])", argv[3]);
    if (argc == 3) {
        const command *c = find_command(argv[2]);
        if (!c && strcmp(argv[2], "version") == 0)
            return version_usage(json ? json : 1);
        if (!c && (strcmp(argv[2], "help") == 0 || (!ended && is_help_flag(argv[2]))))
            return help_usage(json ? json : 1);
        if (!c)
            return refuse(argv[1], "unknown command '%s' (see granwave --help)", argv[2]);
        char *h[] = {"--help", "--json", NULL};
        return stdout_checked(c->name, c->run(json ? 2 : 1, h));
    }
    if (json)
        return usage_json();
    usage(stdout);
    return stdout_checked(NULL, 0);
}

/* granwave version [--json]: the JSON adds the libraries' versions as loaded
 * at run time (the provenance a bug report or a paper's methods needs) */
static int version(int argc, char **argv)
{
    int json = 0, want_help = 0, ended = 0;
    for (int i = 2; i < argc; i++) {
        if (!ended && strcmp(argv[i], "--") == 0) { /* the end of the options: nothing may follow */
            ended = 1;
            continue;
        }
        if (!ended && is_help_flag(argv[i])) { /* as a command's --help among its flags */
            want_help = 1;
            continue;
        }
        if (ended || strcmp(argv[i], "--json") != 0)
            return refuse(argv[1], "unexpected argument '%s' (usage: granwave version [--json])", argv[i]);
        if (json)
            return refuse(argv[1], "%s: given twice", argv[i]);
        json = 1;
    }
    if (want_help)
        return version_usage(json ? GW_CLI_HELP_JSON : 1);
    if (!json) {
        printf("granwave %s\n", gw_version());
        return stdout_checked(NULL, 0);
    }
    char sun[64] = "";
    if (SUNDIALSGetVersion(sun, (int)sizeof sun) != 0)
        sun[0] = '\0';
    cJSON *o = cJSON_CreateObject();
    int ok = o && cJSON_AddStringToObject(o, "version", gw_version()) &&
             cJSON_AddStringToObject(o, "sundials", sun) && cJSON_AddStringToObject(o, "gsl", gsl_version) &&
             cJSON_AddStringToObject(o, "fftw", fftw_version) && cJSON_AddStringToObject(o, "cjson", cJSON_Version());
#if GW_HAVE_HDF5
    unsigned maj = 0, min = 0, rel = 0;
    char h5[48];
    if (H5get_libversion(&maj, &min, &rel) < 0)
        h5[0] = '\0';
    else
        snprintf(h5, sizeof h5, "%u.%u.%u", maj, min, rel);
    ok = ok && cJSON_AddStringToObject(o, "hdf5", h5);
#else
    ok = ok && cJSON_AddNullToObject(o, "hdf5");
#endif
    if (!ok) {
        cJSON_Delete(o);
        fprintf(stderr, "granwave version: out of memory\n");
        return 1;
    }
    const int rc = gw_json_print(o, stdout);
    const int e = errno; /* the failed write's (gw_json_print) */
    cJSON_Delete(o);
    if (rc == GW_ENOMEM) {
        fprintf(stderr, "granwave version: out of memory\n");
        return 1;
    }
    if (rc == GW_EIO) /* said with its errno: the flush emptied the buffer */
        return gw_cli_stdout_failed(NULL, e);
    return stdout_checked(NULL, 0);
}

/* A standard descriptor closed by the caller (granwave sweep C >&- 2>&-) was
 * the lowest free number, so the first file the run opened took it: the
 * sweep's journal became descriptor 2 and took its progress lines ("sweep:
 * 2/4 cases, ..."), and the next run refused the journal as edited by hand;
 * a file opened as 1 would take what is printed. Each closed one is held
 * here by /dev/null opened read-only: a write to it still fails with EBADF,
 * so a lost stdout ends the run with exit 1 as before, and reading gives
 * end of file. Without /dev/null the program refuses to run (exit 2, one
 * line where stderr is open). */
static int hold_std_fds(void)
{
    for (int fd = 0; fd <= 2; fd++) {
        if (fcntl(fd, F_GETFD) != -1 || errno != EBADF)
            continue;
        int nd = open("/dev/null", O_RDONLY);
        if (nd != fd) {
            const int e = nd < 0 ? errno : EBADF;
            if (nd >= 0)
                close(nd);
            /* said where stderr is open (it may be the closed one) */
            fprintf(stderr, "granwave: descriptor %d (standard %s) is closed and /dev/null cannot hold it: %s\n", fd,
                    fd == 0 ? "input" : fd == 1 ? "output" : "error", strerror(e));
            return -1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (hold_std_fds() != 0)
        return 2;
    /* Past a file-size limit (ulimit -f), a write fails with EFBIG instead of
     * SIGXFSZ killing the program with its temporaries left: the output set
     * then removes them and says which file (Python ignores SIGXFSZ already) */
    signal(SIGXFSZ, SIG_IGN);
    /* A reader that leaves early (granwave sweep ... 2>&1 | head -1) made the
     * next progress line kill the run by SIGPIPE: a sweep stopped with its
     * table unwritten (exit 141). A write to a closed pipe now fails with
     * EPIPE instead: progress lines are dropped, the run writes its files, and
     * a failed stdout is reported and ends in exit 1, as a full disk does. */
    signal(SIGPIPE, SIG_IGN);
    /* SIGINT, SIGTERM or SIGHUP (where not ignored) end the program as before,
     * killed by the signal, but first remove the temporaries of the files under
     * way and of the output set not yet placed: --out is then as it was
     * before the run (before, a layer-impact stopped after its first snapshot
     * left snapshot_0.vtk.tmp.HOST.PID.XXXXXX there until the next run). A
     * sweep replaces SIGINT's and SIGTERM's while its cases run (sweep_cmd.c). */
    gw_temps_on_signals();
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
    /* "granwave -- COMMAND ...": the end of the program's own options (--help,
     * --version); COMMAND is then taken as a name, never as one of them */
    const int ended = strcmp(argv[1], "--") == 0;
    if (ended) {
        argv[1] = argv[0];
        argv++;
        argc--;
    }
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "help") == 0 || (!ended && (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0)))
        return help(argc, argv);
    if (strcmp(cmd, "version") == 0 || (!ended && strcmp(cmd, "--version") == 0))
        return version(argc, argv);
    const command *c = find_command(cmd);
    /* the progress displays' delay set for tests (GW_PROGRESS_MS): a
     * malformed value refused before anything is done */
    if (c && gw_cli_progress_env() != 0)
        return 2;
    if (c)
        return stdout_checked(cmd, c->run(argc - 2, argv + 2));
    return refuse(NULL, "unknown command '%s' (see granwave --help)", cmd);
}
