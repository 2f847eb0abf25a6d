/* gen.h - the structure-aware input generator of `make fuzz` (tests/fuzz/gen/): a byte buffer, a seeded random
 * number generator and the families of inputs each kind of input has. A family writes one input of about the
 * budget's size (never much more); the same seed, kind and index give the same bytes on every machine.
 *
 *   gen_text.c   the text format: long CSG/CPG operand lists, deep nesting, reference chains, self-blending
 *                towers, wide DAGs, many entries, extreme numbers, long tokens, control bytes and BOMs, textured
 *                parameters (generators with extreme or reversed ranges, mixes and images where numbers and
 *                colours go, generators where a number must stay constant)
 *   gen_bfc.c    BFC-450 matrices: long tokens, far and huge grids, rows that lie about their length
 *   gen_image.c  PNG, HDR, PFM, EXR and PPM files whose headers claim huge sizes over truncated bodies, and
 *                mutated IFF and DPX headers named .png, .hdr or .pfm
 *                (and, for the probe kind, HDR and PFM only, with probe-like aspect ratios)
 *   gen_mesh.c   glTF nested deeply (JSON, nodes), node DAGs, lying accessors and .glb chunks, renamed PLY,
 *                mesh reader processes that crash or spin
 *                (gtrace's meshes: tests/fuzz/run_mesh_generated.sh)
 *   gen_ies.c    IES LM-63 files: lying counts, truncation, NaN and words, bad angle tables, long headers
 *   gen_medium.c gtrace's medium and phase entries: bounds crossed, references, long chains
 *   gen_scene.c  gtrace's scene files: many objects and lights, long transform chains, wide and deep groups,
 *                include chains and cycles and lying meshes (files of the input), huge cameras, extreme numbers */
#ifndef GENERIC_TESTS_FUZZ_GEN_H
#define GENERIC_TESTS_FUZZ_GEN_H

#include <stddef.h>
#include <stdint.h>

/** A growing byte buffer; out of memory ends the program (the generator has nothing else to do then). */
typedef struct GenBuf {
    unsigned char *p;
    size_t n, cap;
} GenBuf;

/** Appends size bytes. */
void gb_put(GenBuf *b, const void *data, size_t size);
/** Appends one byte. */
void gb_byte(GenBuf *b, int c);
/** Appends a formatted string (without its NUL). */
void gb_printf(GenBuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/** Appends count copies of the byte c. */
void gb_fill(GenBuf *b, int c, size_t count);
/** Appends a 32-bit value, big- or little-endian. */
void gb_u32be(GenBuf *b, uint32_t v);
void gb_u32le(GenBuf *b, uint32_t v);

/** The random number generator (splitmix64). */
typedef struct GenRng {
    uint64_t s;
} GenRng;

/** A generator for input `index` of `kind` under `seed` (independent of every other input). */
GenRng gen_rng(uint64_t seed, const char *kind, unsigned index);
uint64_t gen_next(GenRng *r);
/** Uniform in [0, n) (0 when n is 0). */
uint64_t gen_below(GenRng *r, uint64_t n);
/** Uniform in [0, 1). */
double gen_unit(GenRng *r);
/** Log-uniform integer in [lo, hi]. */
uint64_t gen_log(GenRng *r, uint64_t lo, uint64_t hi);
/** One of the n strings. */
const char *gen_pick(GenRng *r, const char *const *choices, size_t n);
#define GEN_PICK(r, array) gen_pick((r), (array), sizeof(array) / sizeof(array)[0])

/** The mark of an input that is wrong by construction (a row one value short, a token over the limit, a grid
 * claiming more than the file holds): written into a comment of the input, it tells the harness in large mode
 * that a successful load is a silent wrong success (tests/fuzz/fuzz_entry.h). */
#define GEN_MUST_FAIL "gfuzz: must be refused"

/** One family: writes an input of at most about budget bytes into out. */
typedef struct GenFamily {
    const char *name;
    const char *ext;
    void (*make)(GenBuf *out, GenRng *r, size_t budget);
} GenFamily;

/** Writes one extreme number (gen_numbers.c): an edge of double, float or an integer type, or a plain one. */
void gen_text_extreme(GenBuf *b, GenRng *r);
/** The reader's extreme-numbers family (gen_numbers.c): entries whose numbers are the extremes of every type. */
void gen_text_extreme_numbers(GenBuf *b, GenRng *r, size_t budget);
/** The families of each kind, and how many there are. */
extern const GenFamily gen_text_families[];
extern const int gen_text_count;
extern const GenFamily gen_bfc_families[];
extern const int gen_bfc_count;
extern const GenFamily gen_image_families[];
extern const int gen_image_count;
extern const GenFamily gen_probe_families[];
extern const int gen_probe_count;
extern const GenFamily gen_mesh_families[];
extern const int gen_mesh_count;
extern const GenFamily gen_ies_families[];
extern const int gen_ies_count;
extern const GenFamily gen_medium_families[];
extern const int gen_medium_count;
extern const GenFamily gen_scene_families[];
extern const int gen_scene_count;

#endif
