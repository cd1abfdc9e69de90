/*
 * gw_stats_impl.h: what the files of the stats module share and the library
 * does not export (it is built with -fvisibility=hidden; gw_stats.h is the
 * module's public header). Each check returns GW_OK, or GW_EFORMAT naming
 * the table (and the line where there is one) with err set, or GW_ENOMEM;
 * the table is left as it is (the reader frees it on a failure; the
 * analysis's caller with gw_stats_analysis_free).
 */
#ifndef GW_STATS_IMPL_H
#define GW_STATS_IMPL_H

#include "gw_stats.h"

/* gw_stats_table_read, and the sweep's warnings its "# warning: TEXT" lines
 * give (tables since session 45, before the header) appended to *warnings (a
 * gw_warnings_add list; NULL: not kept), in the table's order, a text given
 * twice kept once. *warnings may hold some after a failure: the caller frees
 * it. */
int gw_stats_table_read_warned(const char *path, gw_stats_table *t, char **warnings, gw_err *err);

/* gw_stats_table_check.c, run by gw_stats_table_parse in this order once
 * every row is read: the rows (a case once, grid values once, a bouncing
 * row's e_n, e, alpha_r), the table's completeness against its first line
 * and "# grid" lines, and the rows' hashes against its "# param" and
 * "# input" lines. */
int gw_stats_table_check_rows(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_complete(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_hashes(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_file_hashes(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_rm(const gw_stats_table *t, gw_err *err);

/* The rows of t against the definitions of e_n, e, alpha_r (B.16-B.18) and
 * the energy ledger (gw_stats_bounds.c says per column why; run
 * by gw_stats_analyse): GW_EFORMAT "path:line: column C: ..." for a row no run writes (alpha_r above 90 deg
 * in a bouncing row, e_n cos(alpha_i) above e, a number where a row that did
 * not bounce has nan, ...); a row a run writes in an unusual case only (e
 * above what the incident energy and gravity's work give) is added to
 * *warnings (gw_warnings_add; warnings NULL: not said). alpha_i and V_i of a
 * row: its grid key, its "# param" line, else df's (df NULL or NaN: the
 * checks that need them are skipped). GW_ENOMEM for a warning not added. */
int gw_stats_table_bounds(const gw_stats_table *t, const gw_stats_defaults *df, char **warnings, gw_err *err);

/* A table's counts and arrays agree (gw_stats_groups.c): key and param counts
 * within GW_STATS_MAX_KEYS, the arrays of its rows, keys and columns given,
 * each named; GW_EINVAL "stats table: ..." otherwise. */
int stats_table_shape(const gw_stats_table *t, gw_err *err);

#endif
