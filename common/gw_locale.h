/*
 * gw_locale.h (internal, not installed): number text that does not depend on
 * the process's locale. A program that calls setlocale(LC_ALL, "") (Python
 * after locale.setlocale, matplotlib and Jupyter users, a C program in a
 * German or French locale) gives strtod and printf a decimal comma: "0.5"
 * would read as 0 and files would get "0,5". Every number the library reads
 * from text or writes as text goes through these, which use the "C" locale
 * whatever the process's or the thread's locale is.
 */
#ifndef GW_LOCALE_H
#define GW_LOCALE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

#if defined(__GNUC__)
#define GW_FMT(a, b) __attribute__((format(printf, a, b)))
#else
#define GW_FMT(a, b)
#endif

/* strtod in the "C" locale */
double gw_strtod(const char *s, char **end);
/* snprintf, vsnprintf, fprintf in the "C" locale (no unbounded sprintf) */
int gw_snprintf(char *buf, size_t n, const char *fmt, ...) GW_FMT(3, 4);
int gw_vsnprintf(char *buf, size_t n, const char *fmt, va_list ap) GW_FMT(3, 0);
int gw_fprintf(FILE *fp, const char *fmt, ...) GW_FMT(2, 3);
/* x as the text of %g when that reads back as x, else with the fewest more
 * digits that do (at most 17): a value refused just outside a bound is shown
 * as given, not rounded onto the bound ("1000 is outside [0, 1000]" was said of
 * 1000.0000001). Returns buf (n >= 32 holds every double). */
const char *gw_num_text(char *buf, size_t n, double x);

/* src as one line of UTF-8 into dst (n >= 1 bytes): a control character
 * written \n, \r, \t or \xHH, and so a byte of no whole UTF-8 character;
 * cut between characters where dst ends. Every gw_err message and warning
 * text goes through it, and so does a title the library writes into a
 * file's one-line header (gw_layer_write_vtk). Defined in gw_common.c. */
void gw_one_line(char *dst, size_t n, const char *src);

/* The permissions of a file the library creates in place of `replaces`: the
 * replaced regular file's, or 0666 less the process's umask (what a shell's >
 * gives; the temporary that mkstemp made is 0600). Defined in gw_io_afile.c. */
mode_t gw_new_file_mode(const char *replaces);

#endif
