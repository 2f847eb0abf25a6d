/* progress.h - the progress bar and the clock (progress.c). */
#ifndef GTRACE_PROGRESS_H
#define GTRACE_PROGRESS_H

/** How progress is shown on stderr. */
enum {
    PROGRESS_OFF = 0,   /**< quiet */
    PROGRESS_BAR = 1,   /**< stderr is a terminal: a bar redrawn in place */
    PROGRESS_LINES = 2  /**< stderr is not a terminal: a plain line now and then */
};
/** Least seconds between two progress lines unless GTRACE_PROGRESS_INTERVAL says otherwise. */
#define PROGRESS_LINE_INTERVAL 10.0

/** Progress on stderr: a bar on a terminal, plain lines elsewhere, nothing when quiet. */
typedef struct Progress {
    int enabled;     /**< PROGRESS_OFF, PROGRESS_BAR or PROGRESS_LINES */
    long total, done;
    double start, last; /**< the start, and the last time the bar was drawn or a line printed */
    double interval;    /**< lines: least seconds between two lines */
    long line_done;     /**< lines: the work done at the last line (0: none printed yet) */
} Progress;
/** Starts the progress of total units of work (quiet: never shown). */
void progress_start(Progress *p, long total, int quiet);
/** Adds finished work (call from one thread at a time). A bar is redrawn at most ten times a second; a line is
 * printed when progress_line_due says so: "gtrace: P% rendered, E s elapsed, about L s left" (P rounded down, so
 * 100% only at the end: "gtrace: 100% rendered, E s elapsed"). */
void progress_add(Progress *p, long n);
/** 1 when a line is due at time now: at least a tenth of the work and p->interval seconds since the last line
 * (or the start). */
int progress_line_due(const Progress *p, double now);
/** The seconds between progress lines: GTRACE_PROGRESS_INTERVAL when it is a number in [0, 1e9] (0: a line at
 * every tenth of the work), else PROGRESS_LINE_INTERVAL. */
double progress_interval(void);
/** The estimated seconds left at time now: the elapsed time times the work left over the work done (0 when
 * finished, -1 before any work is done). */
double progress_remaining(const Progress *p, double now);
/** Ends the bar with a newline (a bar that did not reach the total is drawn once more to show where it stopped);
 * after progress lines, prints a last line for the work done since the previous one. */
void progress_finish(Progress *p);
/** Seconds on a monotonic clock. */
double now_seconds(void);

#endif
