/*
 * gw_stats_impl.h: what the files of the stats module share and the library
 * does not export (it is built with -fvisibility=hidden; gw_stats.h is the
 * module's public header). Each check returns GW_OK, or GW_EFORMAT naming
 * the table (and the line where there is one) with err set, or GW_ENOMEM;
 * the table is left as it is (the reader frees it on a failure).
 */
#ifndef GW_STATS_IMPL_H
#define GW_STATS_IMPL_H

#include "gw_stats.h"

/* gw_stats_table_check.c, run by gw_stats_table_parse in this order once
 * every row is read: the rows (a case once, grid values once, a bouncing
 * row's e_n, e, alpha_r), the table's completeness against its first line
 * and "# grid" lines, and the rows' hashes against its "# param" and
 * "# input" lines. */
int gw_stats_table_check_rows(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_complete(const gw_stats_table *t, gw_err *err);
int gw_stats_table_check_hashes(const gw_stats_table *t, gw_err *err);

#endif
