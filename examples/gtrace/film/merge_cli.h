/* merge_cli.h - the command line of `gtrace merge` (joining the crops of one render, film/merge.h). */
#ifndef GTRACE_MERGE_CLI_H
#define GTRACE_MERGE_CLI_H

/* `gtrace merge PIECE... -o OUT`: argv[0] is "merge". The exit status: 0, 1 when the pieces cannot be read, do not
 * fit together or the output cannot be written, 2 for a usage error. */
int merge_cli_main(int argc, char **argv);

#endif
