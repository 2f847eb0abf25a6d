/* test_gtrace_photon_share.c - how the particle integrators share their photon batches between the ranks of an MPI
 * job (integrators/photons.h): the ranges of paths cover a batch exactly once, a packed range unpacks into the same
 * bits, and a pack that is cut, lengthened, or holds a count or colour kind out of range is refused. */
#include "test_gtrace_common.h"
#include "integrators/photons.h"
#include "generic/builtins.h"

/* Ranges of 1..6 parts of n paths: consecutive, from 0 to n, sizes within one of each other. */
static void test_ranges_cover(void **state)
{
    (void)state;
    const int ns[] = {0, 1, 5, 7, 100, 48131};
    for (size_t t = 0; t < sizeof ns / sizeof ns[0]; t++)
        for (int parts = 1; parts <= 6; parts++) {
            int next = 0, smallest = ns[t], largest = 0;
            for (int part = 0; part < parts; part++) {
                int lo, hi;
                photon_share_range(ns[t], part, parts, &lo, &hi);
                assert_int_equal(lo, next);
                assert_true(hi >= lo);
                smallest = hi - lo < smallest ? hi - lo : smallest;
                largest = hi - lo > largest ? hi - lo : largest;
                next = hi;
            }
            assert_int_equal(next, ns[t]);
            assert_true(largest - smallest <= 1);
        }
}

/* A batch of 5 paths of at most 3 particles in model m, each field of each particle distinct. */
static void fill(PhotonBatch *b, const GColorModel *m)
{
    GError err;
    assert_int_equal(photon_batch_init(b, m, 5, 3, &err), G_OK);
    const int counts[5] = {0, 2, 1, 3, 0};
    int floats = (int)(gcolormodel_value_bytes(m) / sizeof(float));
    for (int i = 0; i < b->paths; i++) {
        b->count[i] = counts[i];
        for (int k = 0; k < b->per_path; k++) {
            Photon *ph = &b->photons[i * b->per_path + k];
            double u = i * 10 + k + 0.125;
            ph->p = (GVec3){u, -u, 1.0 / u};
            ph->wi = (GVec3){0.6, 0.0, -0.8};
            ph->pixel = i == 1 ? -1 : i * 1000 + k;
            for (int c = 0; c < floats; c++)
                ph->power.v[c] = (float)(u + 0.001 * c);
        }
    }
}

/* Packs paths [1, 4) of a batch and unpacks them into another: every stored particle equal, bit for bit. */
static void test_pack_round_trip(void **state)
{
    (void)state;
    GError err;
    GColorModel *m = NULL;
    assert_int_equal(generic_register_builtins(&err), G_OK);
    const char *models[] = {"rgb", "spectrum"};
    for (size_t t = 0; t < 2; t++) {
        assert_int_equal(gcolormodel_create(models[t], NULL, &m, &err), G_OK);
        PhotonBatch a, b;
        fill(&a, m);
        assert_int_equal(photon_batch_init(&b, m, 5, 3, &err), G_OK);
        size_t cap = photon_batch_pack_bytes(&a, m, 1, 4);
        unsigned char *buf = malloc(cap);
        assert_non_null(buf);
        size_t len = photon_batch_pack(&a, 1, 4, buf);
        assert_true(len > 0 && len <= cap);
        assert_int_equal(photon_batch_unpack(&b, 1, 4, buf, len), G_OK);
        for (int i = 1; i < 4; i++) {
            assert_int_equal(b.count[i], a.count[i]);
            for (int k = 0; k < a.count[i]; k++) {
                const Photon *p = &a.photons[i * 3 + k], *q = &b.photons[i * 3 + k];
                assert_memory_equal(&p->p, &q->p, sizeof p->p);
                assert_memory_equal(&p->wi, &q->wi, sizeof p->wi);
                assert_int_equal(p->pixel, q->pixel);
                assert_int_equal(p->power.kind, q->power.kind);
                assert_memory_equal(p->power.v, q->power.v, gcolormodel_value_bytes(m));
            }
        }
        /* refused: cut short, one byte too many, a count beyond per_path, an unknown colour kind */
        assert_int_equal(photon_batch_unpack(&b, 1, 4, buf, len - 1), G_ERR_INVALID);
        unsigned char *longer = malloc(len + 1);
        assert_non_null(longer);
        memcpy(longer, buf, len);
        longer[len] = 0;
        assert_int_equal(photon_batch_unpack(&b, 1, 4, longer, len + 1), G_ERR_INVALID);
        free(longer);
        int32_t bad = 4;
        memcpy(buf, &bad, sizeof bad); /* path 1's count */
        assert_int_equal(photon_batch_unpack(&b, 1, 4, buf, len), G_ERR_INVALID);
        photon_batch_pack(&a, 1, 4, buf);
        size_t kind_at = sizeof(int32_t) + 6 * sizeof(double) + sizeof(int64_t); /* path 1's first particle */
        bad = 7;
        memcpy(buf + kind_at, &bad, sizeof bad);
        assert_int_equal(photon_batch_unpack(&b, 1, 4, buf, len), G_ERR_INVALID);
        free(buf);
        photon_batch_free(&a);
        photon_batch_free(&b);
        gcolormodel_destroy(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ranges_cover),
        cmocka_unit_test(test_pack_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
