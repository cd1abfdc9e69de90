/*
 * test_library_left43.c: what the forty-second session left at the writers
 * called from C, each case in its own child process (test_child.h):
 *   - the control-character rule (gw_io_paths.c: a name a run makes that
 *     holds a byte below 0x20 or 0x7f is refused while it does not exist,
 *     an existing one is written into) was applied by the checks made
 *     before a run (gw_out_file_check, gw_out_names_check, gw_mkdir_p), not
 *     by the writers: gw_afile_open("DIR/a\nb.txt"), gw_write_text,
 *     gw_json_write and gw_afile_openat(dfd, DIR, "c\td.csv") made the file.
 *     The writers apply it at their open now: GW_EINVAL naming the byte,
 *     nothing made (no file, no temporary). gw_layer_sample_write goes
 *     through it too. Controls: a plain name is written, and a file that is
 *     there already under a name with a newline is replaced, as before.
 *   - gw_outset_check_input took a NULL dir or names as "no input" (GW_OK,
 *     nothing checked): it refuses them naming the argument. Its contract for
 *     input NULL or "" (a command without that input) is GW_OK, and the same
 *     file as the set's is still refused (controls).
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "granwave.h"
#include "gw_test_cases.h"
#include "layer_test_util.h"
#include "test_child.h"

static char dir[64];

/* the number of entries in dir (. and .. left out) */
static int entries(void)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d)) != NULL;)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

/* dir emptied (each case leaves it so) */
static void empty_dir(void)
{
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d)) != NULL;) {
        char p[512];
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        unlink(p);
    }
    if (d)
        closedir(d);
}

/* a refusal naming the control character, and nothing made in dir */
static int refused_ctrl(int rc, const gw_err *e, const char *byte)
{
    const int n = entries();
    empty_dir();
    EXPECT(refused(rc, e, "holds a control character"));
    EXPECT(strstr(e->msg, byte) != NULL);
    if (n != 0)
        printf("%d files made\n", n);
    EXPECT(n == 0);
    return 0;
}

static int c_afile_newline(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/a\nb.txt", dir);
    gw_afile f;
    gw_err e = {0};
    const int rc = gw_afile_open(&f, path, &e);
    if (rc == GW_OK) {
        fputs("x\n", f.fp);
        gw_afile_commit(&f, &e);
    }
    return refused_ctrl(rc, &e, "byte 0x0a");
}

static int c_afile_missing_dir(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/sub\x1b/x.txt", dir); /* a directory still to make */
    gw_afile f;
    gw_err e = {0};
    const int rc = gw_afile_open(&f, path, &e);
    if (rc == GW_OK)
        gw_afile_abort(&f);
    return refused_ctrl(rc, &e, "byte 0x1b");
}

static int c_write_text_del(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/t\x7f.txt", dir);
    gw_err e = {0};
    return refused_ctrl(gw_write_text(path, "text\n", &e), &e, "byte 0x7f");
}

static int c_json_write_cr(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/j\r.json", dir);
    cJSON *o = cJSON_CreateObject();
    EXPECT(o != NULL);
    gw_err e = {0};
    const int rc = gw_json_write(path, o, &e);
    cJSON_Delete(o);
    return refused_ctrl(rc, &e, "byte 0x0d");
}

static int c_openat_tab(void)
{
    const int dfd = open(dir, O_RDONLY | O_DIRECTORY);
    EXPECT(dfd >= 0);
    gw_afile f;
    gw_err e = {0};
    const int rc = gw_afile_openat(&f, dfd, dir, "c\td.csv", &e);
    if (rc == GW_OK) {
        fputs("x\n", f.fp);
        gw_afile_commit(&f, &e);
    }
    close(dfd);
    return refused_ctrl(rc, &e, "byte 0x09");
}

static int c_sample_newline(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/s\n.txt", dir);
    gw_layer_sample s = test_three_discs(); /* layer_test_util.h */
    gw_err e = {0};
    return refused_ctrl(gw_layer_sample_write(&s, path, NULL, &e), &e, "byte 0x0a");
}

