#include "gw_chain.h"
int gw_cmd_falcon(int argc, char **argv) { (void)argc; (void)argv; return 2; }
