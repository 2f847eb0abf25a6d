/* uplift_memo.h - each thread's memo of the spectra the sigmoid uplift made (lib/color/spectral.c), private to lib/:
 * an image texture asks for the same texel colours again and again, and each answer costs a fit. */
#ifndef GENERIC_LIB_UPLIFT_MEMO_H
#define GENERIC_LIB_UPLIFT_MEMO_H

/** The most values a memo entry holds; longer spectra are not kept. */
#define GUPLIFT_MEMO_MAX_VALUES 96

/** The values kept for (model, role, rgb) with n values in this thread, or NULL. *epoch (never NULL) gets the
 * memo's epoch, to hand to guplift_memo_store once the values are made. */
const float *guplift_memo_find(const void *model, int role, const double rgb[3], int n, unsigned long *epoch);
/** Keeps the n values v (n <= GUPLIFT_MEMO_MAX_VALUES) for (model, role, rgb) in this thread's memo, in place of
 * what the slot held, unless a model was forgotten since epoch was read. Without memory it keeps nothing. */
void guplift_memo_store(const void *model, int role, const double rgb[3], int n, const float *v,
                        unsigned long epoch);
/** Forgets everything every thread keeps (a model is going away: another may be made at its address). */
void guplift_memo_forget_all(void);

#endif
