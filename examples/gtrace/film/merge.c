/* merge.c - joining crops of one render (merge.h): the pieces (`gtrace --crop`, e.g. the tasks of a scheduler's
 * array job) are OpenEXR files whose data windows say where they lie in the full image (the display window). Every
 * piece must name the same full image and channel count, and together they must cover it exactly once; the pixels
 * are copied unchanged, so the result equals the full render bit for bit. Pieces rendered with --spectral are
 * joined with their spectra (gimage_read_spectra), which must be at the same wavelengths in every piece, and the
 * result is written in the same layout. Each piece records what render it belongs to (its note: the scene's digest,
 * the colour model, the full size, the samples and the other settings, written by gtrace), and pieces whose notes
 * differ are refused with the first field that differs in both. Nothing is written when the pieces do not fit: the
 * message names the pieces at fault. */
#include "merge.h"

#include <generic/services/image.h>
#include <generic/memory.h>

#include <string.h>

/* The field of a note ("NAME VALUE; NAME VALUE; ...") at which a and b first differ: its start in a and in b, and
 * their lengths. */
static void first_difference(const char *a, const char *b, const char **fa, int *la, const char **fb, int *lb)
{
    size_t i = 0, start = 0;
    while (a[i] && a[i] == b[i]) {
        if (a[i] == ';')
            start = i + 2;
        i++;
    }
    if (start > i)
        start = i;
    *fa = a + start;
    *fb = b + start;
    *la = (int)strcspn(*fa, ";");
    *lb = (int)strcspn(*fb, ";");
}

/* Piece i's note against the first piece's: G_OK when they are the same render, else the mismatch in err. */
static int same_render(char *const *paths, int i, const GImageWindow *win, GError *err)
{
    const char *a = win[0].note, *b = win[i].note;
    if (strcmp(a, b) == 0)
        return G_OK;
    if (!a[0] || !b[0])
        return gerror_set(err, G_ERR_MISMATCH, "%s records the render it belongs to, %s does not: pieces of another "
                          "render (or of another program)", a[0] ? paths[0] : paths[i], a[0] ? paths[i] : paths[0]);
    const char *fa, *fb;
    int la, lb;
    first_difference(a, b, &fa, &la, &fb, &lb);
    return gerror_set(err, G_ERR_MISMATCH, "%s and %s are pieces of different renders: %.*s in %s, %.*s in %s",
                      paths[0], paths[i], la, fa, paths[0], lb, fb, paths[i]);
}

/* Reads every piece's window and checks that they tile one full image exactly: G_OK, or the first misfit found
 * (a piece of another image or outside it, then two pieces that overlap, then a pixel that none covers) in err. */
static int check_pieces(char *const *paths, int n, GImageWindow *win, GError *err)
{
    for (int i = 0; i < n; i++) {
        int rc = gimage_window(paths[i], &win[i], err);
        if (rc != G_OK)
            return rc;
    }

    for (int i = 0; i < n; i++) {
        const GImageWindow *w = &win[i], *f = &win[0];
        if (w->full_width != f->full_width || w->full_height != f->full_height)
            return gerror_set(err, G_ERR_MISMATCH, "%s is a piece of a %dx%d image, %s of a %dx%d one: pieces of "
                              "another render", paths[i], w->full_width, w->full_height, paths[0], f->full_width,
                              f->full_height);
        if (w->x < 0 || w->y < 0 || (long long)w->x + w->width > w->full_width ||
            (long long)w->y + w->height > w->full_height)
            return gerror_set(err, G_ERR_MISMATCH, "%s: its %dx%d pixels at %d,%d reach outside the %dx%d image",
                              paths[i], w->width, w->height, w->x, w->y, w->full_width, w->full_height);
    }
    long long area = 0;
    for (int i = 0; i < n; i++) {
        area += (long long)win[i].width * win[i].height;
        for (int k = 0; k < i; k++) {
            const GImageWindow *a = &win[i], *b = &win[k];
            int x0 = a->x > b->x ? a->x : b->x, y0 = a->y > b->y ? a->y : b->y;
            int x1 = a->x + a->width < b->x + b->width ? a->x + a->width : b->x + b->width;
            int y1 = a->y + a->height < b->y + b->height ? a->y + a->height : b->y + b->height;
            if (x0 < x1 && y0 < y1)
                return gerror_set(err, G_ERR_MISMATCH, "%s and %s overlap (pixels %d,%d to %d,%d are in both)",
                                  paths[k], paths[i], x0, y0, x1 - 1, y1 - 1);
        }
    }
    long long full = (long long)win[0].full_width * win[0].full_height;
    if (area < full) { /* disjoint pieces inside the image: some pixels are in none; name the first */
        for (int y = 0; y < win[0].full_height; y++)
            for (int x = 0; x < win[0].full_width; x++) {
                int in = 0;
                for (int i = 0; i < n && !in; i++)
                    in = x >= win[i].x && x < win[i].x + win[i].width && y >= win[i].y && y < win[i].y + win[i].height;
                if (!in)
                    return gerror_set(err, G_ERR_MISMATCH, "the pieces leave %lld of the %dx%d image's pixels "
                                      "uncovered, the first at %d,%d (a piece is missing)", full - area,
                                      win[0].full_width, win[0].full_height, x, y);
            }
    }
    return G_OK;
}

