/* progress.c - a progress bar with the elapsed time and an estimate of the time left (the rate so far applied to
 * the work left: the renderer takes its tiles in a shuffled order, so the rate is the image's average), drawn on stderr
 * when stderr is a terminal (and not silenced), at most ten times a second. When stderr is not a terminal (a batch
 * job's log, a notebook), plain lines without carriage returns, one when both a tenth of the work and an interval
 * (10 s, or GTRACE_PROGRESS_INTERVAL seconds) have passed since the previous one. */
#include "progress.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

/* One line of progress: the share done, the time so far and, before the end, the estimate of the time left. */
static void line(Progress *p, double now)
{
    double f = p->total > 0 ? (double)p->done / (double)p->total : 1.0;
    if (p->done < p->total)
        fprintf(stderr, "gtrace: %.0f%% rendered, %.1f s elapsed, about %.1f s left\n", floor(100.0 * f),
                now - p->start, progress_remaining(p, now));
    else
        fprintf(stderr, "gtrace: 100%% rendered, %.1f s elapsed\n", now - p->start);
    fflush(stderr);
    p->last = now;
    p->line_done = p->done;
}

double progress_interval(void)
{
    const char *s = getenv("GTRACE_PROGRESS_INTERVAL");
    char *end;
    double v = s && *s ? strtod(s, &end) : -1.0;
    return s && *s && *end == '\0' && v >= 0.0 && v <= 1e9 ? v : PROGRESS_LINE_INTERVAL;
}

int progress_line_due(const Progress *p, double now)
{
    return p->done - p->line_done >= (p->total + 9) / 10 && now - p->last >= p->interval;
}

void progress_start(Progress *p, long total, int quiet)
{
    p->enabled = quiet ? PROGRESS_OFF : isatty(STDERR_FILENO) ? PROGRESS_BAR : PROGRESS_LINES;
    p->total = total;
    p->done = 0;
    p->line_done = 0;
    p->interval = p->enabled == PROGRESS_LINES ? progress_interval() : 0.0;
    p->start = p->last = now_seconds();
    if (p->enabled == PROGRESS_BAR)
        draw(p, p->start);
}

void progress_add(Progress *p, long n)
{
    p->done += n;
    if (!p->enabled)
        return;
    double now = now_seconds();
    if (p->enabled == PROGRESS_LINES) {
        if (progress_line_due(p, now))
            line(p, now);
        return;
    }
    if (now - p->last >= 0.1 || p->done == p->total) {
        p->last = now;
        draw(p, now);
    }
}

void progress_finish(Progress *p)
{
    if (p->enabled == PROGRESS_LINES) {
        if (p->line_done > 0 && p->line_done < p->done) /* a line was printed: end with where the work stopped */
            line(p, now_seconds());
        return;
    }
    if (!p->enabled)
        return;
    if (p->done != p->total) /* a failed render: show where it stopped */
        draw(p, now_seconds());
    fputc('\n', stderr);
}