/* controls: a plain name is written; a name with a newline that is there
 * already is replaced (the rule is for names a run makes) */
static int c_plain_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/plain.txt", dir);
    gw_err e = {0};
    const int rc = gw_write_text(path, "ok\n", &e);
    if (rc != GW_OK)
        printf("write: %s\n", e.msg);
    const int n = entries();
    empty_dir();
    EXPECT(rc == GW_OK && n == 1);
    return 0;
}

static int c_existing_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/old\nname.txt", dir);
    FILE *fp = fopen(path, "w");
    EXPECT(fp && fputs("old\n", fp) >= 0 && fclose(fp) == 0);
    gw_err e = {0};
    const int rc = gw_write_text(path, "new\n", &e);
    if (rc != GW_OK)
        printf("write: %s\n", e.msg);
    char got[16] = "";
    fp = fopen(path, "r");
    if (fp) {
        if (!fgets(got, sizeof got, fp))
            got[0] = '\0';
        fclose(fp);
    }
    const int n = entries();
    empty_dir();
    EXPECT(rc == GW_OK && strcmp(got, "new\n") == 0 && n == 1);
    return 0;
}

/* ------------------------------------------------ gw_outset_check_input ---- */

static const char *const names[] = {"a.csv", "b.json", NULL};

static int c_outset_null_dir(void)
{
    gw_err e = {0};
    EXPECT(refused(gw_outset_check_input(NULL, names, "in.csv", "test", &e), &e, "dir is NULL"));
    EXPECT(strstr(e.msg, "gw_outset_check_input") != NULL);
    return 0;
}

static int c_outset_null_names(void)
{
    gw_err e = {0};
    EXPECT(refused(gw_outset_check_input(dir, NULL, "in.csv", "test", &e), &e, "names is NULL"));
    EXPECT(strstr(e.msg, "gw_outset_check_input") != NULL);
    return 0;
}

/* the contract: no input (NULL or "") is GW_OK, with nothing said */
static int c_outset_no_input(void)
{
    gw_err e = {0};
    EXPECT(gw_outset_check_input(dir, names, NULL, "test", &e) == GW_OK && e.msg[0] == '\0');
    EXPECT(gw_outset_check_input(dir, names, "", "test", &e) == GW_OK && e.msg[0] == '\0');
    return 0;
}

static int c_outset_same_control(void)
{
    char path[128];
    snprintf(path, sizeof path, "%s/a.csv", dir);
    gw_err e = {0};
    EXPECT(refused(gw_outset_check_input(dir, names, path, "test", &e), &e, "is the file this run writes"));
    snprintf(path, sizeof path, "%s/other.csv", dir);
    EXPECT(gw_outset_check_input(dir, names, path, "test", &e) == GW_OK);
    return 0;
}

static const child_row rows[] = {
    {"gw_afile_open of a new name with a newline", c_afile_newline},
    {"gw_afile_open in a directory still to make named with ESC", c_afile_missing_dir},
    {"gw_write_text of a new name with DEL", c_write_text_del},
    {"gw_json_write of a new name with CR", c_json_write_cr},
    {"gw_afile_openat of a new name with a tab", c_openat_tab},
    {"gw_layer_sample_write of a new name with a newline", c_sample_newline},
    {"a plain name written (control)", c_plain_control},
    {"an existing name with a newline replaced (control)", c_existing_control},
    {"gw_outset_check_input with dir NULL", c_outset_null_dir},
    {"gw_outset_check_input with names NULL", c_outset_null_names},
    {"gw_outset_check_input with no input, NULL or empty (the contract)", c_outset_no_input},
    {"gw_outset_check_input of the set's own file (control)", c_outset_same_control},
};

int main(void)
{
    return test_cases_in_dir(dir, sizeof dir, "left43", rows, sizeof rows / sizeof rows[0], NULL);
}
