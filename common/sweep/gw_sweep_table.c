/*
 * gw_sweep_table.c: the sweep's table (DIR/results.csv), written once every
 * case has run from this sweep's journal alone: its first line (version,
 * model, config hash, N of C cases), the "# param", "# input" and "# grid"
 * lines, the "# warning:" lines (the sweep's warnings: the check pass's,
 * given by the caller, and its rows', taken here from the journal's rows),
 * the header and the rows sorted by case number. Units: the model's.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gw_sweep.h"
#include "gw_locale.h"
#include "gw_sweep_impl.h"
#include "gw_io_impl.h"

typedef struct row_ref {
    long k;
    const char *s;
    size_t len;
} row_ref;

static int cmp_rows(const void *a, const void *b)
{
    long x = ((const row_ref *)a)->k, y = ((const row_ref *)b)->k;
    return (x > y) - (x < y);
}

/* The warnings of the model's rows (each row's text, no newline: its case,
 * its grid values, its model columns, its hashes), appended to *list as the
 * program says them (the config's keys for the single run's flags): the
 * cases that did not end their collision (the column converged 0) and the
 * model's rule over its rows (gw_sweep_rows_rule). They were said on stderr
 * alone, from the table read back: a table kept alone lost them. GW_OK or
 * GW_ENOMEM. */
static int table_rows_warnings(const gw_sweep_config *cfg, const gw_sweep_model *m, const row_ref *rows, long nr,
                               char **list)
{
    int col = -1;
    for (int j = 0; m->columns && j < m->ncolumns; j++)
        if (m->columns[j] && strcmp(m->columns[j], "converged") == 0)
            col = j;
    const gw_sweep_rows_rule *rule = gw_sweep_rows_rule_of(m->name);
    if ((col < 0 && !rule) || m->ncolumns < 1)
        return GW_OK;
    double *row = malloc((size_t)m->ncolumns * sizeof *row);
    void *acc = rule ? calloc(1, rule->acc_size) : NULL;
    if (!row || (rule && !acc)) {
        free(row);
        free(acc);
        return GW_ENOMEM;
    }
    const int at = 1 + cfg->ngrid; /* case, the grid's values (no comma in them), then the model's columns */
    long n = 0, first = -1;
    for (long i = 0; i < nr; i++) {
        const char *s = rows[i].s, *cell = s;
        int k = 0, got = 0;
        for (size_t j = 0; j <= rows[i].len && got < m->ncolumns; j++)
            if (j == rows[i].len || s[j] == ',') {
                if (k >= at && k < at + m->ncolumns) /* (a cell ends at a comma: the row's hashes follow) */
                    row[k - at] = gw_strtod(cell, NULL), got++;
                k++, cell = s + j + 1;
            }
        if (got != m->ncolumns)
            continue; /* not a row this granwave writes: the journal's rows were checked as read */
        if (col >= 0 && row[col] == 0 && n++ == 0)
            first = rows[i].k;
        if (rule)
            rule->row(acc, cfg, rows[i].k, row);
    }
    char *w = NULL;
    int rc = n > 0 ? gw_sweep_undecided_warning(m, n, cfg->ncases, first, &w) : GW_OK;
    if (rc == GW_OK && rule)
        rc = rule->warnings(acc, cfg, &w);
    free(acc);
    free(row);
    gw_sweep_warnings_keys(m, w);
    if (rc == GW_OK)
        rc = gw_sweep_warnings_append(list, w);
    free(w);
    return rc;
}

/* "# warning: TEXT" for each line of list (a gw_warnings_add list), each
 * TEXT one line as gw_warnings_add makes it (gw_one_line: a control
 * character written \r, \t or \xHH, a byte of no whole UTF-8 character
 * \xHH): a caller's list given "a\rb" or an escape sequence wrote them raw
 * into the table, whose reader (layer-stats) said them to a terminal.
 * GW_ENOMEM when a line's copy cannot be made (nothing more written). */
static int write_warnings(FILE *fp, const char *list)
{
    for (const char *p = list; p && *p;) {
        const size_t len = strcspn(p, "\n");
        if (len > 0) {
            char *raw = malloc(len + 1), *line = malloc(4 * len + 1);
            if (!raw || !line) {
                free(raw);
                free(line);
                return GW_ENOMEM;
            }
            memcpy(raw, p, len);
            raw[len] = '\0';
            gw_one_line(line, 4 * len + 1, raw);
            gw_fprintf(fp, "# warning: %s\n", line);
            free(raw);
            free(line);
        }
        p += len + (p[len] == '\n');
    }
    return GW_OK;
}

