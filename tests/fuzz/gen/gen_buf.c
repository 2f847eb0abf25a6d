/* gen_buf.c - the generator's byte buffer and its seeded random numbers (splitmix64). */
#include "gen.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void reserve(GenBuf *b, size_t more)
{
    if (b->n + more <= b->cap)
        return;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + more)
        cap *= 2;
    unsigned char *p = realloc(b->p, cap);
    if (!p) {
        fprintf(stderr, "fuzz_gen: out of memory (%zu bytes)\n", cap);
        exit(2);
    }
    b->p = p;
    b->cap = cap;
}

void gb_put(GenBuf *b, const void *data, size_t size)
{
    reserve(b, size);
    memcpy(b->p + b->n, data, size);
    b->n += size;
}

void gb_byte(GenBuf *b, int c)
{
    unsigned char u = (unsigned char)c;
    gb_put(b, &u, 1);
}

void gb_fill(GenBuf *b, int c, size_t count)
{
    reserve(b, count);
    memset(b->p + b->n, c, count);
    b->n += count;
}

void gb_printf(GenBuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (len <= 0)
        return;
    reserve(b, (size_t)len + 1);
    va_start(ap, fmt);
    vsnprintf((char *)b->p + b->n, (size_t)len + 1, fmt, ap);
    va_end(ap);
    b->n += (size_t)len;
}

void gb_u32be(GenBuf *b, uint32_t v)
{
    unsigned char x[4] = {(unsigned char)(v >> 24), (unsigned char)(v >> 16), (unsigned char)(v >> 8),
                          (unsigned char)v};
    gb_put(b, x, 4);
}

void gb_u32le(GenBuf *b, uint32_t v)
{
    unsigned char x[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16),
                          (unsigned char)(v >> 24)};
    gb_put(b, x, 4);
}

uint64_t gen_next(GenRng *r)
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

GenRng gen_rng(uint64_t seed, const char *kind, unsigned index)
{
    uint64_t h = 1469598103934665603ull; /* FNV-1a of the kind, mixed with the seed and the index */
    for (const char *k = kind; *k; k++)
        h = (h ^ (unsigned char)*k) * 1099511628211ull;
    GenRng r = {h ^ (seed * 0x9e3779b97f4a7c15ull) ^ ((uint64_t)index << 32)};
    gen_next(&r);
    return r;
}

uint64_t gen_below(GenRng *r, uint64_t n) { return n ? gen_next(r) % n : 0; }

double gen_unit(GenRng *r) { return (double)(gen_next(r) >> 11) * 0x1.0p-53; }

uint64_t gen_log(GenRng *r, uint64_t lo, uint64_t hi)
{
    if (lo < 1)
        lo = 1;
    if (hi <= lo)
        return lo;
    double v = exp(log((double)lo) + gen_unit(r) * (log((double)hi + 1.0) - log((double)lo)));
    uint64_t x = (uint64_t)v;
    return x < lo ? lo : x > hi ? hi : x;
}

const char *gen_pick(GenRng *r, const char *const *choices, size_t n) { return choices[gen_below(r, n)]; }
