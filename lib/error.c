/* error.c - the error record. */
#include "generic/error.h"

#include <stdarg.h>
#include <stdio.h>

static void vset(GError *err, int code, const char *param, const char *fmt, va_list ap)
{
    err->code = code;
    err->line = err->col = 0;
    snprintf(err->param, sizeof err->param, "%s", param ? param : "");
    vsnprintf(err->message, sizeof err->message, fmt, ap);
}

int gerror_set(GError *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vset(err, code, NULL, fmt, ap);
        va_end(ap);
    }
    return code;
}

int gerror_set_param(GError *err, int code, const char *param, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vset(err, code, param, fmt, ap);
        va_end(ap);
    }
    return code;
}

void gerror_clear(GError *err)
{
    if (err) {
        err->code = G_OK;
        err->line = err->col = 0;
        err->param[0] = '\0';
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
