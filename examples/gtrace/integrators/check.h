/* check.h - the integrators' error idiom: CHECK(expr) evaluates a status and, when it is negative, stores it in the
 * caller's `rc` and jumps to the caller's `done` label (where temporaries are released). */
#ifndef GTRACE_INTEGRATORS_CHECK_H
#define GTRACE_INTEGRATORS_CHECK_H

#define CHECK(expr)                                                                                                    \
    do {                                                                                                               \
        int rc_ = (expr);                                                                                              \
        if (rc_ < 0) {                                                                                                 \
            rc = rc_;                                                                                                  \
            goto done;                                                                                                 \
        }                                                                                                              \
    } while (0)

#endif
