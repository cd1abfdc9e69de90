/*
 * abi_sizes: the library's own answers for tests/abi/gw_abi.py. Prints
 * "gw_abi_version() N", then for each line of stdin (a struct's name) the name
 * and gw_struct_size(name); an empty line is asked as "" and printed as
 * "(empty)". Linked to libgranwave.so, so it sees what a caller sees.
 */
#include <stdio.h>
#include <string.h>

#include "gw_abi.h"

int main(void)
{
    char line[256];
    printf("gw_abi_version() %d\n", gw_abi_version());
    while (fgets(line, sizeof line, stdin)) {
        line[strcspn(line, "\r\n")] = '\0';
        printf("%s %zu\n", line[0] ? line : "(empty)", gw_struct_size(line));
    }
    printf("(null) %zu\n", gw_struct_size(NULL));
    return ferror(stdin) ? 1 : 0;
}
