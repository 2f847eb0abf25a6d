/* error.c - the error record. */
#include "generic/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Length of the UTF-8 sequence at s (1..4) when it is well formed and not a C1 control (U+0080..U+009F), else 0. */
static size_t utf8_printable(const unsigned char *s)
{
    size_t n = s[0] >= 0xf0 && s[0] <= 0xf4 ? 4 : s[0] >= 0xe0 ? 3 : s[0] >= 0xc2 && s[0] < 0xe0 ? 2 : 0;
    for (size_t i = 1; i < n; i++)
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    if (n == 2 && s[0] == 0xc2 && s[1] < 0xa0)
        return 0; /* C1 controls, which terminals may obey */
    if ((n == 3 && s[0] == 0xe0 && s[1] < 0xa0) || (n == 4 && s[0] == 0xf0 && s[1] < 0x90) ||
        (n == 4 && s[0] == 0xf4 && s[1] >= 0x90))
        return 0; /* overlong or beyond U+10FFFF */
    return n;
}

/* Copies src into dst (size bytes) with every control character and every byte that is not well-formed UTF-8
 * written as an escape (\n, \t, \r, \xNN): a message can carry a file name or text from a file, and is
 * printed on a terminal. Printable text, backslashes included, is kept, so escaping twice changes nothing. */
static void escape_controls(char *dst, size_t size, const char *src)
{
    size_t o = 0;
    const unsigned char *s = (const unsigned char *)src;
    while (*s && o + 1 < size) {
        char esc[8];
        size_t n = 1;
        if (*s == '\n' || *s == '\t' || *s == '\r')
            snprintf(esc, sizeof esc, "\\%c", *s == '\n' ? 'n' : *s == '\t' ? 't' : 'r');
        else if (*s < 0x20 || *s == 0x7f || (*s >= 0x80 && !(n = utf8_printable(s))))
            snprintf(esc, sizeof esc, "\\x%02x", *s), n = 1;
        else
            esc[0] = '\0';
        if (esc[0]) {
            size_t k = strlen(esc);
            if (o + k + 1 > size)
                break;
            memcpy(dst + o, esc, k);
            o += k;
        } else {
            if (o + n + 1 > size)
                break;
            memcpy(dst + o, s, n);
            o += n;
        }
        s += n;
    }
    dst[o] = '\0';
}

static void vset(GError *err, int code, const char *param, const char *fmt, va_list ap)
{
    char raw[sizeof err->message];
    err->code = code;
    err->line = err->col = 0;
    snprintf(err->param, sizeof err->param, "%s", param ? param : "");
    vsnprintf(raw, sizeof raw, fmt, ap);
    escape_controls(err->message, sizeof err->message, raw);
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
