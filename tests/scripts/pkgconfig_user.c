/* pkgconfig_user.c - a program that uses libgeneric as an outside user would, built by the pkg-config tests
 * (pkgconfig_uninstalled.sh, install_test.sh) with `cc pkgconfig_user.c $(pkg-config --cflags --libs generic)`:
 * prints the XYZ of white light in the rgb model and exits 0 when Y is 1. */
#include <generic/builtins.h>
#include <generic/color.h>
#include <stdio.h>

int main(void)
{
    GError err;
    GColorModel *m;
    if (generic_register_builtins(&err) != G_OK || gcolormodel_create("rgb", NULL, &m, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    float s[9]; /* rgb's capacity: a value may be a 3 x 3 re-radiation matrix */
    GColor c;
    if (gcolor_wrap(&c, m, s, 9) != G_OK)
        return 1;
    double w[3] = {1, 1, 1}, xyz[3];
    if (gcolor_from_rgb(&c, w, GCOLOR_LIGHT) != G_OK || gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz) != G_OK)
        return 1;
    gcolormodel_destroy(m);
    printf("%.4f %.4f %.4f\n", xyz[0], xyz[1], xyz[2]);
    return (xyz[1] > 0.999 && xyz[1] < 1.001) ? 0 : 1;
}
