/*
 * gw_abi.h: which ABI of libgranwave a program was compiled for, and the
 * library's own sizes of its public structs.
 *
 * The library writes a caller's struct whole: a result or outcome, a gw_err,
 * a gw_layer_sample, a setup's defaults. A struct that gained a member since
 * the caller was compiled (or a hand-made mirror, ctypes) is then written past
 * its end. GW_ABI_VERSION is raised whenever a public struct's layout or an
 * enum constant changes (tests/abi/gw_abi.txt records them; test_abi fails
 * until it is), and it is the soname: libgranwave.so.GW_ABI_VERSION. A
 * program linked against one ABI is therefore refused by the dynamic linker
 * when only another is installed ("libgranwave.so.N: cannot open shared
 * object file"), before any of its code runs. A caller that loads the library
 * itself (dlopen, ctypes) checks gw_abi_version() == GW_ABI_VERSION, or the
 * number its mirrors were written for, before calling anything else.
 */
#ifndef GW_ABI_H
#define GW_ABI_H

#include <stddef.h>

#include "gw_version.h" /* GW_ABI_VERSION: the ABI of these headers */
#include "gw_api.h"

GW_BEGIN_DECLS /* the exported interface, C linkage (gw_api.h) */

/* The ABI of the library linked at run time (GW_ABI_VERSION of the headers it
 * was built from). */
int gw_abi_version(void);

/* sizeof the public struct whose name (the typedef, "gw_layer_sample") is
 * given, as the library was compiled; 0 for NULL or a name that is no struct
 * of the installed headers. Every struct of the installed headers is known
 * (test_abi checks each against the compiler's layout), so a binding compares
 * its mirror of any of them before the library writes one. */
size_t gw_struct_size(const char *name);

GW_END_DECLS

#endif
