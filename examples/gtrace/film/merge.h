/* merge.h - `gtrace merge`: crops rendered apart, joined into the full image (merge.c). */
#ifndef GTRACE_MERGE_H
#define GTRACE_MERGE_H

/** The merge command: argv[0] is "merge", then its options and the pieces. Returns the exit status (0, 1 when
 * the pieces cannot be read, do not fit together or the output cannot be written, 2 for a usage error). */
int merge_main(int argc, char **argv);

#endif
