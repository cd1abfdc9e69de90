/*
 * gw_io_lines.h (internal, not installed): the line rule the text inputs
 * share (gw_io_input.c): the sweep config scanner (gw_sweep_config.c) and
 * the sweep table reader (gw_stats_table.c). The text sample reader
 * (layer_sample.c), which reads a stream and never holds the file whole,
 * checks its last byte against the same rule directly.
 */
#ifndef GW_IO_LINES_H
#define GW_IO_LINES_H

#include <stddef.h>

/* Every text input the writers end line by line (samples, sweep config files,
 * sweep tables) takes a last line without its newline as the end of a file
 * cut short (a number cut in its digits still reads). When the last line of
 * text[0, len) has no newline after it (neither an LF nor the CR of a CR LF),
 * its number (first: the number of the line text starts in) and, in *start
 * (may be NULL), the offset of its first byte; 0 when text is empty or its
 * last line is ended. Each reader keeps its own exemptions (a comment line,
 * a section header) and its own message. */
long gw_input_unended_line(const char *text, size_t len, long first, size_t *start);

#endif
