/* gen_main.c - fuzz_gen: writes structured inputs for one fuzz target into a directory.
 *
 *   fuzz_gen KIND SEED COUNT DIR [BUDGET]
 *
 * KIND is reader, bfc, image, probe, ies, medium or scene (the targets of tests/fuzz/), or mesh (gtrace's meshes, run
 * by tests/fuzz/run_mesh_generated.sh); input i is DIR/NNN-FAMILY.EXT. The first
 * inputs take each family once at the full BUDGET (bytes, default 4 MiB), the rest a random family at a
 * log-uniform size up to it. Input i depends only on (KIND, SEED, i, BUDGET), so one failing input is
 * reproduced from its name alone. Prints one line per input: path, family, size. */
#include "gen.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct {
    const char *kind;
    const GenFamily *families;
    const int *count;
} kinds[] = {
    {"reader", gen_text_families, &gen_text_count},
    {"bfc", gen_bfc_families, &gen_bfc_count},
    {"image", gen_image_families, &gen_image_count},
    {"probe", gen_probe_families, &gen_probe_count},
    {"mesh", gen_mesh_families, &gen_mesh_count},
    {"ies", gen_ies_families, &gen_ies_count},
    {"medium", gen_medium_families, &gen_medium_count},
    {"scene", gen_scene_families, &gen_scene_count},
};

static int usage(void)
{
    fprintf(stderr, "usage: fuzz_gen reader|bfc|image|probe|mesh|ies|medium|scene SEED COUNT DIR [BUDGET_BYTES]\n");
    return 2;
}

int main(int argc, char **argv)
{
    if (argc < 5 || argc > 6)
        return usage();
    int k = -1;
    for (int i = 0; i < (int)(sizeof kinds / sizeof kinds[0]); i++)
        if (strcmp(argv[1], kinds[i].kind) == 0)
            k = i;
    char *end;
    errno = 0;
    unsigned long long seed = strtoull(argv[2], &end, 10);
    int bad = k < 0 || errno || *end;
    long count = strtol(argv[3], &end, 10);
    bad |= *end || count < 0 || count > 100000;
    unsigned long long budget = argc > 5 ? strtoull(argv[5], &end, 10) : 4u << 20;
    bad |= argc > 5 && (*end || budget < 1024 || budget > (1ull << 30));
    if (bad)
        return usage();
    const GenFamily *fam = kinds[k].families;
    int nf = *kinds[k].count;
    for (long i = 0; i < count; i++) {
        GenRng r = gen_rng(seed, argv[1], (unsigned)i);
        int f = i < nf ? (int)i : (int)gen_below(&r, (uint64_t)nf);
        size_t size = i < nf ? (size_t)budget : (size_t)gen_log(&r, 1024, budget);
        GenBuf b = {0};
        fam[f].make(&b, &r, size);
        char path[4096];
        snprintf(path, sizeof path, "%s/%03ld-%s%s", argv[4], i, fam[f].name, fam[f].ext);
        FILE *out = fopen(path, "wb");
        if (!out || (b.n && fwrite(b.p, 1, b.n, out) != b.n) || fclose(out) != 0) {
            fprintf(stderr, "fuzz_gen: cannot write %s: %s\n", path, strerror(errno));
            free(b.p);
            return 1;
        }
        printf("%s\t%s\t%zu\n", path, fam[f].name, b.n);
        free(b.p);
    }
    return 0;
}
