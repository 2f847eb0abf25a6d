/* error.h - status codes and the error record filled by functions that can fail. */
#ifndef GENERIC_ERROR_H
#define GENERIC_ERROR_H

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

/** Error record: the status and a human readable message ("file:line:col: ..." for text input). */
typedef struct GError {
    int code;
    char message[512];
} GError;

/** Sets code and a printf-style message; err may be NULL. Returns code so callers can `return gerror_set(...)`. */
int gerror_set(GError *err, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/** Clears the record to G_OK and an empty message; err may be NULL. */
void gerror_clear(GError *err);

/** Returns a short static description of a status code. */
const char *gstatus_string(int code);

#ifdef __cplusplus
}
#endif
#endif
