/*
 * chain_commands.h: the column's commands of the program (app/granwave.c),
 * argv entry points that parse options and print; not part of the library's
 * public headers (not installed).
 */
#ifndef CHAIN_COMMANDS_H
#define CHAIN_COMMANDS_H

int gw_cmd_chain(int argc, char **argv);
int gw_cmd_falcon(int argc, char **argv);
int gw_cmd_wavespeed(int argc, char **argv);
int gw_cmd_softwall(int argc, char **argv);
int gw_cmd_dispersion(int argc, char **argv);
int gw_cmd_drop(int argc, char **argv);

#endif
