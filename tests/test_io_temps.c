/*
 * test_io_temps.c: the table of temporaries a signal handler removes
 * (gw_io_temps.c, issue 18), no physics.
 *  - gw_temps_remove removes an atomic file's temporary while it is written,
 *    and an output set's staged temporaries, and leaves every placed file (a
 *    file renamed into place, an earlier run's files) as it was; after a
 *    commit or an abort it removes nothing; the file and the set are then
 *    aborted safely.
 *  - The table grows: with 200 atomic files open at once (more than its first
 *    block of 64 slots), all 200 temporaries are removed, and the slots given
 *    back serve again. Before, 64 were removed and 136 stayed.
 *  - An output set of 150 files staged and one more file open in a child with
 *    the handler, then SIGTERM: killed by it, no temporary, the 150 earlier
 *    files byte for byte (before: 87 temporaries left); the same set placed
 *    whole in this process, and one staged, emptied and aborted.
 *  - gw_temps_on_signals in a child: an output set with a staged file and a
 *    file being written, then SIGTERM (SIGINT, SIGHUP): the child ends killed
 *    by that signal (wait status), its directory holds the earlier file byte
 *    for byte and no temporary. Before the handler, the staged temporary
 *    stayed. A signal ignored before the call stays ignored, and one with the
 *    program's own handler keeps it.
 *  - An output set's directory moved and a new one made in its place: the
 *    staged and the open temporaries removed in the moved directory, the new
 *    one untouched (2 of its 8 checks fail before: the table held paths); a
 *    file still open when its set closes is removed by its path.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gw_common.h"
#include "gw_test.h"

static char dir[256];

/* The names in dir holding ".tmp." */
static int count_temps(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strstr(e->d_name, ".tmp.") != NULL;
    closedir(d);
    return n;
}

static void path_of(char *out, size_t n, const char *name) { snprintf(out, n, "%s/%s", dir, name); }

/* The temporaries a failed check left removed, so that the next checks count
 * only their own (on the code before, the table's bound left some) */
static void clear_temps(void)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (strstr(e->d_name, ".tmp.")) {
            char p[512];
            path_of(p, sizeof p, e->d_name);
            unlink(p);
        }
    closedir(d);
}

static int write_file(const char *name, const char *text)
{
    char p[512];
    path_of(p, sizeof p, name);
    return gw_write_text(p, text, NULL);
}

/* 1 when dir/name holds exactly text */
static int holds(const char *name, const char *text)
{
    char p[512], buf[256] = "";
    path_of(p, sizeof p, name);
    FILE *fp = fopen(p, "r");
    if (!fp)
        return 0;
    size_t k = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    buf[k] = '\0';
    return strcmp(buf, text) == 0;
}

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static const char *const names[] = {"a.csv", "b.csv", "c.csv", NULL};

static void remove_in_process(void)
{
    gw_err err = {{0}};
    write_file("a.csv", "earlier a\n");
    write_file("b.csv", "earlier b\n");
    /* an atomic file alone, being written */
    char p[512];
    path_of(p, sizeof p, "c.csv");
    gw_afile f;
    gw_test_true(gw_afile_open(&f, p, &err) == GW_OK && exists(f.tmp), "an atomic file open: its temporary exists");
    fputs("new c\n", f.fp);
    fflush(f.fp);
    gw_temps_remove();
    gw_test_true(!exists(f.tmp) && count_temps() == 0, "gw_temps_remove: the open file's temporary removed");
    gw_test_true(holds("a.csv", "earlier a\n") && holds("b.csv", "earlier b\n") && !exists(p),
                 "  the other files as they were, nothing placed");
    gw_afile_abort(&f);
    /* a set: a staged, b being written */
    gw_outset s;
    gw_test_true(gw_outset_begin(&s, dir, names, &err) == GW_OK, "an output set begun");
    path_of(p, sizeof p, "a.csv");
    gw_test_true(gw_write_text(p, "new a\n", &err) == GW_OK && count_temps() == 1, "  a.csv staged (1 temporary)");
    path_of(p, sizeof p, "b.csv");
    gw_test_true(gw_afile_open(&f, p, &err) == GW_OK && count_temps() == 2, "  b.csv being written (2 temporaries)");
    gw_temps_remove();
    gw_test_true(count_temps() == 0, "gw_temps_remove: the staged and the open temporaries removed");
    gw_test_true(holds("a.csv", "earlier a\n") && holds("b.csv", "earlier b\n"), "  the earlier files as they were");
    gw_afile_abort(&f);
    gw_outset_abort(&s);
    gw_test_true(count_temps() == 0 && holds("a.csv", "earlier a\n"), "  the set aborted after it: nothing else changed");
    /* after a commit: the placed files stay */
    gw_test_true(gw_outset_begin(&s, dir, names, &err) == GW_OK, "a second set begun");
    path_of(p, sizeof p, "a.csv");
    int w = gw_write_text(p, "new a\n", &err);
    path_of(p, sizeof p, "b.csv");
    w = w == GW_OK ? gw_write_text(p, "new b\n", &err) : w;
    gw_test_true(w == GW_OK && gw_outset_commit(&s, &err) == GW_OK, "  two files written and the set placed");
    gw_temps_remove();
    gw_test_true(holds("a.csv", "new a\n") && holds("b.csv", "new b\n") && count_temps() == 0,
                 "gw_temps_remove after the commit: the placed files stay");
    gw_test_true(gw_write_text(p, "newer b\n", &err) == GW_OK, "a file alone written and placed");
    gw_temps_remove();
    gw_test_true(holds("b.csv", "newer b\n"), "gw_temps_remove after it: the file stays");
}

