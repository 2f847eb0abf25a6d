/* sampler.c - sample values for the path tracer: shuffled, Owen-scrambled Sobol points (Burley, "Practical
 * Hash-based Owen Scrambling", JCGT 9(4), 2020), four dimensions a group.
 *
 * The Sobol sequence's first four dimensions are generated from their direction numbers (Joe and Kuo's published
 * primitive polynomials and initial numbers; the table below is their recurrence, which the tests redo). Each
 * group of four dimensions of a pixel's samples shuffles the sample index by a nested uniform scramble seeded by
 * the pixel and the group: that maps the first 2^m indices onto one aligned block of 2^m Sobol points, which keeps
 * the block's stratification, and decorrelates groups and pixels. Each coordinate is then Owen-scrambled with its
 * own seed. The scramble is a hash on the bit-reversed value whose every step carries only from lower to higher
 * bits (adding, multiplying by an odd number, xor with a multiple of an even number): each output bit depends on
 * the input bits above it only, which is a nested uniform scramble when the hash is good. The hash's steps are
 * Vegdahl's refinement ("Building a better LK hash", 2021) of Laine and Karras's. */
#include "sampler.h"
#include "camera/rng.h"

/* The direction numbers v_1 .. v_32 of dimensions 0 .. 3 as 32-bit fractions: v_k = m_k / 2^k, the m_k from
 * m_1 .. m_s and the recurrence of the dimension's primitive polynomial of degree s (Bratley and Fox). */
static const uint32_t SOBOL_V[4][32] = {
    {0x80000000u, 0x40000000u, 0x20000000u, 0x10000000u, 0x08000000u, 0x04000000u, 0x02000000u, 0x01000000u,
     0x00800000u, 0x00400000u, 0x00200000u, 0x00100000u, 0x00080000u, 0x00040000u, 0x00020000u, 0x00010000u,
     0x00008000u, 0x00004000u, 0x00002000u, 0x00001000u, 0x00000800u, 0x00000400u, 0x00000200u, 0x00000100u,
     0x00000080u, 0x00000040u, 0x00000020u, 0x00000010u, 0x00000008u, 0x00000004u, 0x00000002u, 0x00000001u},
    {0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u, 0xaa000000u, 0xff000000u,
     0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u, 0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u,
     0x80008000u, 0xc000c000u, 0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u,
     0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu, 0xaaaaaaaau, 0xffffffffu},
    {0x80000000u, 0xc0000000u, 0x60000000u, 0x90000000u, 0xe8000000u, 0x5c000000u, 0x8e000000u, 0xc5000000u,
     0x68800000u, 0x9cc00000u, 0xee600000u, 0x55900000u, 0x80680000u, 0xc09c0000u, 0x60ee0000u, 0x90550000u,
     0xe8808000u, 0x5cc0c000u, 0x8e606000u, 0xc5909000u, 0x6868e800u, 0x9c9c5c00u, 0xeeee8e00u, 0x5555c500u,
     0x8000e880u, 0xc0005cc0u, 0x60008e60u, 0x9000c590u, 0xe8006868u, 0x5c009c9cu, 0x8e00eeeeu, 0xc5005555u},
    {0x80000000u, 0xc0000000u, 0x20000000u, 0x50000000u, 0xf8000000u, 0x74000000u, 0xa2000000u, 0x93000000u,
     0xd8800000u, 0x25400000u, 0x59e00000u, 0xe6d00000u, 0x78080000u, 0xb40c0000u, 0x82020000u, 0xc3050000u,
     0x208f8000u, 0x51474000u, 0xfbea2000u, 0x75d93000u, 0xa0858800u, 0x914e5400u, 0xdbe79e00u, 0x25db6d00u,
     0x58800080u, 0xe54000c0u, 0x79e00020u, 0xb6d00050u, 0x800800f8u, 0xc00c0074u, 0x200200a2u, 0x50050093u},
};

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

/* The points bit-reversed, a byte of the index at a time: SOBOL_BYTES[d][b][v] is the xor of the reversed direction
 * numbers of dimension d selected by the bits of v at byte b of the index (a shuffled index has all 32 bits set at
 * random, so the sum over its bits is four table reads). Made once, before main (a constructor: no thread can race
 * it). */
static uint32_t SOBOL_BYTES[4][4][256];

__attribute__((constructor)) static void sobol_bytes_make(void)
{
    for (int d = 0; d < 4; d++)
        for (int b = 0; b < 4; b++)
            for (int v = 0; v < 256; v++) {
                uint32_t x = 0;
                for (int k = 0; k < 8; k++)
                    if (v & (1 << k))
                        x ^= reverse_bits(SOBOL_V[d][8 * b + k]);
                SOBOL_BYTES[d][b][v] = x;
            }
}

/* The point `index` of dimension d, bit-reversed. */
static uint32_t sobol_reversed(uint32_t index, int d)
{
    const uint32_t(*t)[256] = SOBOL_BYTES[d & 3];
    return t[0][index & 255u] ^ t[1][(index >> 8) & 255u] ^ t[2][(index >> 16) & 255u] ^ t[3][index >> 24];
}

uint32_t sobol_bits(uint32_t index, int d)
{
    return reverse_bits(sobol_reversed(index, d));
}

/* The hash of owen_scramble on a bit-reversed value: each output bit depends on the input bits below it. */
static uint32_t lk_hash(uint32_t x, uint32_t seed)
{
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

uint32_t owen_scramble(uint32_t v, uint32_t seed)
{
    /* the fraction's leading bit at the bottom: carries go from it downwards */
    return reverse_bits(lk_hash(reverse_bits(v), seed));
}

SamplePoint sample_point(uint64_t pixel, uint32_t index)
{
    return (SamplePoint){.pixel_seed = rng_mix64(pixel ^ 0x6a09e667f3bcc909ULL), .index = index};
}

SampleGroup sample_group(const SamplePoint *p, uint32_t group)
{
    uint64_t a = rng_mix64(p->pixel_seed ^ rng_mix64((uint64_t)group));
    /* the index shuffled by the same scramble: each bit flipped by the bits above it, so the pixel's first 2^m
     * samples (the bits above m all 0) stay one aligned block of 2^m points, permuted */
    return (SampleGroup){.group = group, .index = owen_scramble(p->index, (uint32_t)a),
                         .seed = {(uint32_t)rng_mix64(a + 1), (uint32_t)rng_mix64(a + 2), (uint32_t)rng_mix64(a + 3),
                                  (uint32_t)rng_mix64(a + 4)}};
}

double sample_group_value(const SampleGroup *g, int d)
{
    return reverse_bits(lk_hash(sobol_reversed(g->index, d), g->seed[d & 3])) * (1.0 / 4294967296.0);
}

double sample_value(const SamplePoint *p, uint32_t dim)
{
    SampleGroup g = sample_group(p, dim / SAMPLER_GROUP_DIMS);
    return sample_group_value(&g, (int)(dim % SAMPLER_GROUP_DIMS));
}
