/* merge.c - `gtrace merge PIECES... -o OUT`: the pieces are crops of one render (`gtrace --crop`, e.g. the tasks of
 * a scheduler's array job), OpenEXR files whose data windows say where they lie in the full image (the display
 * window). Every piece must name the same full image and channel count, and together they must cover it exactly
 * once; the pixels are copied unchanged, so the result equals the full render bit for bit. Nothing is written
 * when the pieces do not fit: the messages name the pieces at fault. */
#include "merge.h"
#include "../common/cli.h"

#include <generic/image.h>
#include <generic/memory.h>

#include <stdio.h>
#include <string.h>

static void merge_usage(FILE *f)
{
    fprintf(f,
            "usage: gtrace merge PIECE... -o OUT [-q]\n"
            "Joins crops of one render (gtrace --crop X0,Y0,X1,Y1 -o PIECE.exr, rendered as separate processes,\n"
            "e.g. the tasks of a Slurm or HTCondor array job) into the full image. Each piece is an OpenEXR file\n"
            "whose data window is its place in the full image (its display window), as gtrace writes a crop; the\n"
            "pieces must share the full image size and channels and cover it exactly once (no overlap, no gap).\n"
            "Pixels are copied unchanged: the merged image equals a single render bit for bit. See\n"
            "docs/distributed.md.\n"
            "  -o OUT       the merged image (.exr keeps the floats; other formats are display-encoded)\n"
            "  -q, --quiet  no summary line\n"
            "  -h, --help   this text\n"
            "  --version    the version\n" CLI_EXIT_STATUS_HELP);
}

/* Reads every piece's window and checks that they tile one full image exactly. 0, or -1 after the messages. */
static int check_pieces(char **paths, int n, GImageWindow *win)
{
    GError err;
    int bad = 0;
    for (int i = 0; i < n; i++) {
        if (gimage_window(paths[i], &win[i], &err) != G_OK) {
            fprintf(stderr, "gtrace merge: %s\n", err.message);
            return -1;
        }
        const GImageWindow *w = &win[i], *f = &win[0];
        if (w->full_width != f->full_width || w->full_height != f->full_height) {
            fprintf(stderr, "gtrace merge: %s is a piece of a %dx%d image, %s of a %dx%d one: pieces of another "
                    "render\n", paths[i], w->full_width, w->full_height, paths[0], f->full_width, f->full_height);
            bad = 1;
        } else if (w->x < 0 || w->y < 0 || (long long)w->x + w->width > w->full_width ||
                   (long long)w->y + w->height > w->full_height) {
            fprintf(stderr, "gtrace merge: %s: its %dx%d pixels at %d,%d reach outside the %dx%d image\n", paths[i],
                    w->width, w->height, w->x, w->y, w->full_width, w->full_height);
            bad = 1;
        }
    }
    if (bad)
        return -1;
    long long area = 0;
    for (int i = 0; i < n; i++) {
        area += (long long)win[i].width * win[i].height;
        for (int k = 0; k < i; k++) {
            const GImageWindow *a = &win[i], *b = &win[k];
            int x0 = a->x > b->x ? a->x : b->x, y0 = a->y > b->y ? a->y : b->y;
            int x1 = a->x + a->width < b->x + b->width ? a->x + a->width : b->x + b->width;
            int y1 = a->y + a->height < b->y + b->height ? a->y + a->height : b->y + b->height;
            if (x0 < x1 && y0 < y1) {
                fprintf(stderr, "gtrace merge: %s and %s overlap (pixels %d,%d to %d,%d are in both)\n", paths[k],
                        paths[i], x0, y0, x1 - 1, y1 - 1);
                bad = 1;
            }
        }
    }
    if (bad)
        return -1;
    long long full = (long long)win[0].full_width * win[0].full_height;
    if (area < full) { /* disjoint pieces inside the image: some pixels are in none; name the first */
        for (int y = 0; y < win[0].full_height; y++)
            for (int x = 0; x < win[0].full_width; x++) {
                int in = 0;
                for (int i = 0; i < n && !in; i++)
                    in = x >= win[i].x && x < win[i].x + win[i].width && y >= win[i].y && y < win[i].y + win[i].height;
                if (!in) {
                    fprintf(stderr, "gtrace merge: the pieces leave %lld of the %dx%d image's pixels uncovered, the "
                            "first at %d,%d (a piece is missing)\n", full - area, win[0].full_width,
                            win[0].full_height, x, y);
                    return -1;
                }
            }
    }
    return 0;
}