/* More temporaries at once than the table's first block of 64 holds: every
 * one is removed (the table grows; before, the 65th and later stayed). */
#define NOPEN 200

static void table_grows(void)
{
    static gw_afile f[NOPEN];
    gw_err err = {{0}};
    int opened = 0;
    for (int i = 0; i < NOPEN; i++) {
        char name[32], p[512];
        snprintf(name, sizeof name, "many%03d.txt", i);
        path_of(p, sizeof p, name);
        opened += gw_afile_open(&f[i], p, &err) == GW_OK;
    }
    gw_test_true(opened == NOPEN && count_temps() == NOPEN, "200 atomic files open: 200 temporaries");
    gw_temps_remove();
    int left = count_temps();
    printf("  left after gw_temps_remove: %d\n", left);
    gw_test_true(left == 0, "gw_temps_remove: all 200 removed (the table past its first 64 slots)");
    clear_temps();
    for (int i = NOPEN - 1; i >= 0; i--)
        gw_afile_abort(&f[i]);
    gw_test_true(count_temps() == 0, "  all aborted: no temporary");
    /* the slots were given back: new files' temporaries are found again, in
     * the first block and past it */
    for (int i = 0; i < NOPEN; i++) {
        char name[32], p[512];
        snprintf(name, sizeof name, "again%03d.txt", i);
        path_of(p, sizeof p, name);
        gw_afile_open(&f[i], p, &err);
    }
    gw_temps_remove();
    gw_test_true(count_temps() == 0 && !exists(f[0].tmp) && !exists(f[NOPEN - 1].tmp),
                 "  the slots given back: 200 new temporaries removed again");
    clear_temps();
    for (int i = 0; i < NOPEN; i++)
        gw_afile_abort(&f[i]);
}

/* An output set of NSET files, with the earlier run's NSET files in dir */
#define NSET 150

static const char *const *set_names(void)
{
    static char buf[NSET][16];
    static const char *list[NSET + 1];
    for (int i = 0; i < NSET; i++) {
        snprintf(buf[i], sizeof buf[i], "s%03d.csv", i);
        list[i] = buf[i];
    }
    list[NSET] = NULL;
    return list;
}

/* 1 when every file of the set holds "WHO k\n" */
static int set_holds(const char *who)
{
    const char *const *nm = set_names();
    for (int i = 0; i < NSET; i++) {
        char text[64];
        snprintf(text, sizeof text, "%s %d\n", who, i);
        if (!holds(nm[i], text))
            return 0;
    }
    return 1;
}

/* In a child: the handler installed, the NSET files staged and one more open,
 * then SIGTERM. Returns the child's wait status. */