/* The spectra of piece i (count 0: none) against the first piece's: G_OK, or the mismatch in err. */
static int same_wavelengths(char *const *paths, int i, const GImageSpectraBuf *sp, const GImageSpectraBuf *first,
                            GError *err)
{
    if (sp->count != first->count) {
        if (!sp->count || !first->count)
            return gerror_set(err, G_ERR_MISMATCH,
                              "%s has values at %d wavelengths, %s at %d: pieces of another "
                              "render (all or none rendered with --spectral)",
                              paths[i], sp->count, paths[0], first->count);
        return gerror_set(err, G_ERR_MISMATCH, "%s has %d wavelengths (%g to %g nm), %s %d (%g to %g nm): pieces of "
                          "another render (another colour model?)", paths[i], sp->count, sp->wavelengths[0],
                          sp->wavelengths[sp->count - 1], paths[0], first->count, first->wavelengths[0],
                          first->wavelengths[first->count - 1]);
    }
    for (int k = 0; k < sp->count; k++)
        if (sp->wavelengths[k] != first->wavelengths[k])
            return gerror_set(err, G_ERR_MISMATCH, "%s's wavelength %d is %.6f nm, %s's %.6f nm: pieces of another "
                              "render (another colour model?)", paths[i], k + 1, sp->wavelengths[k], paths[0],
                              first->wavelengths[k]);
    return G_OK;
}

/* Copies count floats a pixel of a w x h piece at (x, y) into a full image of width fw. */
static void place(float *full, int fw, const float *piece, int x, int y, int w, int h, int count)
{
    size_t row = (size_t)w * (size_t)count;
    for (int r = 0; r < h; r++)
        memcpy(full + ((size_t)(y + r) * (size_t)fw + (size_t)x) * (size_t)count, piece + (size_t)r * row,
               row * sizeof(float));
}

/* Copies every piece into the full image, and their spectra (the values at the colour model's wavelengths that
 * --spectral stores) into the full spectra: wavelengths and values (NULL when the pieces have none), count
 * their number. G_OK or the error in err. */
