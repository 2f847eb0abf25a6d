/* colorspace.c - the input colour spaces (generic/colorspace.h): RGB to XYZ matrices from each space's primaries,
 * its white brought to D65 by a Bradford adaptation where it differs. Needs libm only (the table generator links
 * it too). */
#include "generic/colorspace.h"
#include "colorspace_matrix.h"

#include <strings.h>

typedef struct SpaceDef {
    const char *name, *alias;
    double prim[3][2]; /* xy of red, green, blue */
    double white[2];   /* xy of the space's white */
} SpaceDef;

#define D65_XY {0.3127, 0.3290}
#define ACES_WHITE_XY {0.32168, 0.33767}

static const SpaceDef spaces[GCOLORSPACE_COUNT] = {
    {"srgb", "rec709", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, D65_XY},
    {"display-p3", "p3", {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}}, D65_XY},
    {"rec2020", "bt2020", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}}, D65_XY},
    {"aces2065-1", "aces", {{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}}, ACES_WHITE_XY},
    {"acescg", "ap1", {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}}, ACES_WHITE_XY},
};

/* IEC 61966-2-1's own matrix for sRGB (lib/color/cie.c uses the same), so sRGB is the library's exactly. */
static const double SRGB_TO_XYZ[3][3] = {
    {0.4124564, 0.3575761, 0.1804375},
    {0.2126729, 0.7151522, 0.0721750},
    {0.0193339, 0.1191920, 0.9503041},
};

int gcolorspace_find(const char *name)
{
    if (!name)
        return -1;
    for (int i = 0; i < GCOLORSPACE_COUNT; i++)
        if (strcasecmp(name, spaces[i].name) == 0 || strcasecmp(name, spaces[i].alias) == 0)
            return i;
    return -1;
}

const char *gcolorspace_name(int space) { return space >= 0 && space < GCOLORSPACE_COUNT ? spaces[space].name : NULL; }

const char *gcolorspace_names(void)
{
    return "srgb (rec709), display-p3 (p3), rec2020, aces2065-1 (aces), acescg (ap1)";
}

int gcolorspace_invert3(const double m[3][3], double out[3][3])
{
    double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
           c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    if (!(det > 1e-300 || det < -1e-300))
        return -1;
    double id = 1.0 / det;
    out[0][0] = c00 * id;
    out[1][0] = c01 * id;
    out[2][0] = c02 * id;
    out[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
    out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
    out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
    out[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
    out[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
    out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
    return 0;
}

static void mul3(const double a[3][3], const double b[3][3], double out[3][3])
{
    double t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = t[i][j];
}

static void xy_to_xyz(const double xy[2], double xyz[3])
{
    xyz[0] = xy[0] / xy[1];
    xyz[1] = 1.0;
    xyz[2] = (1.0 - xy[0] - xy[1]) / xy[1];
}

void gcolorspace_matrix(int space, double m[3][3])
{
    if (space == GCOLORSPACE_SRGB) {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                m[i][j] = SRGB_TO_XYZ[i][j];
        return;
    }
    const SpaceDef *s = &spaces[space];
    /* columns: the primaries' XYZ scaled so that they sum to the white (Y = 1) */
    double p[3][3], pinv[3][3], w[3], k[3];
    for (int c = 0; c < 3; c++) {
        double v[3];
        xy_to_xyz(s->prim[c], v);
        for (int r = 0; r < 3; r++)
            p[r][c] = v[r];
    }
    /* D65 as sRGB's matrix has it (xy rounded to four places), so that white is one XYZ in every space */
    double d65w[3] = {SRGB_TO_XYZ[0][0] + SRGB_TO_XYZ[0][1] + SRGB_TO_XYZ[0][2], 1.0,
                      SRGB_TO_XYZ[2][0] + SRGB_TO_XYZ[2][1] + SRGB_TO_XYZ[2][2]};
    const double d65[2] = D65_XY;
    int adapt = s->white[0] != d65[0] || s->white[1] != d65[1];
    if (adapt)
        xy_to_xyz(s->white, w);
    else
        w[0] = d65w[0], w[1] = d65w[1], w[2] = d65w[2];
    gcolorspace_invert3(p, pinv);
    for (int c = 0; c < 3; c++)
        k[c] = pinv[c][0] * w[0] + pinv[c][1] * w[1] + pinv[c][2] * w[2];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            m[r][c] = p[r][c] * k[c];
    if (!adapt)
        return;
    /* Bradford: XYZ of the space's white to XYZ of D65 */
    static const double B[3][3] = {{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}};
    double binv[3][3], wd[3], cs[3], cd[3], a[3][3] = {{0}};
    gcolorspace_invert3(B, binv);
    wd[0] = d65w[0], wd[1] = d65w[1], wd[2] = d65w[2];
    for (int r = 0; r < 3; r++) {
        cs[r] = B[r][0] * w[0] + B[r][1] * w[1] + B[r][2] * w[2];
        cd[r] = B[r][0] * wd[0] + B[r][1] * wd[1] + B[r][2] * wd[2];
    }
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = B[r][c] * cd[r] / cs[r];
    mul3(binv, a, a);
    mul3(a, m, m);
}

int gcolorspace_to_xyz(int space, const double rgb[3], double xyz[3])
{
    if (space < 0 || space >= GCOLORSPACE_COUNT)
        return G_ERR_INVALID;
    double m[3][3];
    gcolorspace_matrix(space, m);
    double x[3];
    for (int r = 0; r < 3; r++)
        x[r] = m[r][0] * rgb[0] + m[r][1] * rgb[1] + m[r][2] * rgb[2];
    for (int r = 0; r < 3; r++)
        xyz[r] = x[r];
    return G_OK;
}

int gcolorspace_to_srgb(int space, const double rgb[3], double srgb[3])
{
    double xyz[3], inv[3][3];
    int rc = gcolorspace_to_xyz(space, rgb, xyz);
    if (rc != G_OK)
        return rc;
    gcolorspace_invert3(SRGB_TO_XYZ, inv);
    for (int r = 0; r < 3; r++)
        srgb[r] = inv[r][0] * xyz[0] + inv[r][1] * xyz[1] + inv[r][2] * xyz[2];
    return G_OK;
}
