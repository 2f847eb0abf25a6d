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
/** Ends the bar with a newline (a bar that did not reach the total is drawn once more to show where it stopped). */
void progress_finish(Progress *p);
/** Seconds on a monotonic clock. */
double now_seconds(void);

#endif
