/*
 * gw_sweep_build.c: the build a sweep journal records on its "# build" line
 * (gw_sweep_journal.c): granwave's version, the git commit it was built from
 * (when the build knew it: "+" when tracked files differed from it), the
 * compiler and the flags that can change results, and the versions of the
 * numerical libraries it runs with (SUNDIALS, GSL, FFTW: read at run time,
 * since a shared library updated under an unchanged program changes its
 * numbers too). A journal resumes only under the build that started it: the
 * rows' form is checked byte for byte, but another build may compute other
 * numbers in the same form (the rebound definition changed e_n in issue 18
 * without changing a row's columns), and a table made of both would mix them
 * silently. No units.
 */
#define _POSIX_C_SOURCE 200809L
#include <fftw3.h>
#include <gsl/gsl_version.h>
#include <pthread.h>
#include <string.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_version.h>

#include "gw_build_id.h"
#include "gw_locale.h"
#include "gw_sweep_impl.h"

static char build[GW_SWEEP_BUILD_MAX];

static void make_build(void)
{
    char sun[64] = "";
    if (SUNDIALSGetVersion(sun, (int)sizeof sun) != 0)
        gw_snprintf(sun, sizeof sun, "?");
    char commit[48] = "commit unknown";
    if (GW_BUILD_COMMIT[0])
        gw_snprintf(commit, sizeof commit, "commit %s%s", GW_BUILD_COMMIT, GW_BUILD_LOCAL_CHANGES ? "+" : "");
    /* one line, printable: a flag with a newline or a control byte would cut
     * the journal's head */
    gw_snprintf(build, sizeof build, "granwave %s, %s, %s, SUNDIALS %s, GSL %s, %s", gw_version(), commit,
                GW_BUILD_SETTINGS, sun, gsl_version, fftw_version);
    for (char *p = build; *p; p++)
        if ((unsigned char)*p < 0x20 || (unsigned char)*p == 0x7f)
            *p = ' ';
}

const char *gw_sweep_build(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, make_build);
    return build;
}