static int assemble(char *const *paths, int n, const GImageWindow *win, GImage *full, GImageSpectraBuf *spectra,
                    GError *err)
{
    full->pixels = NULL;
    *spectra = (GImageSpectraBuf){0};
    for (int i = 0; i < n; i++) {
        GImage piece;
        GImageSpectraBuf sp;
        int w, h, channels;
        int rc = gimage_info(paths[i], &w, &h, &channels, err);
        if (rc != G_OK)
            return rc;
        if ((rc = gimage_read(paths[i], 0, &piece, err)) != G_OK)
            return rc;
        if ((rc = gimage_read_spectra(paths[i], &sp, err)) != G_OK) {
            gimage_free(&piece);
            return rc;
        }
        if (piece.width != win[i].width || piece.height != win[i].height || sp.width != piece.width ||
            sp.height != piece.height)
            rc = gerror_set(err, G_ERR_IO, "%s: read as %dx%d, its header said %dx%d", paths[i], piece.width,
                            piece.height, win[i].width, win[i].height);
        else if (channels > 4 && channels > piece.channels + sp.count) /* nothing may be dropped on the way */
            rc = gerror_set(err, G_ERR_UNSUPPORTED, "%s has %d channels, %d of them neither colour nor values at "
                            "wavelengths (S0.<wavelength>nm): gtrace merge would drop them", paths[i], channels,
                            channels - piece.channels - sp.count);
        else if (i > 0 && piece.channels != full->channels)
            rc = gerror_set(err, G_ERR_IO, "%s has %d channels, %s %d: pieces of another render", paths[i],
                            piece.channels, paths[0], full->channels);
        else if (i > 0)
            rc = same_wavelengths(paths, i, &sp, spectra, err);
        else if ((rc = gimage_create(full, win[0].full_width, win[0].full_height, piece.channels, err)) == G_OK &&
                 sp.count > 0) {
            size_t values = (size_t)win[0].full_width * (size_t)win[0].full_height * (size_t)sp.count;
            if (values * sizeof(float) > gimage_memory_budget())
                rc = gerror_set(err, G_ERR_NOMEM, "%d values per pixel of a %dx%d image take %zu MiB, more than "
                                "the image memory budget of %zu MiB (GENERIC_IMAGE_BUDGET_MB)", sp.count,
                                win[0].full_width, win[0].full_height, (values * sizeof(float)) >> 20,
                                gimage_memory_budget() >> 20);
            else if (!(spectra->wavelengths = gmem_alloc((size_t)sp.count * sizeof(double))) ||
                     !(spectra->values = gmem_alloc(values * sizeof(float))))
                rc = gerror_set(err, G_ERR_NOMEM, "out of memory for the spectra of a %dx%d image",
                                win[0].full_width, win[0].full_height);
            else {
                memcpy(spectra->wavelengths, sp.wavelengths, (size_t)sp.count * sizeof(double));
                spectra->count = sp.count;
                spectra->width = win[0].full_width;
                spectra->height = win[0].full_height;
            }
        }
        if (rc == G_OK) {
            place(full->pixels, full->width, piece.pixels, win[i].x, win[i].y, piece.width, piece.height,
                  piece.channels);
            if (sp.count > 0)
                place(spectra->values, spectra->width, sp.values, win[i].x, win[i].y, sp.width, sp.height,
                      sp.count);
        }
        gimage_free(&piece);
        gimage_spectra_free(&sp);
        if (rc != G_OK)
            return rc;
    }
    return G_OK;
}

/* Writes the merged image, with its spectra when the pieces have them. */
static int write_merged(const char *out, const GImage *full, const GImageSpectraBuf *spectra, GError *err)
{
    GImageSpectra sp = {.count = spectra->count, .wavelengths = spectra->wavelengths, .values = spectra->values};
    GImageWriteOptions opt = {.spectra = spectra->count > 0 ? &sp : NULL};
    return gimage_write(out, full, &opt, err);
}

int merge_pieces(char *const *paths, int n, const char *out, int *width, int *height, GError *err)
{
    if (n < 1)
        return gerror_set(err, G_ERR_INVALID, "no pieces given");
    int rc = gimage_check_output(out, err); /* before the pieces are read */
    if (rc != G_OK)
        return rc;
    GImageWindow *win = gmem_calloc((size_t)n, sizeof *win);
    if (!win)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d pieces", n);
    GImage full = {0};
    GImageSpectraBuf spectra = {0};
    if ((rc = check_pieces(paths, n, win, err)) == G_OK && (rc = assemble(paths, n, win, &full, &spectra, err)) == G_OK)
        for (int i = 1; i < n && rc == G_OK; i++) /* the pieces fit and match: are they of one render? */
            rc = same_render(paths, i, win, err);
    if (rc == G_OK)
        rc = write_merged(out, &full, &spectra, err);
    *width = full.width;
    *height = full.height;
    gimage_free(&full);
    gimage_spectra_free(&spectra);
    gmem_free(win);
    return rc;
}
