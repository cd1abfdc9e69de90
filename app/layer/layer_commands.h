/*
 * layer_commands.h: the layer's commands of the program (app/granwave.c),
 * argv entry points that parse options and print; not part of the library's
 * public headers (not installed).
 */
#ifndef LAYER_COMMANDS_H
#define LAYER_COMMANDS_H

int gw_cmd_layer_make(int argc, char **argv);
int gw_cmd_layer_impact(int argc, char **argv);
/* `granwave layer-stats RESULTS.csv`: statistics, binary-impact check and
 * bouncing-occurrence diagram of a layer sweep table (layer_stats.c). */
int gw_cmd_layer_stats(int argc, char **argv);

#define GW_LAYER_COMMANDS                                                           \
    {"layer-make", gw_cmd_layer_make, "pluviate a 2D granular sample (Bourrier 2008)"}, \
    {"layer-impact", gw_cmd_layer_impact, "one block impact on a 2D granular layer"}, \
    {"layer-stats", gw_cmd_layer_stats, "statistics and bouncing diagram of a layer sweep table"},

#endif
