/* progress.c - a progress bar with the elapsed time and an estimate of the time left (the rate so far applied to
 * the work left: the renderer takes its tiles in a shuffled order, so the rate is the image's average), drawn on stderr
 * only when stderr is a terminal (and not silenced), at most ten times a second. */
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double progress_remaining(const Progress *p, double now)
{
    if (p->done <= 0)
        return -1.0;
    if (p->done >= p->total)
        return 0.0;
    return (now - p->start) * (double)(p->total - p->done) / (double)p->done;
}

static void draw(const Progress *p, double now)
{
    enum { WIDTH = 40 };
    double f = p->total > 0 ? (double)p->done / (double)p->total : 1.0;
    int fill = (int)(f * WIDTH + 0.5);
    char bar[WIDTH + 1];
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < fill ? '#' : '.';
    bar[WIDTH] = '\0';
    double elapsed = now - p->start;
    if (p->done > 0 && p->done < p->total)
        fprintf(stderr, "\r[%s] %3.0f%%  %.1f s, about %.1f s left ", bar, 100.0 * f, elapsed,
                progress_remaining(p, now));
    else
        fprintf(stderr, "\r[%s] %3.0f%%  %.1f s                    ", bar, 100.0 * f, elapsed);
    fflush(stderr);
}

void progress_start(Progress *p, long total, int quiet)
{
    p->enabled = !quiet && isatty(STDERR_FILENO);
    p->total = total;
    p->done = 0;
    p->start = p->last = now_seconds();
    if (p->enabled)
        draw(p, p->start);
}

void progress_add(Progress *p, long n)
{
    p->done += n;
    if (!p->enabled)
        return;
    double now = now_seconds();
    if (now - p->last >= 0.1 || p->done == p->total) {
        p->last = now;
        draw(p, now);
    }
}

void progress_finish(Progress *p)
{
    if (!p->enabled)
        return;
    if (p->done != p->total) /* a failed render: show where it stopped */
        draw(p, now_seconds());
    fputc('\n', stderr);
}
