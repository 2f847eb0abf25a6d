/* merge_cli.c - the command line of `gtrace merge`: options, help text and messages around merge_pieces. */
#include "merge_cli.h"

#include "merge.h"
#include "../../common/cli.h"

#include <generic/error.h>

#include <stdio.h>

static void merge_usage(FILE *f)
{
    fprintf(f,
            "usage: gtrace merge PIECE... -o OUT [-q]\n"
            "Joins crops of one render (gtrace --crop X0,Y0,X1,Y1 -o PIECE.exr, rendered as separate processes,\n"
            "e.g. the tasks of a Slurm or HTCondor array job) into the full image. Each piece is an OpenEXR file\n"
            "whose data window is its place in the full image (its display window), as gtrace writes a crop; the\n"
            "pieces must share the full image size and channels and cover it exactly once (no overlap, no gap),\n"
            "and be of one render: each piece records the scene file's digest, the colour model, the full size,\n"
            "the samples and the other settings, and pieces that differ are refused naming both.\n"
            "Pieces rendered with --spectral keep their values at the colour model's wavelengths (channels\n"
            "S0.<nm>nm): all of them must have the same wavelengths, and OUT must be an .exr.\n"
            "Pixels are copied unchanged: the merged image equals a single render bit for bit. See\n"
            "docs/distributed.md.\n"
            "  -o OUT       the merged image (.exr keeps the floats; other formats are display-encoded)\n"
            "  -q, --quiet  no summary line\n"
            "  -h, --help   this text\n"
            "  --version    the version\n" CLI_EXIT_STATUS_HELP);
}

int merge_cli_main(int argc, char **argv)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS,
        {"output", required_argument, NULL, 'o'},
        {"quiet", no_argument, NULL, 'q'},
        {NULL, 0, NULL, 0},
    };
    const char *out = NULL;
    int quiet = 0, c;
    CliParser p;
    cli_begin(&p, "gtrace merge", argc, argv, "ho:q", longopts);
    while ((c = cli_next(&p)) != -1) {
        switch (c) {
        case 'h':
            merge_usage(stdout);
            return 0;
        case CLI_VERSION:
            cli_version("gtrace");
            return 0;
        case 'o':
            out = optarg;
            break;
        case 'q':
            quiet = 1;
            break;
        default:
            return 2;
        }
    }
    int n, width, height;
    char **paths = cli_operands(&p, &n);
    if (n < 1 || !out) {
        fprintf(stderr, "gtrace merge: %s\n", n < 1 ? "no pieces given" : "no output file given (-o OUT)");
        merge_usage(stderr);
        return 2;
    }
    GError err;
    if (merge_pieces(paths, n, out, &width, &height, &err) != G_OK) {
        fprintf(stderr, "gtrace merge: %s\n", err.message);
        return 1;
    }
    if (!quiet)
        printf("gtrace merge: %s %dx%d from %d piece%s\n", out, width, height, n, n > 1 ? "s" : "");
    return 0;
}
