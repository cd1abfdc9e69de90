/*
 * abi_caller: a program as a user writes one, for tests/abi/test_abi_loader.sh.
 * It checks, before anything else, that the library it runs with has the ABI
 * of the headers it was compiled against (gw_abi.h), and that the library's
 * gw_err is the size of its own; then prints "ran ABI N" and exits 0. Exit 2
 * with one line on stderr when the library is of another ABI.
 */
#include <stdio.h>

#include "granwave.h"

int main(void)
{
    if (gw_abi_version() != GW_ABI_VERSION) {
        fprintf(stderr, "abi_caller: libgranwave has ABI %d, this program was compiled for ABI %d\n",
                gw_abi_version(), GW_ABI_VERSION);
        return 2;
    }
    if (gw_struct_size("gw_err") != sizeof(gw_err)) {
        fprintf(stderr, "abi_caller: gw_err is %zu bytes in libgranwave, %zu here\n", gw_struct_size("gw_err"),
                sizeof(gw_err));
        return 2;
    }
    printf("ran ABI %d\n", GW_ABI_VERSION);
    return 0;
}
