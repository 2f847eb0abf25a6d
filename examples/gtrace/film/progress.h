/* progress.h - the progress bar and the clock (progress.c). */
#ifndef GTRACE_PROGRESS_H
#define GTRACE_PROGRESS_H

/** Progress bar on stderr: shown only when stderr is a terminal and not quiet. */
typedef struct Progress {
    int enabled;
    long total, done;
    double start, last;
} Progress;
/** Starts a bar for total units of work (quiet: never shown). */
void progress_start(Progress *p, long total, int quiet);
/** Adds finished work; redraws at most ten times a second (call from one thread at a time). */
void progress_add(Progress *p, long n);
/** The estimated seconds left at time now: the elapsed time times the work left over the work done (0 when
 * finished, -1 before any work is done). */
double progress_remaining(const Progress *p, double now);
/** Ends the bar with a newline (a bar that did not reach the total is drawn once more to show where it stopped). */
void progress_finish(Progress *p);
/** Seconds on a monotonic clock. */
double now_seconds(void);

#endif
