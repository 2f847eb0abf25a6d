/* colour_difference.h - CIELAB and CIEDE2000 for the colour tests (static inline, header only). */
#ifndef GENERIC_TEST_COLOUR_DIFFERENCE_H
#define GENERIC_TEST_COLOUR_DIFFERENCE_H

#include <math.h>

/** CIELAB of XYZ against a white. */
static inline void cd_xyz_to_lab_white(const double xyz[3], const double white[3], double lab[3])
{
    double f[3];
    for (int i = 0; i < 3; i++) {
        double t = xyz[i] / white[i];
        f[i] = t > 216.0 / 24389.0 ? cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
    }
    lab[0] = 116.0 * f[1] - 16.0;
    lab[1] = 500.0 * (f[0] - f[1]);
    lab[2] = 200.0 * (f[1] - f[2]);
}

/** CIELAB of XYZ against the D65 white of Y = 1 (the library's reflectance white). */
static inline void cd_xyz_to_lab(const double xyz[3], double lab[3])
{
    const double white[3] = {0.95047, 1.0, 1.08883};
    cd_xyz_to_lab_white(xyz, white, lab);
}

/** CIEDE2000 between two CIELAB colours (Sharma, Wu and Dalal 2005). */
static inline double cd_delta_e2000(const double l1[3], const double l2[3])
{
    const double deg = M_PI / 180.0;
    double c1 = hypot(l1[1], l1[2]), c2 = hypot(l2[1], l2[2]), cm = 0.5 * (c1 + c2);
    double cm7 = pow(cm, 7.0), g = 0.5 * (1.0 - sqrt(cm7 / (cm7 + pow(25.0, 7.0))));
    double a1 = (1.0 + g) * l1[1], a2 = (1.0 + g) * l2[1];
    double cp1 = hypot(a1, l1[2]), cp2 = hypot(a2, l2[2]);
    double h1 = (a1 == 0 && l1[2] == 0) ? 0 : atan2(l1[2], a1), h2 = (a2 == 0 && l2[2] == 0) ? 0 : atan2(l2[2], a2);
    if (h1 < 0)
        h1 += 2 * M_PI;
    if (h2 < 0)
        h2 += 2 * M_PI;
    double dl = l2[0] - l1[0], dc = cp2 - cp1, dh = 0.0;
    if (cp1 * cp2 != 0) {
        dh = h2 - h1;
        if (dh > M_PI)
            dh -= 2 * M_PI;
        else if (dh < -M_PI)
            dh += 2 * M_PI;
    }
    double dH = 2.0 * sqrt(cp1 * cp2) * sin(dh / 2.0);
    double lm = 0.5 * (l1[0] + l2[0]), cpm = 0.5 * (cp1 + cp2), hm = h1 + h2;
    if (cp1 * cp2 != 0) {
        if (fabs(h1 - h2) <= M_PI)
            hm = 0.5 * (h1 + h2);
        else
            hm = (h1 + h2 < 2 * M_PI) ? 0.5 * (h1 + h2 + 2 * M_PI) : 0.5 * (h1 + h2 - 2 * M_PI);
    }
    double t = 1 - 0.17 * cos(hm - 30 * deg) + 0.24 * cos(2 * hm) + 0.32 * cos(3 * hm + 6 * deg) -
               0.20 * cos(4 * hm - 63 * deg);
    double dtheta = 30 * deg * exp(-pow((hm / deg - 275) / 25, 2));
    double cpm7 = pow(cpm, 7.0), rc = 2 * sqrt(cpm7 / (cpm7 + pow(25.0, 7.0)));
    double sl = 1 + 0.015 * (lm - 50) * (lm - 50) / sqrt(20 + (lm - 50) * (lm - 50));
    double sc = 1 + 0.045 * cpm, sh = 1 + 0.015 * cpm * t, rt = -sin(2 * dtheta) * rc;
    return sqrt(pow(dl / sl, 2) + pow(dc / sc, 2) + pow(dH / sh, 2) + rt * (dc / sc) * (dH / sh));
}

/** CIEDE2000 between two XYZ colours (D65 white). */
static inline double cd_delta_e_xyz(const double a[3], const double b[3])
{
    double la[3], lb[3];
    cd_xyz_to_lab(a, la);
    cd_xyz_to_lab(b, lb);
    return cd_delta_e2000(la, lb);
}

#endif