/* Copies every piece into the full image; G_OK or the error in err. */
static int assemble(char **paths, int n, const GImageWindow *win, GImage *full, GError *err)
{
    full->pixels = NULL;
    for (int i = 0; i < n; i++) {
        GImage piece;
        int w, h, channels;
        int rc = gimage_info(paths[i], &w, &h, &channels, err);
        if (rc != G_OK)
            return rc;
        if (channels > 4) /* gimage_read keeps the colour channels only: refuse rather than drop the rest */
            return gerror_set(err, G_ERR_UNSUPPORTED, "%s has %d channels (values at wavelengths, --spectral?): gtrace "
                              "merge joins colour channels only; join such pieces with `oiiotool PIECE1 PIECE2 --add "
                              "PIECE3 --add ... -o OUT` (docs/distributed.md)", paths[i], channels);
        if ((rc = gimage_read(paths[i], 0, &piece, err)) != G_OK)
            return rc;
        if (piece.width != win[i].width || piece.height != win[i].height) {
            gimage_free(&piece);
            return gerror_set(err, G_ERR_IO, "%s: read as %dx%d, its header said %dx%d", paths[i], piece.width,
                              piece.height, win[i].width, win[i].height);
        }
        if (i == 0 && (rc = gimage_create(full, win[0].full_width, win[0].full_height, piece.channels, err)) != G_OK) {
            gimage_free(&piece);
            return rc;
        }
        if (piece.channels != full->channels) {
            gimage_free(&piece);
            return gerror_set(err, G_ERR_IO, "%s has %d channels, %s %d: pieces of another render", paths[i],
                              piece.channels, paths[0], full->channels);
        }
        size_t row = (size_t)piece.width * (size_t)piece.channels;
        for (int y = 0; y < piece.height; y++)
            memcpy(full->pixels + ((size_t)(win[i].y + y) * (size_t)full->width + (size_t)win[i].x) * full->channels,
                   piece.pixels + (size_t)y * row, row * sizeof(float));
        gimage_free(&piece);
    }
    return G_OK;
}

int merge_main(int argc, char **argv)
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
    int n;
    char **paths = cli_operands(&p, &n);
    if (n < 1 || !out) {
        fprintf(stderr, "gtrace merge: %s\n", n < 1 ? "no pieces given" : "no output file given (-o OUT)");
        merge_usage(stderr);
        return 2;
    }
    GError err;
    if (gimage_check_output(out, &err) != G_OK) {
        fprintf(stderr, "gtrace merge: %s\n", err.message);
        return 1;
    }
    GImageWindow *win = gmem_calloc((size_t)n, sizeof *win);
    if (!win) {
        fprintf(stderr, "gtrace merge: out of memory\n");
        return 1;
    }
    GImage full = {0};
    int status = check_pieces(paths, n, win) != 0 ? 1 : 0;
    if (!status && (assemble(paths, n, win, &full, &err) != G_OK || gimage_write(out, &full, NULL, &err) != G_OK)) {
        fprintf(stderr, "gtrace merge: %s\n", err.message);
        status = 1;
    }
    if (!status && !quiet)
        printf("gtrace merge: %s %dx%d from %d piece%s\n", out, full.width, full.height, n, n > 1 ? "s" : "");
    gimage_free(&full);
    gmem_free(win);
    return status;
}
