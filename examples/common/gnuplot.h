/* gnuplot.h - what the tools that draw with gnuplot share: finding the program, quoting a string for its
 * scripts, and the terminal every figure is drawn with. Texts are drawn as written (noenhanced), so a name
 * such as ggx_conductor keeps its underscore instead of starting a subscript. Header only (static functions),
 * libc only, like cli.h. */
#ifndef EXAMPLES_GNUPLOT_H
#define EXAMPLES_GNUPLOT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/** 1 when an executable `gnuplot` is on PATH (or in /usr/bin:/bin when PATH is unset), else 0. */
static inline int gnuplot_found(void)
{
    const char *path = getenv("PATH");
    char buf[4096];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        const char *e = strchr(p, ':');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        snprintf(buf, sizeof buf, "%.*s/gnuplot", (int)n, n ? p : ".");
        if (access(buf, X_OK) == 0)
            return 1;
        p += n + (e ? 1 : 0);
    }
    return 0;
}

/** Writes s as a single-quoted gnuplot string: a quote is doubled, a newline left out. */
static inline void gnuplot_put_quoted(FILE *g, const char *s)
{
    fputc('\'', g);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', g);
        if (*s != '\n')
            fputc(*s, g);
    }
    fputc('\'', g);
}

/** Starts a script: a w x h PNG (pngcairo, Sans of `font` points, texts drawn as written) into png. */
static inline void gnuplot_begin_png(FILE *g, int w, int h, double font, const char *png)
{
    fprintf(g, "set terminal pngcairo noenhanced size %d,%d font 'Sans,%g'\nset output ", w, h, font);
    gnuplot_put_quoted(g, png);
    fputc('\n', g);
}

#endif