int gw_sweep_write_table(const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m, gw_err *err)
{
    if (!dir)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_write_table: dir is NULL");
    /* "": refused as "cannot open the sweep's directory: No such file or
     * directory" here, as "path too long" by the _at call */
    if (!dir[0])
        return gw_err_set(err, GW_EINVAL, "sweep directory: the directory is empty ('' names none; '.' is this one)");
    const int dfd = gw_sweep_dir_open(dir);
    if (dfd < 0)
        return gw_err_set(err, GW_EIO, "%s: cannot open the sweep's directory: %s", dir, strerror(errno));
    const int rc = gw_sweep_write_table_at(dfd, dir, cfg, m, err);
    close(dfd);
    return rc;
}

int gw_sweep_write_table_at(int dfd, const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m,
                            gw_err *err)
{
    if (!dir || !cfg || !m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_write_table_at: %s is NULL", !dir ? "dir" : !cfg ? "cfg" : "m");
    /* the check pass's warnings too, from the config as the program's sweep
     * gives them (its table's "# warning:" lines, byte for byte): these calls
     * wrote the rows' alone, and a C caller's table lost a dashpot of no
     * effect. A case refused now (an input file gone since the sweep) leaves
     * them out, the table written as before. */
    char *w = NULL;
    if (gw_sweep_config_check(cfg, NULL) == GW_OK && gw_sweep_check_warnings(cfg, m, &w) != GW_OK) {
        free(w);
        w = NULL;
    }
    const int rc = gw_sweep_write_table_warned(dfd, dir, cfg, m, w, NULL, err);
    free(w);
    return rc;
}

int gw_sweep_write_table_warned(int dfd, const char *dir, const gw_sweep_config *cfg, const gw_sweep_model *m,
                                const char *warnings, char **rows_warnings, gw_err *err)
{
    if (!dir || !cfg || !m)
        return gw_err_set(err, GW_EINVAL, "gw_sweep_write_table_warned: %s is NULL", !dir ? "dir" : !cfg ? "cfg" : "m");
    int shape = gw_sweep_config_check(cfg, err); /* (as the journal's calls) */
    if (shape == GW_OK)
        shape = gw_sweep_model_check("gw_sweep_write_table", cfg, m, 0, err);
    if (shape == GW_OK && !cfg->model) /* a zeroed config: a table of "model (null)" */
        shape = gw_err_set(err, GW_EINVAL, "gw_sweep_write_table: the config names no model (cfg->model NULL)");
    if (shape != GW_OK)
        return shape;
    char path[4096];
    if (gw_io_path_join(path, sizeof path, dir, "journal.csv", "sweep directory", err) != GW_OK)
        return GW_EINVAL;
    /* the journal now in the directory (another sweep's, when it was
     * replaced: refused below), read through the directory held */
    if (gw_sweep_dir_held(dfd, dir, err) != GW_OK)
        return GW_EIO;
    const int jfd = openat(dfd, "journal.csv", O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (jfd < 0)
        return gw_err_set(err, GW_EIO, "%s: cannot read: %s", path, strerror(errno));
    size_t len = 0;
    char *buf = gw_sweep_slurp_fd(jfd, path, gw_sweep_journal_bound(cfg), &len, err);
    close(jfd);
    if (!buf)
        return errno == ENOMEM ? GW_ENOMEM : GW_EIO;
    row_ref *rows = calloc((size_t)cfg->ncases + 1, sizeof *rows);
    char *seen = calloc((size_t)cfg->ncases + 1, 1);
    long nr = 0;
    for (size_t pos = 0; rows && seen && pos < len;) {
        const char *nl = memchr(buf + pos, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - (buf + pos)) + 1 : len - pos;
        long k = gw_sweep_line_case(buf + pos, l, cfg->ncases);
        if (k >= 0 && !seen[k]) {
            seen[k] = 1;
            rows[nr++] = (row_ref){k, buf + pos, l - 10}; /* drop ",checksum\n" */
        }
        pos += l;
    }
    int rc = GW_OK;
    char head[96];
    gw_snprintf(head, sizeof head, GW_SWEEP_JOURNAL_HEAD "\n", cfg->hash);
    const int other = strncmp(buf, head, strlen(head)) != 0;
    if (!rows || !seen) {
        rc = gw_err_set(err, GW_ENOMEM, "sweep: out of memory");
    } else if (other || nr != cfg->ncases) {
        /* the table is of this sweep's journal, every case once: a journal
         * replaced meanwhile gave a table of another sweep's rows, exit 0 */
        rc = other
                 ? gw_err_set(err, GW_EIO, "%s: replaced by another sweep's journal while this sweep ran: no table "
                              "written (this sweep's rows are not in it)", path)
                 : gw_err_set(err, GW_EIO, "%s: lost rows while the sweep ran (%ld of its %ld cases in it): no table "
                              "written; rerun to resume", path, nr, cfg->ncases);
    } else {
        qsort(rows, (size_t)nr, sizeof *rows, cmp_rows);
        gw_afile f;
        char *rw = NULL; /* the rows' warnings, as the check pass's from the journal alone: a resume's table is
                            byte for byte an uninterrupted sweep's */
        if (table_rows_warnings(cfg, m, rows, nr, &rw) != GW_OK)
            rc = gw_err_set(err, GW_ENOMEM, "sweep: out of memory");
        else if ((rc = gw_afile_openat(&f, dfd, dir, "results.csv", err)) == GW_OK) {
            gw_fprintf(f.fp, "# granwave %s sweep, model %s, config %016lx, %ld of %ld cases\n", gw_version(),
                    cfg->model, cfg->hash, nr, cfg->ncases);
            gw_fprintf(f.fp, "# build %s\n", gw_sweep_build()); /* the journal's: it computed every row */
            for (int i = 0; i < cfg->nparams; i++)
                gw_fprintf(f.fp, "# param %s = %s\n", cfg->params[i].name, cfg->params[i].values[0]);
            for (int i = 0; i < cfg->ninputs; i++) /* what the cases' files held */
                gw_fprintf(f.fp, "# input %s = %s fnv1a64 %016llx\n", cfg->inputs[i].key, cfg->inputs[i].value,
                        cfg->inputs[i].hash);
            /* the grid itself: a reader can tell a missing or edited row */
            for (int i = 0; i < cfg->ngrid; i++) {
                gw_fprintf(f.fp, "# grid %s = ", cfg->grid[i].name);
                for (int j = 0; j < cfg->grid[i].nvalues; j++)
                    gw_fprintf(f.fp, "%s%s", j ? ", " : "", cfg->grid[i].values[j]);
                fputc('\n', f.fp);
            }
            const int wrote = write_warnings(f.fp, warnings) == GW_OK && write_warnings(f.fp, rw) == GW_OK;
            gw_fprintf(f.fp, "case");
            for (int i = 0; i < cfg->ngrid; i++)
                gw_fprintf(f.fp, ",%s", cfg->grid[i].name);
            for (int i = 0; i < m->ncolumns; i++)
                gw_fprintf(f.fp, ",%s", m->columns[i]);
            gw_fprintf(f.fp, ",case_config_fnv1a64"); /* the hashes that end each row */
            if (cfg->read_key)
                gw_fprintf(f.fp, ",%s_fnv1a64", cfg->read_key);
            fputc('\n', f.fp);
            for (long i = 0; i < nr; i++) {
                fwrite(rows[i].s, 1, rows[i].len, f.fp);
                fputc('\n', f.fp);
            }
            if (wrote) {
                rc = gw_afile_commit(&f, err);
            } else { /* no table without its warnings */
                gw_afile_abort(&f);
                rc = gw_err_set(err, GW_ENOMEM, "sweep: out of memory");
            }
        }
        if (rc == GW_OK && rows_warnings && rw) { /* said by the caller: the lines it wrote */
            const size_t have = *rows_warnings ? strlen(*rows_warnings) : 0;
            char *grown = realloc(*rows_warnings, have + strlen(rw) + 1);
            if (grown)
                strcpy(grown + have, rw), *rows_warnings = grown;
        }
        free(rw);
    }
    free(rows);
    free(seen);
    free(buf);
    return rc;
}
