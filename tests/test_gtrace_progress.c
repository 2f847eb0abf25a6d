/* test_gtrace_progress.c - gtrace's progress estimate and crops: the tiles are taken in a fixed shuffled order,
 * so that the estimate of the time left follows the work even when the costly pixels are all at the bottom of
 * the image (where rendering in order misleads it); when progress lines are due (tests/scripts/gtrace_progress.sh
 * checks the lines themselves); a crop renders pixels bit-identical to the full image's. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

/* The order is a permutation of 0..n-1, the same on every call, and not the identity. */
static void test_tile_order_is_fixed_permutation(void **state)
{
    (void)state;
    const int sizes[] = {1, 2, 7, 100, 4097};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        int n = sizes[k];
        int *a = gmem_alloc((size_t)n * sizeof(int)), *b = gmem_alloc((size_t)n * sizeof(int));
        char *seen = gmem_calloc((size_t)n, 1);
        assert_non_null(a), assert_non_null(b), assert_non_null(seen);
        render_tile_order(n, a);
        render_tile_order(n, b);
        int moved = 0;
        for (int i = 0; i < n; i++) {
            assert_true(a[i] >= 0 && a[i] < n);
            assert_false(seen[a[i]]);
            seen[a[i]] = 1;
            assert_int_equal(a[i], b[i]);
            moved += a[i] != i;
        }
        if (n >= 100)
            assert_true(moved > n / 2);
        gmem_free(a), gmem_free(b), gmem_free(seen);
    }
}

/* The worst error of the time-left estimate, as a fraction of the whole render time, between 20% and 90% of the
 * work, when the tiles cost `cost` seconds each and are taken in `order` (the estimate is progress_remaining on
 * pixels done, as render.c feeds it). */
static double worst_estimate_error(int n, const int *order, const double *cost)
{
    double total = 0.0;
    for (int i = 0; i < n; i++)
        total += cost[i];
    Progress p = {.enabled = 0, .total = (long)n * 256, .done = 0, .start = 0.0};
    double now = 0.0, worst = 0.0;
    for (int i = 0; i < n; i++) {
        now += cost[order[i]];
        p.done += 256; /* a 16x16 tile */
        double f = (double)p.done / (double)p.total;
        if (f < 0.2 || f > 0.9)
            continue;
        double err = fabs(progress_remaining(&p, now) - (total - now)) / total;
        worst = err > worst ? err : worst;
    }
    return worst;
}

static void test_estimate_follows_work(void **state)
{
    (void)state;
    enum { NTX = 40, NTY = 24, N = NTX * NTY };
    int order[N], in_order[N];
    double cost[N];
    for (int t = 0; t < N; t++) { /* the floor: the bottom quarter of the image costs twenty times the rest */
        cost[t] = t / NTX >= NTY * 3 / 4 ? 20.0 : 1.0;
        in_order[t] = t;
    }
    render_tile_order(N, order);
    double shuffled = worst_estimate_error(N, order, cost), sequential = worst_estimate_error(N, in_order, cost);
    print_message("worst error of the time left, 20%%..90%% done: shuffled %.3f, in order %.3f (of the render time)\n",
                  shuffled, sequential);
    assert_true(shuffled < 0.2);
    assert_true(sequential > 0.4); /* the measure sees the problem the shuffle removes */

    Progress p = {.total = 100, .done = 0, .start = 10.0};
    assert_true(progress_remaining(&p, 12.0) < 0.0); /* nothing done: no estimate */
    p.done = 25;
    assert_near(progress_remaining(&p, 12.0), 6.0, 1e-12); /* 2 s for a quarter: 6 s for the rest */
    p.done = 100;
    assert_near(progress_remaining(&p, 20.0), 0.0, 0.0);
}

/* Lines are due after a tenth of the work and the interval, both counted from the last line; the interval comes from
 * GTRACE_PROGRESS_INTERVAL when that is a number in [0, 1e9]. */
