/* merge.h - crops rendered apart, joined into the full image (merge.c; the `gtrace merge` command). */
#ifndef GTRACE_MERGE_H
#define GTRACE_MERGE_H

#include <generic/error.h>

/** Joins the pieces paths[0..n-1], crops of one render (OpenEXR files whose data windows say where they lie in the
 * full image), into the full image and writes it to out, with their values at wavelengths when they have them. The
 * pieces must share the full image's size, channels and wavelengths and cover it exactly once. G_OK with the full
 * image's size in *width, *height; else the first misfit (naming the pieces at fault), or why a piece could not be
 * read or out written, in err, and nothing written. */
int merge_pieces(char *const *paths, int n, const char *out, int *width, int *height, GError *err);

#endif
