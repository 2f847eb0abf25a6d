/* error.c - the error record. */
#include "generic/error.h"

#include <stdarg.h>
#include <stdio.h>

int gerror_set(GError *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        err->code = code;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return code;
}

void gerror_clear(GError *err)
{
    if (err) {
        err->code = G_OK;
        err->message[0] = '\0';
    }
}

const char *gstatus_string(int code)
{
    switch (code) {
    case G_OK: return "ok";
    case G_ERR_INVALID: return "invalid argument or value";
    case G_ERR_NOMEM: return "out of memory";
    case G_ERR_IO: return "input/output error";
    case G_ERR_PARSE: return "parse error";
    case G_ERR_MISMATCH: return "colours of different models or kinds";
    case G_ERR_VERSION: return "interface version mismatch";
    case G_ERR_NOTFOUND: return "not found";
    case G_ERR_EXISTS: return "already exists";
    case G_ERR_UNSUPPORTED: return "operation not supported";
    default: return "unknown error";
    }
}
