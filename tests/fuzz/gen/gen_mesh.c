/* gen_mesh.c - mesh files that attack the readers behind gtrace's `object mesh` (examples/gtrace/geometry/): glTF
 * whose JSON nests deeply (inside "extras"), whose nodes nest deeply or form a DAG that expands to 2^levels
 * placements, whose accessors claim more elements than their views hold; .glb files whose header and chunk lengths
 * lie; PLY content under a glTF name, truncated or claiming huge counts. Every input is wrong by construction
 * (refused), except that a DAG or chain within the bounds may load: they carry no GEN_MUST_FAIL mark (JSON has no
 * comments; the harness refuses or loads, never crashes, hangs or exceeds its memory). The fault-* families are a
 * legal PLY whose name makes gtrace's mesh reader process crash or spin (GENERIC_DECODE_FAULT=by-name, set by
 * run_mesh_generated.sh): gtrace must refuse the file, naming how its reader ended (a reader that grows to its
 * address space limit is tests/test_gtrace_mesh_isolation.c's: it touches a GiB and more). */
#include "gen.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The 9 floats (0,0,0, 1,0,0, 0,1,0) in base64: one triangle. */
#define GEN_TRI_B64 "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"

/* A glTF's start up to its nodes array's '[' (the nodes follow, then gltf_tail). */
static void gltf_head(GenBuf *b)
{
    gb_printf(b, "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[");
}

/* After the nodes: one mesh of one triangle from a data: URI, count elements claimed, then extra before the '}'. */
static void gltf_tail(GenBuf *b, uint64_t count, const char *extra)
{
    gb_printf(b, "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                 "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64," GEN_TRI_B64 "\"}],"
                 "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                 "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%llu,\"type\":\"VEC3\"}]%s}\n",
              (unsigned long long)count, extra);
}

/* JSON nested as deep as the budget allows inside "extras" (arrays or objects). */
static void gltf_nested_json(GenBuf *b, GenRng *r, size_t budget)
{
    int objects = gen_below(r, 2) == 0;
    size_t depth = budget > 1024 ? (budget - 512) / (objects ? 6 : 2) : 100;
    gltf_head(b);
    gb_printf(b, "{\"mesh\":0}");
    gltf_tail(b, 3, "");
    b->n -= 2; /* "}\n" */
    gb_printf(b, ",\"extras\":");
    for (size_t i = 0; i < depth; i++)
        gb_printf(b, "%s", objects ? "{\"a\":" : "[");
    gb_printf(b, "0");
    for (size_t i = 0; i < depth; i++)
        gb_byte(b, objects ? '}' : ']');
    gb_printf(b, "}\n");
}

/* Nodes nested in a chain as long as the budget allows (each node's one child is the next). */
static void gltf_node_chain(GenBuf *b, GenRng *r, size_t budget)
{
    size_t n = budget / 16 > 2 ? budget / 16 : 2;
    if (gen_below(r, 4) == 0)
        n = 200 + gen_below(r, 100); /* around the depth limit */
    gltf_head(b);
    for (size_t i = 0; i + 1 < n; i++)
        gb_printf(b, "{\"children\":[%zu]},", i + 1);
    gb_printf(b, "{\"mesh\":0}");
    gltf_tail(b, 3, "");
}

/* Nodes as a DAG: each level names the next k times, for levels levels (k^levels placements), sometimes with a
 * cycle back to the root. */
static void gltf_dag(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    int levels = 2 + (int)gen_below(r, 60), k = 2 + (int)gen_below(r, 3), cycle = gen_below(r, 5) == 0;
    gltf_head(b);
    for (int i = 0; i < levels; i++) {
        gb_printf(b, "{\"children\":[");
        for (int j = 0; j < k; j++)
            gb_printf(b, "%s%d", j ? "," : "", i + 1);
        gb_printf(b, "]},");
    }
    gb_printf(b, cycle ? "{\"mesh\":0,\"children\":[0]}" : "{\"mesh\":0}");
    gltf_tail(b, 3, "");
}

/* An accessor claiming up to 2^40 elements over a 36-byte view. */
static void gltf_accessor_lie(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    gltf_head(b);
    gb_printf(b, "{\"mesh\":0}");
    gltf_tail(b, gen_log(r, 4, 1ull << 40), "");
}

/* A .glb whose total length, JSON chunk or BIN chunk claims more than the file holds (up to 4 GiB). */
static void glb_chunk_lie(GenBuf *b, GenRng *r, size_t budget)
{
    GenBuf json = {0};
    gltf_head(&json);
    gb_printf(&json, "{\"mesh\":0}");
    gltf_tail(&json, 3, "");
    while (json.n % 4)
        gb_byte(&json, ' ');
    size_t pad = budget > json.n + 64 ? gen_below(r, budget - json.n - 64) & ~(size_t)3 : 0;
    int lie = (int)gen_below(r, 3);
    uint32_t big = (uint32_t)gen_log(r, budget + 1, 0xffffffffu);
    uint32_t total = (uint32_t)(12 + 8 + json.n + pad + 8 + 36);
    gb_put(b, "glTF", 4);
    gb_u32le(b, 2);
    gb_u32le(b, lie == 0 ? big : total);
    gb_u32le(b, lie == 1 ? big : (uint32_t)(json.n + pad));
    gb_put(b, "JSON", 4);
    gb_put(b, json.p, json.n);
    gb_fill(b, ' ', pad);
    gb_u32le(b, lie == 2 ? big : 36);
    gb_put(b, "BIN\0", 4);
    gb_fill(b, 0, 36);
    free(json.p);
}

/* PLY content (named .gltf by the family's extension): a header cut anywhere, or counts far beyond the body. */
static void ply_renamed(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    GenBuf h = {0};
    gb_printf(&h, "ply\nformat %s 1.0\nelement vertex %llu\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face %llu\nproperty list uchar int vertex_indices\nend_header\n",
              gen_below(r, 2) ? "ascii" : "binary_little_endian", (unsigned long long)gen_log(r, 3, 1ull << 40),
              (unsigned long long)gen_log(r, 1, 1ull << 40));
    size_t cut = gen_below(r, 2) ? gen_below(r, h.n) : h.n;
    gb_put(b, h.p, cut);
    if (cut == h.n)
        gb_printf(b, "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    free(h.p);
}

/* A legal PLY triangle: the family's name (fault-crash, ...) is what fails, in the reader process. */
static void reader_fault(GenBuf *b, GenRng *r, size_t budget)
{
    (void)r, (void)budget;
    gb_printf(b, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
}

const GenFamily gen_mesh_families[] = {
    {"gltf-nested-json", ".gltf", gltf_nested_json}, {"gltf-node-chain", ".gltf", gltf_node_chain},
    {"gltf-dag", ".gltf", gltf_dag},                 {"gltf-accessor-lie", ".gltf", gltf_accessor_lie},
    {"glb-chunk-lie", ".glb", glb_chunk_lie},        {"ply-renamed", ".gltf", ply_renamed},
    {"fault-crash", ".ply", reader_fault},           {"fault-spin", ".ply", reader_fault},
};
const int gen_mesh_count = (int)(sizeof gen_mesh_families / sizeof gen_mesh_families[0]);
