/* test_lexer.c - tokens of the text format: every token type with its position, comments, escapes, numbers
 * (and the refusal of NaN, infinity and malformed numbers), unterminated strings, stray characters. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>

#include <string.h>

#include "reader/lexer.h"

typedef struct Lexed {
    GLexer lx;
    GLexToken t;
    GError err;
} Lexed;

static void start(Lexed *l, const char *text)
{
    glexer_init(&l->lx, "t.mat", text, strlen(text));
    gerror_clear(&l->err);
}

static void expect(Lexed *l, int type, const char *text, int line, int col)
{
    assert_int_equal(glexer_next(&l->lx, &l->t, &l->err), G_OK);
    assert_int_equal(l->t.tok.type, type);
    if (text)
        assert_string_equal(l->t.tok.text, text);
    assert_int_equal(l->t.tok.line, line);
    assert_int_equal(l->t.tok.col, col);
}

static void expect_error(const char *text, const char *message)
{
    Lexed l;
    start(&l, text);
    int rc;
    do
        rc = glexer_next(&l.lx, &l.t, &l.err);
    while (rc == G_OK && l.t.tok.type != GTOK_EOF);
    assert_int_equal(rc, G_ERR_PARSE);
    assert_string_equal(l.err.message, message);
}

/* Every number is read as strtod reads it, bit for bit, whether or not the lexer's exact shortcut takes it: decimals
 * of 1 to 19 significant digits, with and without exponents (the shortcut's bounds, 15 digits and |e| <= 22, and
 * either side of them), signs, leading and trailing zeros. */
static void test_numbers_match_strtod(void **state)
{
    (void)state;
    uint64_t x = 88172645463325252ull;
    char text[64];
    for (int i = 0; i < 200000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        int digits = 1 + (int)(x % 19), point = (int)((x >> 8) % (unsigned)(digits + 2)) - 1;
        int zeros = (int)((x >> 16) % 4), exp = (int)((x >> 24) % 61) - 30, form = (int)((x >> 32) % 4);
        size_t n = 0;
        if (form == 1)
            text[n++] = '-';
        for (int k = 0; k < zeros; k++)
            text[n++] = '0';
        uint64_t y = x * 2862933555777941757ull + 3037000493ull;
        for (int k = 0; k < digits; k++) {
            if (k == point)
                text[n++] = '.';
            text[n++] = (char)('0' + (y >> 60) % 10);
            y = y * 2862933555777941757ull + 3037000493ull;
        }
        if (form >= 2)
            n += (size_t)snprintf(text + n, sizeof text - n, "e%d", exp);
        text[n] = '\0';
        Lexed l;
        start(&l, text);
        assert_int_equal(glexer_next(&l.lx, &l.t, &l.err), G_OK);
        assert_int_equal(l.t.tok.type, GTOK_NUMBER);
        double want = strtod(text, NULL);
        if (memcmp(&l.t.tok.number, &want, sizeof want) != 0)
            print_error("%s: lexer %.17g, strtod %.17g\n", text, l.t.tok.number, want);
        assert_memory_equal(&l.t.tok.number, &want, sizeof want);
    }
}

static void test_tokens_and_positions(void **state)
{
    (void)state;
    Lexed l;
    start(&l, "material wall lambert {\n  reflectance <0.5, 1e-1, -2>  # comment\n\t\"a \\\"q\\\" \\\\ b\" }\n");
    expect(&l, GTOK_IDENT, "material", 1, 1);
    expect(&l, GTOK_IDENT, "wall", 1, 10);
    expect(&l, GTOK_IDENT, "lambert", 1, 15);
    expect(&l, GTOK_LBRACE, "{", 1, 23);
    expect(&l, GTOK_IDENT, "reflectance", 2, 3);
    expect(&l, GTOK_LANGLE, "<", 2, 15);
    expect(&l, GTOK_NUMBER, "0.5", 2, 16);
    assert_true(l.t.tok.number == 0.5);
    expect(&l, GTOK_COMMA, ",", 2, 19);
    expect(&l, GTOK_NUMBER, "1e-1", 2, 21);
    assert_true(l.t.tok.number == 0.1);
    expect(&l, GTOK_COMMA, ",", 2, 25);
    expect(&l, GTOK_NUMBER, "-2", 2, 27);
    assert_true(l.t.tok.number == -2.0);
    expect(&l, GTOK_RANGLE, ">", 2, 29);
    expect(&l, GTOK_STRING, "a \"q\" \\ b", 3, 2);
    expect(&l, GTOK_RBRACE, "}", 3, 17);
    expect(&l, GTOK_EOF, NULL, 4, 1);
    expect(&l, GTOK_EOF, NULL, 4, 1); /* stays at the end */
}

