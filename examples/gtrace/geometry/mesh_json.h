/* mesh_json.h - the JSON scanner behind the glTF pre-check (mesh_json.c): one pass, no recursion, a bounded
 * nesting depth, the document as a flat array of tokens that the check walks before assimp reads the file. */
#ifndef GTRACE_MESH_JSON_H
#define GTRACE_MESH_JSON_H

#include <generic/error.h>

#include <stddef.h>
#include <stdint.h>

/** Deepest nesting of objects and arrays accepted (glTF files nest about 6 levels; assimp's JSON reader recurses). */
#define JSON_MAX_DEPTH 64
/** Most tokens (values and keys) of one document. */
#define JSON_MAX_TOKENS (1u << 22)
/** Largest document in bytes. */
#define JSON_MAX_BYTES (64u << 20)

/** What a token is. */
typedef enum JsonType { JSON_OBJECT, JSON_ARRAY, JSON_STRING, JSON_NUMBER, JSON_LITERAL } JsonType;

/** One value or key: its bytes [start, end) in the text (a string's without its quotes, escapes kept), the index
 * of the token after it and everything inside it, and the number of its members (object) or elements (array). */
typedef struct JsonTok {
    uint32_t start, end, next, count;
    uint8_t type;
} JsonTok;

/** A scanned document; token 0 is its top value. */
typedef struct Json {
    const char *text;
    size_t len;
    JsonTok *tok;
    uint32_t n, cap;
} Json;

/** Scans text (len bytes, at most JSON_MAX_BYTES) as one JSON value followed by white space only, into j (free with
 * json_free). Refuses anything that is not strict JSON (RFC 8259), nesting beyond JSON_MAX_DEPTH and more than
 * JSON_MAX_TOKENS tokens, with "PATH:LINE:COL: message" (where follows the message: "" for a file of JSON,
 * " (in the .glb's JSON chunk)" for a .glb). Returns G_OK, G_ERR_PARSE or G_ERR_NOMEM. */
int json_scan(Json *j, const char *path, const char *where, const char *text, size_t len, GError *err);
/** Releases j's tokens. */
void json_free(Json *j);
/** The 1-based line and column of byte offset at in j's text. */
void json_position(const Json *j, size_t at, int *line, int *col);
/** The value of key in object token obj, -1 when obj is not an object or has no such member. */
int json_get(const Json *j, int obj, const char *key);
/** 1 when token t is a non-negative integer (digits only, no fraction or exponent) of at most max; *out gets it. */
int json_uint(const Json *j, int t, unsigned long long max, unsigned long long *out);
/** 1 when token t is a string whose bytes are s exactly (escapes compared as written). */
int json_string_is(const Json *j, int t, const char *s);

#endif
