/* mesh_json.c - a strict JSON scanner without recursion: a stack of open containers bounded by JSON_MAX_DEPTH, and
 * the tokens in one array, each knowing where its subtree ends, so that the glTF check walks members and elements
 * without recursing either. */
#include "mesh_json.h"

#include <generic/memory.h>

#include <stdio.h>
#include <string.h>

typedef enum Want { WANT_VALUE, WANT_KEY, WANT_COLON, WANT_NEXT, WANT_END } Want;

typedef struct Scan {
    Json *j;
    const char *path, *where;
    size_t at;
    GError *err;
} Scan;

void json_position(const Json *j, size_t at, int *line, int *col)
{
    int l = 1, c = 1;
    for (size_t i = 0; i < at && i < j->len; i++) {
        if (j->text[i] == '\n')
            l++, c = 1;
        else
            c++;
    }
    *line = l;
    *col = c;
}

static int scan_error(Scan *S, size_t at, const char *msg)
{
    int line, col;
    json_position(S->j, at, &line, &col);
    return gerror_set(S->err, G_ERR_PARSE, "%s:%d:%d: %s%s", S->path, line, col, msg, S->where);
}

static int push_token(Scan *S, JsonType type, size_t start, size_t end)
{
    Json *j = S->j;
    if (j->n == JSON_MAX_TOKENS)
        return scan_error(S, start, "more than 4194304 JSON values (the limit of a glTF file)");
    if (j->n == j->cap) {
        uint32_t cap = j->cap ? j->cap * 2 : 256;
        JsonTok *t = gmem_realloc(j->tok, (size_t)cap * sizeof *t);
        if (!t)
            return gerror_set(S->err, G_ERR_NOMEM, "%s: out of memory", S->path);
        j->tok = t;
        j->cap = cap;
    }
    j->tok[j->n] = (JsonTok){(uint32_t)start, (uint32_t)end, j->n + 1, 0, (uint8_t)type};
    return (int)j->n++;
}

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
static int is_digit(char c) { return c >= '0' && c <= '9'; }
static int is_hex(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

/* A string from the quote at S->at: its end (after the closing quote) in *end, or an error. */
static int scan_string(Scan *S, size_t *end)
{
    const char *t = S->j->text;
    size_t i = S->at + 1, n = S->j->len;
    while (i < n && t[i] != '"') {
        unsigned char c = (unsigned char)t[i];
        if (c < 0x20)
            return scan_error(S, i, "a control character inside a string");
        if (c == '\\') {
            if (i + 1 >= n)
                break;
            char e = t[i + 1];
            if (e == 'u') {
                for (int k = 2; k < 6; k++)
                    if (i + k >= n || !is_hex(t[i + k]))
                        return scan_error(S, i, "\\u needs four hexadecimal digits");
                i += 6;
                continue;
            }
            if (!strchr("\"\\/bfnrt", e) || e == '\0')
                return scan_error(S, i, "an unknown escape in a string");
            i += 2;
            continue;
        }
        i++;
    }
    if (i >= n)
        return scan_error(S, S->at, "a string without its closing quote");
    *end = i + 1;
    return G_OK;
}

/* A number from S->at (RFC 8259's grammar): its end in *end. */
static int scan_number(Scan *S, size_t *end)
{
    const char *t = S->j->text;
    size_t i = S->at, n = S->j->len;
    if (t[i] == '-')
        i++;
    if (i < n && t[i] == '0')
        i++;
    else if (i < n && is_digit(t[i]))
        while (i < n && is_digit(t[i]))
            i++;
    else
        return scan_error(S, S->at, "a malformed number");
    if (i < n && t[i] == '.') {
        size_t d = ++i;
        while (i < n && is_digit(t[i]))
            i++;
        if (i == d)
            return scan_error(S, S->at, "a malformed number (no digit after the point)");
    }
    if (i < n && (t[i] == 'e' || t[i] == 'E')) {
        i++;
        if (i < n && (t[i] == '+' || t[i] == '-'))
            i++;
        size_t d = i;
        while (i < n && is_digit(t[i]))
            i++;
        if (i == d)
            return scan_error(S, S->at, "a malformed number (no digit in the exponent)");
    }
    *end = i;
    return G_OK;
}

/* A scalar value (string, number, true, false, null) at S->at; returns its token or an error. */
static int scan_scalar(Scan *S)
{
    const char *t = S->j->text + S->at;
    size_t left = S->j->len - S->at, end = S->at;
    int rc;
    if (*t == '"') {
        if ((rc = scan_string(S, &end)) < 0)
            return rc;
        rc = push_token(S, JSON_STRING, S->at + 1, end - 1);
    } else if (*t == '-' || is_digit(*t)) {
        if ((rc = scan_number(S, &end)) < 0)
            return rc;
        rc = push_token(S, JSON_NUMBER, S->at, end);
    } else {
        static const char *const words[] = {"true", "false", "null"};
        size_t k = 0;
        while (k < 3 && !(left >= strlen(words[k]) && memcmp(t, words[k], strlen(words[k])) == 0))
            k++;
        if (k == 3)
            return scan_error(S, S->at, "expected a JSON value");
        end = S->at + strlen(words[k]);
        rc = push_token(S, JSON_LITERAL, S->at, end);
    }
    if (rc >= 0)
        S->at = end;
    return rc;
}

int json_scan(Json *j, const char *path, const char *where, const char *text, size_t len, GError *err)
{
    memset(j, 0, sizeof *j);
    j->text = text;
    j->len = len;
    Scan S = {j, path, where, 0, err};
    if (len > JSON_MAX_BYTES)
        return gerror_set(err, G_ERR_PARSE, "%s: JSON of %zu bytes%s, more than the limit of %u", path, len, where,
                          JSON_MAX_BYTES);
    int stack[JSON_MAX_DEPTH];
    int depth = 0, first = 0, rc = G_OK;
    Want want = WANT_VALUE;
    while (rc >= 0) {
        while (S.at < len && is_space(text[S.at]))
            S.at++;
        if (S.at == len) {
            if (want != WANT_END)
                rc = scan_error(&S, S.at, depth ? "the JSON ends inside an object or array" : "no JSON value");
            break;
        }
        char c = text[S.at];
        int top = depth ? stack[depth - 1] : -1;
        if (want == WANT_END) {
            rc = scan_error(&S, S.at, "text after the JSON value");
        } else if (want == WANT_COLON) {
            if (c != ':')
                rc = scan_error(&S, S.at, "expected ':' after a member's name");
            S.at++;
            want = WANT_VALUE;
        } else if ((want == WANT_NEXT || first) && (c == '}' || c == ']')) {
            if (top < 0 || (c == '}') != (j->tok[top].type == JSON_OBJECT)) {
                rc = scan_error(&S, S.at, c == '}' ? "a '}' closing an array" : "a ']' closing an object");
                break;
            }
            j->tok[top].end = (uint32_t)++S.at;
            j->tok[top].next = j->n;
            depth--;
            first = 0;
            want = depth ? WANT_NEXT : WANT_END;
        } else if (want == WANT_NEXT) {
            if (c != ',') {
                rc = scan_error(&S, S.at,
                                j->tok[top].type == JSON_OBJECT ? "expected ',' or '}'" : "expected ',' or ']'");
                break;
            }
            S.at++;
            want = j->tok[top].type == JSON_OBJECT ? WANT_KEY : WANT_VALUE;
        } else if (want == WANT_KEY) {
            if (c != '"') {
                rc = scan_error(&S, S.at, "expected a member's name (a string)");
                break;
            }
            if ((rc = scan_scalar(&S)) >= 0) {
                j->tok[top].count++;
                first = 0;
                want = WANT_COLON;
            }
        } else if (c == '{' || c == '[') {
            if (depth == JSON_MAX_DEPTH) {
                char msg[96];
                snprintf(msg, sizeof msg, "JSON nested deeper than %d levels (the limit)", JSON_MAX_DEPTH);
                rc = scan_error(&S, S.at, msg);
                break;
            }
            if ((rc = push_token(&S, c == '{' ? JSON_OBJECT : JSON_ARRAY, S.at, S.at + 1)) < 0)
                break;
            if (top >= 0 && j->tok[top].type == JSON_ARRAY)
                j->tok[top].count++;
            stack[depth++] = rc;
            S.at++;
            first = 1;
            want = c == '{' ? WANT_KEY : WANT_VALUE;
        } else {
            if ((rc = scan_scalar(&S)) < 0)
                break;
            if (top >= 0 && j->tok[top].type == JSON_ARRAY)
                j->tok[top].count++;
            first = 0;
            want = depth ? WANT_NEXT : WANT_END;
        }
    }
    if (rc < 0) {
        json_free(j);
        return rc;
    }
    return G_OK;
}

void json_free(Json *j)
{
    gmem_free(j->tok);
    j->tok = NULL;
    j->n = j->cap = 0;
}

int json_get(const Json *j, int obj, const char *key)
{
    if (obj < 0 || j->tok[obj].type != JSON_OBJECT)
        return -1;
    for (uint32_t k = (uint32_t)obj + 1; k < j->tok[obj].next; k = j->tok[k + 1].next)
        if (json_string_is(j, (int)k, key))
            return (int)k + 1;
    return -1;
}

int json_uint(const Json *j, int t, unsigned long long max, unsigned long long *out)
{
    if (t < 0 || j->tok[t].type != JSON_NUMBER)
        return 0;
    unsigned long long v = 0;
    for (uint32_t i = j->tok[t].start; i < j->tok[t].end; i++) {
        char c = j->text[i];
        unsigned d = (unsigned)(c - '0');
        if (!is_digit(c) || d > max || v > (max - d) / 10)
            return 0;
        v = v * 10 + d;
    }
    *out = v;
    return 1;
}

int json_string_is(const Json *j, int t, const char *s)
{
    size_t n = strlen(s);
    return t >= 0 && j->tok[t].type == JSON_STRING && j->tok[t].end - j->tok[t].start == n &&
           memcmp(j->text + j->tok[t].start, s, n) == 0;
}