static int child_large_set(void)
{
    const char *const *nm = set_names();
    pid_t pid = fork();
    if (pid == 0) {
        gw_temps_on_signals();
        gw_outset s;
        gw_afile f;
        char p[512], text[64];
        if (gw_outset_begin(&s, dir, nm, NULL) != GW_OK)
            _exit(3);
        for (int i = 0; i < NSET; i++) {
            path_of(p, sizeof p, nm[i]);
            snprintf(text, sizeof text, "child %d\n", i);
            if (gw_write_text(p, text, NULL) != GW_OK)
                _exit(4);
        }
        path_of(p, sizeof p, "open.csv");
        if (gw_afile_open(&f, p, NULL) != GW_OK)
            _exit(5);
        sigset_t m;
        sigemptyset(&m);
        sigaddset(&m, SIGTERM);
        pthread_sigmask(SIG_UNBLOCK, &m, NULL);
        kill(getpid(), SIGTERM);
        _exit(0);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return st;
}

static void large_set(void)
{
    const char *const *nm = set_names();
    gw_err err = {{0}};
    char p[512], text[64];
    int w = GW_OK;
    for (int i = 0; i < NSET && w == GW_OK; i++) {
        path_of(p, sizeof p, nm[i]);
        snprintf(text, sizeof text, "earlier %d\n", i);
        w = gw_write_text(p, text, &err);
    }
    gw_test_true(w == GW_OK && set_holds("earlier"), "150 earlier files written");
    int st = child_large_set();
    char what[200];
    snprintf(what, sizeof what, "SIGTERM with 150 files staged and one open: the child killed by it (status 0x%x)",
             st);
    gw_test_true(WIFSIGNALED(st) && WTERMSIG(st) == SIGTERM, what);
    int left = count_temps();
    snprintf(what, sizeof what, "  no temporary (%d left), the 150 earlier files byte for byte", left);
    gw_test_true(left == 0 && set_holds("earlier"), what);
    clear_temps();
    /* and in this process: such a set placed whole, then one aborted */
    gw_outset s;
    w = gw_outset_begin(&s, dir, nm, &err);
    for (int i = 0; i < NSET && w == GW_OK; i++) {
        path_of(p, sizeof p, nm[i]);
        snprintf(text, sizeof text, "new %d\n", i);
        w = gw_write_text(p, text, &err);
    }
    gw_test_true(w == GW_OK && count_temps() == NSET, "150 files staged in this process: 150 temporaries");
    gw_test_true(gw_outset_commit(&s, &err) == GW_OK && set_holds("new") && count_temps() == 0,
                 "  the set placed: the 150 new files, no temporary");
    w = gw_outset_begin(&s, dir, nm, &err);
    for (int i = 0; i < NSET && w == GW_OK; i++) {
        path_of(p, sizeof p, nm[i]);
        w = gw_write_text(p, "lost\n", &err);
    }
    gw_temps_remove();
    gw_test_true(w == GW_OK && count_temps() == 0 && set_holds("new"),
                 "  a second set staged, gw_temps_remove: no temporary, the placed files kept");
    clear_temps();
    gw_outset_abort(&s);
    gw_test_true(set_holds("new") && count_temps() == 0, "  and aborted: nothing changed");
}

/* In a child: the handler installed, a set with a.csv staged and b.csv open,
 * then sig raised at the process. Returns the child's wait status. */
static int child_signal(int sig, int ignore_first)
{
    pid_t pid = fork();
    if (pid == 0) {
        if (ignore_first)
            signal(sig, SIG_IGN);
        gw_temps_on_signals();
        gw_outset s;
        gw_afile f;
        char p[512];
        if (gw_outset_begin(&s, dir, names, NULL) != GW_OK)
            _exit(3);
        path_of(p, sizeof p, "a.csv");
        if (gw_write_text(p, "child a\n", NULL) != GW_OK)
            _exit(4);
        path_of(p, sizeof p, "b.csv");
        if (gw_afile_open(&f, p, NULL) != GW_OK)
            _exit(5);
        fputs("child b\n", f.fp);
        /* the file's hold (this thread's mask) lifted: the signal as another
         * thread of the process would take it, which that mask does not stop */
        sigset_t m;
        sigemptyset(&m);
        sigaddset(&m, sig);
        pthread_sigmask(SIG_UNBLOCK, &m, NULL);
        kill(getpid(), sig);
        gw_afile_abort(&f); /* reached only when the signal is ignored */
        gw_outset_abort(&s);
        _exit(0);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return st;
}

static void on_own(int sig) { (void)sig; }

static void on_signals(void)
{
    static const int sigs[] = {SIGTERM, SIGINT, SIGHUP};
    static const char *const sname[] = {"SIGTERM", "SIGINT", "SIGHUP"};
    write_file("a.csv", "earlier a\n");
    write_file("b.csv", "earlier b\n");
    for (int k = 0; k < 3; k++) {
        int st = child_signal(sigs[k], 0);
        char what[160];
        snprintf(what, sizeof what, "%s with the handler: the child killed by it (status 0x%x)", sname[k], st);
        gw_test_true(WIFSIGNALED(st) && WTERMSIG(st) == sigs[k], what);
        snprintf(what, sizeof what, "  %s: no temporary (%d), the earlier files byte for byte", sname[k],
                 count_temps());
        gw_test_true(count_temps() == 0 && holds("a.csv", "earlier a\n") && holds("b.csv", "earlier b\n"), what);
    }
    int st = child_signal(SIGTERM, 1);
    gw_test_true(WIFEXITED(st) && WEXITSTATUS(st) == 0 && count_temps() == 0,
                 "SIGTERM ignored before gw_temps_on_signals stays ignored (the child ends normally)");
    /* a handler of the program's own is kept; a signal at its default action
     * gets the handler */
    struct sigaction own, was_term, was_hup, got_term, got_hup;
    memset(&own, 0, sizeof own);
    own.sa_handler = on_own;
    sigemptyset(&own.sa_mask);
    sigaction(SIGTERM, &own, &was_term);
    sigaction(SIGHUP, NULL, &was_hup);
    gw_test_true(was_hup.sa_handler == SIG_DFL, "SIGHUP at its default action in this process");
    gw_test_true(gw_temps_on_signals() == GW_OK, "gw_temps_on_signals: GW_OK");
    sigaction(SIGTERM, NULL, &got_term);
    sigaction(SIGHUP, NULL, &got_hup);
    gw_test_true(got_term.sa_handler == on_own, "  SIGTERM keeps the program's own handler");
    gw_test_true(got_hup.sa_handler != SIG_DFL && got_hup.sa_handler != SIG_IGN, "  SIGHUP gets the handler");
    sigaction(SIGTERM, &was_term, NULL); /* this process's, back */
    sigaction(SIGHUP, &was_hup, NULL);
}

/* The names in path (a directory), "." and ".." left out: -1 when it cannot
 * be read */
static int entries(const char *path)
{
    int n = 0;
    DIR *d = opendir(path);
    if (!d)
        return -1;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

/* An output set's temporaries after its directory M was moved to M.old and
 * a new M made: gw_temps_remove finds them in M.old (the set's handle on the
 * directory) and touches nothing in the new M. Before, the table held paths:
 * both stayed in M.old. A file still open when its set closes is removed by
 * its path from then on (its slot no longer names the closed handle). */
static void moved_dir(void)
{
    gw_err err = {{0}};
    char m[300], old[304], pa[320], pb[320], pc[320];
    snprintf(m, sizeof m, "%s/M", dir);
    snprintf(old, sizeof old, "%s/M.old", dir);
    snprintf(pa, sizeof pa, "%s/a.csv", m);
    snprintf(pb, sizeof pb, "%s/b.csv", m);
    snprintf(pc, sizeof pc, "%s/c.csv", m);
    mkdir(m, 0700);
    gw_outset s;
    gw_afile a, b;
    gw_test_true(gw_outset_begin(&s, m, names, &err) == GW_OK && gw_afile_open(&a, pa, &err) == GW_OK &&
                     fputs("new a\n", a.fp) >= 0 && gw_afile_commit(&a, &err) == GW_OK &&
                     gw_afile_open(&b, pb, &err) == GW_OK && entries(m) == 2,
                 "a set in M: a.csv staged, b.csv open (2 temporaries in M)");
    gw_test_true(rename(m, old) == 0 && mkdir(m, 0700) == 0, "  M moved to M.old, a new M made");
    gw_temps_remove();
    printf("  after gw_temps_remove: M.old holds %d, the new M %d\n", entries(old), entries(m));
    gw_test_true(entries(old) == 0, "  gw_temps_remove: both temporaries removed in M.old");
    gw_test_true(entries(m) == 0, "  the new M untouched (empty)");
    gw_afile_abort(&b);
    gw_outset_abort(&s);
    gw_test_true(entries(old) == 0 && entries(m) == 0, "  the file and the set aborted: nothing left");
    /* a file open when its set closes */
    gw_afile c;
    gw_test_true(gw_outset_begin(&s, m, names, &err) == GW_OK && gw_afile_open(&c, pc, &err) == GW_OK &&
                     entries(m) == 1,
                 "a set in M, c.csv open");
    gw_outset_abort(&s);
    gw_test_true(entries(m) == 1, "  the set aborted, c.csv still open: its temporary stays");
    gw_temps_remove();
    gw_test_true(entries(m) == 0, "  gw_temps_remove: removed by its path");
    gw_afile_abort(&c);
    rmdir(m);
    rmdir(old);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/gw_test_io_temps.XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    remove_in_process();
    table_grows();
    large_set();
    on_signals();
    moved_dir();
    /* clean up */
    DIR *d = opendir(dir);
    if (d) {
        for (struct dirent *e; (e = readdir(d)) != NULL;) {
            char p[512];
            if (e->d_name[0] != '.' || strstr(e->d_name, ".tmp.")) {
                snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
                unlink(p);
            }
        }
        closedir(d);
    }
    rmdir(dir);
    return gw_test_summary("test_io_temps");
}
