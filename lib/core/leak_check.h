/* leak_check.h - sanitizer builds only: the leak check at exit, run when no thread is in the middle of exiting. */
#ifndef GENERIC_CORE_LEAK_CHECK_H
#define GENERIC_CORE_LEAK_CHECK_H

/** In a build with AddressSanitizer (and not the fuzzing build): waits until the process's thread count has been
 * steady for a while (at most about two seconds), then runs LeakSanitizer's check, once. Elsewhere it does nothing.
 * LeakSanitizer's own check at exit stops every thread with a tracer that can crash on a thread that is exiting at
 * that moment (the workers that TBB, OpenImageIO or log4cplus stop in their destructors). */
void gleak_check_when_threads_settle(void);

#endif
