/* error.h - status codes and the error record filled by functions that can fail. */
#ifndef GENERIC_ERROR_H
#define GENERIC_ERROR_H

#include "export.h"
#ifdef __cplusplus
extern "C" {
#endif

/** Status codes: 0 is success, every failure is negative. */
enum {
    G_OK = 0,
    G_ERR_INVALID = -1,  /**< bad argument or value (NaN, negative where not allowed, ...) */
    G_ERR_NOMEM = -2,    /**< an allocation failed */
    G_ERR_IO = -3,       /**< a file could not be read or written */
    G_ERR_PARSE = -4,    /**< malformed text input */
    G_ERR_MISMATCH = -5, /**< colours of different models or kinds were combined */
    G_ERR_VERSION = -6,  /**< an interface version does not match */
    G_ERR_NOTFOUND = -7, /**< a name is not registered or defined */
    G_ERR_EXISTS = -8,   /**< a name is registered already */
    G_ERR_UNSUPPORTED = -9 /**< the operation is not defined for this model or value */
};

/** Longest parameter name a GError records (longer names are cut). */
#define GERROR_PARAM_MAX 32

/** Error record: the status, a human readable message ("file:line:col: ..." for text input), and where the
 * complaint is: the text position once a reader has placed it, and the parameter a constructor named. */
typedef struct GError {
    int code;
    int line, col;                 /**< 1-based position in text input; 0 until a reader places the error */
    char param[GERROR_PARAM_MAX];  /**< the parameter the complaint is about ("" for none) */
    char message[512];
} GError;

/** Sets code and a printf-style message, with no position and no parameter; err may be NULL. Returns code so callers
 * can `return gerror_set(...)`. The message is safe to print: control characters (ESC, newlines, ...), UTF-8 C1
 * controls and bytes that are not well-formed UTF-8 are written as escapes (\n, \t, \r, \xNN); other text is kept as it
 * is. */
GENERIC_API int gerror_set(GError *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/** gerror_set naming the parameter the complaint is about (a constructor's `param`, e.g. "reflectance"): a
 * reader that called the constructor places the message at that parameter of the entry (reader.h,
 * greader_locate). Returns code. */
GENERIC_API int gerror_set_param(GError *err, int code, const char *param, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/** Clears the record to G_OK and an empty message; err may be NULL. */
GENERIC_API void gerror_clear(GError *err);

/** Returns a short static description of a status code. */
GENERIC_API const char *gstatus_string(int code);

#ifdef __cplusplus
}
#endif
#endif