static void test_lines_due(void **state)
{
    (void)state;
    Progress p = {.enabled = PROGRESS_LINES, .total = 1000, .done = 0, .start = 0.0, .last = 0.0, .interval = 10.0};
    p.done = 99;
    assert_false(progress_line_due(&p, 1e6)); /* less than a tenth, however long it took */
    p.done = 100;
    assert_false(progress_line_due(&p, 9.99)); /* a tenth, but too soon */
    assert_true(progress_line_due(&p, 10.0));
    p.line_done = 100, p.last = 10.0, p.done = 199;
    assert_false(progress_line_due(&p, 100.0));
    p.done = 200;
    assert_true(progress_line_due(&p, 20.0));
    p.total = 1001, p.done = 100, p.line_done = 0, p.last = 0.0; /* a tenth rounds up */
    assert_false(progress_line_due(&p, 20.0));
    p.done = 101;
    assert_true(progress_line_due(&p, 20.0));

    const char *values[] = {"0", "2.5", "1e9", "", "abc", "-1", "3s", "2e9", NULL};
    const double expect[] = {0.0, 2.5, 1e9, PROGRESS_LINE_INTERVAL, PROGRESS_LINE_INTERVAL, PROGRESS_LINE_INTERVAL,
                             PROGRESS_LINE_INTERVAL, PROGRESS_LINE_INTERVAL, PROGRESS_LINE_INTERVAL};
    for (size_t i = 0; i < sizeof expect / sizeof *expect; i++) {
        if (values[i])
            setenv("GTRACE_PROGRESS_INTERVAL", values[i], 1);
        else
            unsetenv("GTRACE_PROGRESS_INTERVAL");
        assert_near(progress_interval(), expect[i], 0.0);
    }
    assert_near(PROGRESS_LINE_INTERVAL, 10.0, 0.0);
}

/* A crop's pixels are those of the full render, bit for bit, whatever the region and the thread count. */
static void test_crop_matches_full_render(void **state)
{
    (void)state;
    Scene *s = new_scene("rgb", gvec3(0, 1, 4), gvec3(0, 0.5, 0), 40.0);
    add_plane(s, lambert(s, 0.5), gvec3(0, 0, 0), gvec3(0, 1, 0));
    add_sphere(s, glass(s, 1.5), gvec3(0, 0.5, 0), 0.5);
    add_light(s, LIGHT_POINT, 20.0)->position = gvec3(2, 4, 3);
    GError err;
    assert_int_equal(accel_build(s, &err), G_OK);
    RenderSettings rs = {.width = 45, .height = 37, .spp = 3, .depth = 4, .threads = 2, .quiet = 1,
                         .cutoff = s->camera.cutoff};
    Framebuffer full = {0};
    RenderStats st;
    assert_int_equal(render_image(s, &rs, &full, &st, &err), G_OK);
    const int crops[][4] = {{0, 0, 45, 37}, {3, 5, 20, 36}, {17, 0, 45, 1}, {44, 36, 45, 37}, {15, 15, 33, 33}};
    for (size_t k = 0; k < sizeof crops / sizeof crops[0]; k++) {
        RenderSettings rc = rs;
        memcpy(rc.crop, crops[k], sizeof rc.crop);
        rc.threads = 1 + (int)(k % 3);
        Framebuffer fb = {0};
        assert_int_equal(render_image(s, &rc, &fb, &st, &err), G_OK);
        assert_int_equal(fb.width, crops[k][2] - crops[k][0]);
        assert_int_equal(fb.height, crops[k][3] - crops[k][1]);
        assert_int_equal(fb.x, crops[k][0]);
        assert_int_equal(fb.y, crops[k][1]);
        assert_int_equal(fb.full_width, 45);
        assert_int_equal(fb.full_height, 37);
        for (int y = 0; y < fb.height; y++)
            assert_memory_equal(pixel(&fb, 0, y), pixel(&full, crops[k][0], crops[k][1] + y),
                                (size_t)fb.width * 3 * sizeof(float));
        framebuffer_free(&fb);
    }
    /* the comparison can fail: a crop is not the neighbouring region */
    RenderSettings rc = rs;
    memcpy(rc.crop, (int[4]){3, 5, 20, 36}, sizeof rc.crop);
    Framebuffer fb = {0};
    assert_int_equal(render_image(s, &rc, &fb, &st, &err), G_OK);
    int differ = 0;
    for (int y = 0; y < fb.height; y++)
        differ |= memcmp(pixel(&fb, 0, y), pixel(&full, 4, 5 + y), (size_t)fb.width * 3 * sizeof(float)) != 0;
    assert_true(differ);
    framebuffer_free(&fb);
    const int bad[][4] = {{0, 0, 46, 37}, {5, 5, 5, 9}, {10, 3, 2, 9}, {-1, 0, 4, 4}, {0, 0, 45, 38}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        memcpy(rc.crop, bad[k], sizeof rc.crop);
        assert_int_equal(render_image(s, &rc, &fb, &st, &err), G_ERR_INVALID);
        assert_null(fb.pixels);
    }
    framebuffer_free(&full);
    scene_destroy(s);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tile_order_is_fixed_permutation),
        cmocka_unit_test(test_estimate_follows_work),
        cmocka_unit_test(test_lines_due),
        cmocka_unit_test(test_crop_matches_full_render),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
