/* test_gtrace_embed.c - gtrace as a function (embed/render_file.h, what libgtrace.so exports for bindings): the
 * image of a scene file with the command line's settings, its size from the camera's aspect, a crop equal to the
 * same region of the full render bit for bit, the settings refused and errors placed in the file. */
#include "test_gtrace_common.h"

#include "embed/render_file.h"

static const char scene_text[] =
    "colormodel rgb\n"
    "camera pinhole { from <0, 1.5, 4> at <0, 0.4, 0> fov 40 width 40 height 30 spp 2 depth 2 }\n"
    "light point { position <-3, 5, 4> intensity rgb 40 40 40 }\n"
    "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.6 0.6 0.55 } }\n"
    "object sphere { center <0, 0.6, 0> radius 0.6 material phong { diffuse rgb 0.6 0.1 0.1 specular rgb 0.3 0.3 "
    "0.3 } }\n";

static void test_render_and_crop(void **state)
{
    (void)state;
    const char *path = write_text("embed.scene", scene_text);
    GtraceRenderRequest rq = {.scene = path, .width = 48, .depth = -1, .threads = 2};
    GtraceImage full, crop;
    GError err;
    assert_int_equal(gtrace_render_file(&rq, &full, &err), G_OK);
    assert_int_equal(full.width, 48);
    assert_int_equal(full.height, 36); /* the camera's 4:3 */
    double sum = 0;
    for (int i = 0; i < 3 * full.width * full.height; i++)
        sum += full.pixels[i];
    assert_true(sum > 10.0);
    int box[4] = {5, 7, 30, 20};
    memcpy(rq.crop, box, sizeof box);
    rq.threads = 1;
    assert_int_equal(gtrace_render_file(&rq, &crop, &err), G_OK);
    assert_int_equal(crop.width, 25);
    assert_int_equal(crop.height, 13);
    assert_int_equal(crop.x, 5);
    assert_int_equal(crop.full_width, 48);
    for (int y = 0; y < crop.height; y++)
        assert_memory_equal(crop.pixels + 3 * y * crop.width, full.pixels + 3 * ((y + 7) * full.width + 5),
                            3 * sizeof(float) * (size_t)crop.width);
    gtrace_image_free(&full);
    gtrace_image_free(&crop);
    gtrace_image_free(&crop); /* cleared: a no-op */
    gtrace_image_free(NULL);
}

static void test_errors(void **state)
{
    (void)state;
    GtraceImage img;
    GError err;
    const char *bad = write_text("embed_bad.scene", "camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 }\n"
                                                    "object sphere { center <0, 0, 0> radius -1 }\n");
    GtraceRenderRequest rq = {.scene = bad, .depth = -1};
    assert_true(gtrace_render_file(&rq, &img, &err) < 0);
    assert_non_null(strstr(err.message, "embed_bad.scene:2:"));
    assert_null(img.pixels);
    rq.scene = write_text("embed_ok.scene", scene_text);
    rq.integrator = 2;
    assert_int_equal(gtrace_render_file(&rq, &img, &err), G_ERR_INVALID);
    rq.integrator = 1;
    int outside[4] = {0, 0, 41, 10};
    memcpy(rq.crop, outside, sizeof outside);
    assert_int_equal(gtrace_render_file(&rq, &img, &err), G_ERR_INVALID);
    assert_non_null(strstr(err.message, "crop 0,0,41,10 is not a region of the 40x30 image"));
    assert_int_equal(gtrace_render_file(NULL, &img, &err), G_ERR_INVALID);
    rq.scene = "/nonexistent/embed.scene";
    memset(rq.crop, 0, sizeof rq.crop);
    assert_true(gtrace_render_file(&rq, &img, &err) < 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_render_and_crop), cmocka_unit_test(test_errors)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