static void test_numbers(void **state)
{
    (void)state;
    Lexed l;
    start(&l, ".5 +3 -.25 7. 1E3 0.000001 name-with.dots_1");
    expect(&l, GTOK_NUMBER, ".5", 1, 1);
    assert_true(l.t.tok.number == 0.5);
    expect(&l, GTOK_NUMBER, "+3", 1, 4);
    assert_true(l.t.tok.number == 3.0);
    expect(&l, GTOK_NUMBER, "-.25", 1, 7);
    assert_true(l.t.tok.number == -0.25);
    expect(&l, GTOK_NUMBER, "7.", 1, 12);
    expect(&l, GTOK_NUMBER, "1E3", 1, 15);
    assert_true(l.t.tok.number == 1000.0);
    expect(&l, GTOK_NUMBER, "0.000001", 1, 19);
    expect(&l, GTOK_IDENT, "name-with.dots_1", 1, 28);
}

static void test_crlf_and_comments(void **state)
{
    (void)state;
    Lexed l;
    start(&l, "# only a comment\r\n  a\r\n#x\r\n b # trailing");
    expect(&l, GTOK_IDENT, "a", 2, 3);
    expect(&l, GTOK_IDENT, "b", 4, 2);
    expect(&l, GTOK_EOF, NULL, 4, 14);
}

static void test_errors(void **state)
{
    (void)state;
    expect_error("a \"open\nb\"", "t.mat:1:3: unterminated string (a string ends on the line it starts)");
    expect_error("\n  \"never closed", "t.mat:2:3: unterminated string (a string ends on the line it starts)");
    expect_error("\"bad \\q\"", "t.mat:1:6: unknown escape '\\' followed by 'q' in string");
    expect_error("x 1.2.3", "t.mat:1:3: bad number '1.2.3'");
    expect_error("12abc", "t.mat:1:1: bad number '12abc'");
    expect_error("1e", "t.mat:1:1: bad number '1e'");
    expect_error("0x10", "t.mat:1:1: bad number '0x10'");
    expect_error("-inf", "t.mat:1:1: '-inf' is not allowed: numbers must be finite");
    expect_error("+nan", "t.mat:1:1: '+nan' is not allowed: numbers must be finite");
    expect_error("1e999", "t.mat:1:1: number '1e999' is out of range");
    expect_error("a ; b", "t.mat:1:3: unexpected character ';'");
    expect_error("a\n @", "t.mat:2:2: unexpected character '@'");
    char nul[] = "ab\0c";
    Lexed l;
    glexer_init(&l.lx, "t.mat", nul, 4);
    assert_int_equal(glexer_next(&l.lx, &l.t, &l.err), G_OK);
    assert_int_equal(glexer_next(&l.lx, &l.t, &l.err), G_ERR_PARSE);
    assert_string_equal(l.err.message, "t.mat:1:3: unexpected character byte 0x00");
}

static void test_long_token(void **state)
{
    (void)state;
    static char text[GLEX_TEXT_MAX + 16];
    memset(text, 'a', GLEX_TEXT_MAX + 8);
    text[GLEX_TEXT_MAX + 8] = '\0';
    expect_error(text, "t.mat:1:1: name longer than 4095 bytes");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tokens_and_positions),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_numbers_match_strtod),
        cmocka_unit_test(test_crlf_and_comments),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_long_token),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
