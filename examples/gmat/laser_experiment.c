/* laser_experiment.c - the laser experiment of Wilkie et al. (sections 3 and 6): a collimated monochromatic beam on a
 * material, the split of the reflected power into light that kept its wavelength and light that was shifted,
 * and the reflection pattern on a white diffuse target.
 *
 * Geometry: the sample lies in the x-y plane with normal +z, the beam travels in the x-z plane and hits the
 * origin at elevation e, so `in` (towards the source) is (-cos e, 0, sin e) and the mirror direction
 * r = (cos e, 0, sin e). Directions are written about r: o = cos a r + sin a (cos b t1 + sin b t2), with
 * t1 = (0, 1, 0) across the plane of incidence and t2 = (-sin e, 0, cos e) along it.
 *
 * Power: a beam of irradiance E (perpendicular to it) lights the spot with E cos theta_i per area; the
 * spot's radiance towards o is L = reflection(in, E, o), its exitance the integral of L cos theta_o over the
 * hemisphere, so the reflected share is that integral over E cos theta_i. The target, perpendicular to r at
 * distance 1, receives from the spot an irradiance proportional to L(o) cos theta_o cos psi / d^2 (psi
 * between o and r, d the distance to the target point).
 *
 * Spectral models: the beam is a unit value on one sample of the model (the one nearest the requested
 * wavelength), written into the samples of a vector colour (the first nsamples values of a vector are its
 * samples at lambda_min + k * lambda_step). Everything else goes through the generic operations. */
#include "laser_experiment.h"

#include <generic/kit/fluorescent_kit.h>

#include <math.h>
#include <string.h>

typedef struct Beam {
    const GMaterial *mat;
    const GColorModel *model;
    GSurfPoint sp;
    GVec3 in, r, t1, t2;
    int sample; /* the beam's sample, -1 in non-spectral models */
    GColor light, tmp;
} Beam;

static int beam_setup(Beam *b, const GMaterial *mat, GScratch *scratch, double nm, double elevation_deg,
                      GError *err)
{
    memset(b, 0, sizeof *b);
    if (!mat || !mat->model || !scratch)
        return gerror_set(err, G_ERR_INVALID, "laser: no material or scratch arena given");
    if (!isfinite(elevation_deg) || elevation_deg <= 0.0 || elevation_deg > 90.0)
        return gerror_set(err, G_ERR_INVALID, "laser: elevation %g degrees (must be in (0, 90])", elevation_deg);
    const GColorModel *m = mat->model;
    b->mat = mat;
    b->model = m;
    b->sample = -1;
    if (m->nsamples > 0) {
        if (!isfinite(nm))
            return gerror_set(err, G_ERR_INVALID, "laser: wavelength is not a number");
        double f = (nm - m->lambda_min) / m->lambda_step;
        if (!(f >= -0.5 && f < m->nsamples - 0.5)) /* tested before the cast: f may be beyond any int */
            return gerror_set(err, G_ERR_INVALID, "laser: %g nm is outside the model's range %g..%g nm", nm,
                              m->lambda_min, m->lambda_min + (m->nsamples - 1) * m->lambda_step);
        b->sample = (int)floor(f + 0.5);
    }
    double e = elevation_deg * M_PI / 180.0;
    b->in = gvec3(-cos(e), 0.0, sin(e));
    b->r = gvec3(cos(e), 0.0, sin(e));
    b->t1 = gvec3(0.0, 1.0, 0.0);
    b->t2 = gvec3(-sin(e), 0.0, cos(e));
    gsurfpoint_init(&b->sp, m, scratch);
    b->sp.geometric_normal = gvec3(0.0, 0.0, 1.0);
    b->sp.dpdu = gvec3(1.0, 0.0, 0.0);
    b->sp.dpdv = gvec3(0.0, 1.0, 0.0);
    b->sp.material = mat;
    b->sp.entering = 1;
    if (gcolor_scratch(&b->light, m, scratch) != G_OK || gcolor_scratch(&b->tmp, m, scratch) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "laser: out of scratch memory");
    if (b->sample >= 0) {
        b->light.v[b->sample] = 1.0f;
    } else {
        double white[3] = {1.0, 1.0, 1.0};
        int rc = gcolor_from_rgb(&b->light, white, GCOLOR_LIGHT);
        if (rc != G_OK)
            return gerror_set(err, rc, "laser: cannot make a white beam in model '%s'", gcolormodel_name(m));
    }
    return G_OK;
}

/* Radiance towards o into b->tmp. */
static int beam_reflect(Beam *b, GVec3 o)
{
    return gmaterial_reflection(b->mat, &b->sp, b->in, &b->light, o, &b->tmp);
}

double gfluor_dominant_wavelength(double x, double y)
{
    const double xw = 1.0 / 3.0, yw = 1.0 / 3.0;
    double dx = x - xw, dy = y - yw;
    if (hypot(dx, dy) < 1e-9)
        return 0.0;
    double best = 0.0, best_nm = 0.0, best_anti = 0.0, anti_nm = 0.0;
    for (int nm = GNM_MIN; nm <= 700; nm++) {
        double c[3];
        gcie_cmf(nm, c);
        double s = c[0] + c[1] + c[2];
        if (s <= 0.0)
            continue;
        double lx = c[0] / s - xw, ly = c[1] / s - yw;
        double cosang = (lx * dx + ly * dy) / (hypot(lx, ly) * hypot(dx, dy));
        if (cosang > best) {
            best = cosang;
            best_nm = nm;
        }
        if (-cosang > best_anti) {
            best_anti = -cosang;
            anti_nm = nm;
        }
    }
    /* a direction between those of 380 nm and 700 nm (counter-clockwise) points at the purples */
    double c0[3], c1[3];
    gcie_cmf(GNM_MIN, c0);
    gcie_cmf(700, c1);
    double x0 = c0[0] / (c0[0] + c0[1] + c0[2]) - xw, y0 = c0[1] / (c0[0] + c0[1] + c0[2]) - yw;
    double x1 = c1[0] / (c1[0] + c1[1] + c1[2]) - xw, y1 = c1[1] / (c1[0] + c1[1] + c1[2]) - yw;
    double a0 = x0 * dy - y0 * dx, a1 = dx * y1 - dy * x1;
    if (a0 > 0.0 && a1 > 0.0)
        return -anti_nm;
    return best_nm;
}

/* Values integrate sums per ring: the model's samples, or the brightness in a non-spectral model. */
static int sum_count(const Beam *b)
{
    return b->sample >= 0 ? b->model->nsamples : 1;
}

/* The reflected power over the hemisphere per sample into sum[sum_count] (over E cos theta_i), with nt rings
 * about the mirror direction and np steps around it. The rings a = pi u^2 crowd near the mirror direction,
 * where glossy lobes are. Each ring is summed in the model's colour and added to sum in double precision, so
 * that many rings do not lose the small terms of a float sum. */
static int integrate(Beam *b, int nt, int np, GColor *ring, double *sum)
{
    const int count = sum_count(b);
    const double cos_i = b->in.z;
    for (int k = 0; k < count; k++)
        sum[k] = 0.0;
    int rc = G_OK;
    for (int iu = 0; iu < nt && rc == G_OK; iu++) {
        double u = (iu + 0.5) / nt;
        double a = M_PI * u * u;
        double w = sin(a) * 2.0 * M_PI * u * (1.0 / nt) * (2.0 * M_PI / np);
        gcolor_black(ring);
        for (int ib = 0; ib < np && rc == G_OK; ib++) {
            double beta = 2.0 * M_PI * (ib + 0.5) / np;
            GVec3 o = gvec3_add(gvec3_scale(b->r, cos(a)), gvec3_add(gvec3_scale(b->t1, sin(a) * cos(beta)),
                                                                gvec3_scale(b->t2, sin(a) * sin(beta))));
            if (o.z <= 0.0)
                continue;
            rc = beam_reflect(b, o);
            if (rc == G_OK)
                rc = gcolor_add_scaled(ring, &b->tmp, o.z);
        }
        if (b->sample < 0)
            sum[0] += w * gcolor_brightness(ring) / (gcolor_brightness(&b->light) * cos_i);
        else
            for (int k = 0; k < count; k++)
                sum[k] += w * ring->v[k] / cos_i;
    }
    return rc;
}

/* Kept and shifted shares of the power in sum (see GFluorLaserSplit). */
static void shares(const Beam *b, const double *sum, double *kept, double *shifted)
{
    *kept = b->sample < 0 ? sum[0] : sum[b->sample];
    *shifted = 0.0;
    for (int k = 0; k < sum_count(b); k++)
        if (k != b->sample && b->sample >= 0)
            *shifted += sum[k];
}

int gfluor_laser_split(const GMaterial *material, GScratch *scratch, double nm, double elevation_deg,
                       const GFluorLaserOptions *opt, GFluorLaserSplit *out, GError *err)
{
    memset(out, 0, sizeof *out);
    int fixed = opt && opt->n_theta > 0;
    int nt = fixed ? opt->n_theta : GFLUOR_LASER_RINGS;
    int np = opt && opt->n_phi > 0 ? opt->n_phi : GFLUOR_LASER_RINGS;
    GScratchMark mark = gscratch_mark(scratch);
    Beam b;
    int rc = beam_setup(&b, material, scratch, nm, elevation_deg, err);
    GColor ring;
    double *sum = NULL, *finer = NULL;
    if (rc == G_OK) {
        sum = gscratch_alloc(scratch, 2 * (size_t)sum_count(&b) * sizeof *sum);
        finer = sum ? sum + sum_count(&b) : NULL;
        if (!sum || gcolor_scratch(&ring, b.model, scratch) != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "laser: out of scratch memory");
    }
    if (rc == G_OK)
        rc = integrate(&b, nt, np, &ring, sum);
    /* without a ring count given: twice the rings until kept and shifted change by at most GFLUOR_LASER_TOLERANCE
     * (the specular lobe of a smooth material is narrow, and takes more rings to resolve) */
    while (rc == G_OK && !fixed && nt < GFLUOR_LASER_MAX_RINGS) {
        double k0, s0, k1, s1;
        rc = integrate(&b, 2 * nt, np, &ring, finer);
        if (rc != G_OK)
            break;
        shares(&b, sum, &k0, &s0);
        shares(&b, finer, &k1, &s1);
        nt *= 2;
        memcpy(sum, finer, (size_t)sum_count(&b) * sizeof *sum);
        if (fabs(k1 - k0) <= GFLUOR_LASER_TOLERANCE && fabs(s1 - s0) <= GFLUOR_LASER_TOLERANCE)
            break;
    }
    if (rc != G_OK) {
        if (err && err->code == G_OK)
            gerror_set(err, rc, "laser: evaluating '%s' failed", gmaterial_name(material));
        gscratch_release(scratch, mark);
        return rc;
    }
    out->elevation = elevation_deg;
    out->rings = nt;
    shares(&b, sum, &out->kept, &out->shifted);
    if (b.sample < 0) {
        gscratch_release(scratch, mark);
        return G_OK;
    }
    const GColorModel *m = b.model;
    out->wavelength = m->lambda_min + b.sample * m->lambda_step;
    double xyz[3] = {0, 0, 0}, peak = 0.0;
    for (int k = 0; k < m->nsamples; k++) {
        if (k == b.sample)
            continue;
        double p = sum[k], lam = m->lambda_min + k * m->lambda_step, c[3];
        if (p > peak) {
            peak = p;
            out->peak_nm = lam;
        }
        gcie_cmf(lam, c);
        for (int j = 0; j < 3; j++)
            xyz[j] += p * c[j];
    }
    double s = xyz[0] + xyz[1] + xyz[2];
    if (out->shifted > 1e-9 && s > 0.0)
        out->dominant_nm = gfluor_dominant_wavelength(xyz[0] / s, xyz[1] / s);
    else
        out->peak_nm = 0.0;
    gscratch_release(scratch, mark);
    return G_OK;
}

/* Full width at half maximum of a run of pixels through the peak at index c (stride between pixels). */
static double fwhm(const float *v, int count, int stride, int c, double pixel)
{
    double half = 0.5 * v[(long)c * stride];
    double ends[2];
    for (int dir = 0; dir < 2; dir++) {
        int step = dir ? 1 : -1, k = c;
        while (k + step >= 0 && k + step < count && v[(long)(k + step) * stride] >= half)
            k += step;
        double pos = k;
        if (k + step >= 0 && k + step < count) {
            double a = v[(long)k * stride], z = v[(long)(k + step) * stride];
            pos += step * (a - half) / (a - z);
        }
        ends[dir] = pos;
    }
    return (ends[1] - ends[0]) * pixel;
}

void gfluor_pattern_free(GFluorPattern *p)
{
    if (!p)
        return;
    gmem_free(p->rgb);
    gmem_free(p->kept);
    memset(p, 0, sizeof *p);
}

int gfluor_laser_pattern(const GMaterial *material, GScratch *scratch, double nm, double elevation_deg, int width,
                         int height, double extent, GFluorPattern *out, GError *err)
{
    memset(out, 0, sizeof *out);
    if (width < 8 || height < 8 || width > 8192 || height > 8192 || !(extent > 0.0) || !isfinite(extent))
        return gerror_set(err, G_ERR_INVALID, "laser pattern: size %d x %d, extent %g (need 8..8192 pixels and "
                          "extent > 0)", width, height, extent);
    GScratchMark mark = gscratch_mark(scratch);
    Beam b;
    int rc = beam_setup(&b, material, scratch, nm, elevation_deg, err);
    long npx = (long)width * height;
    float *xyz = NULL;
    if (rc == G_OK) {
        out->rgb = gmem_calloc((size_t)npx * 3, sizeof(float));
        out->kept = gmem_calloc((size_t)npx, sizeof(float));
        xyz = gmem_calloc((size_t)npx * 3, sizeof(float));
        if (!out->rgb || !out->kept || !xyz)
            rc = gerror_set(err, G_ERR_NOMEM, "laser pattern: out of memory for %d x %d pixels", width, height);
    }
    double pixel = 2.0 * extent / width, ymax = 0.0;
    for (int py = 0; py < height && rc == G_OK; py++)
        for (int px = 0; px < width && rc == G_OK; px++) {
            double x = (px + 0.5 - 0.5 * width) * pixel, y = (0.5 * height - py - 0.5) * pixel;
            GVec3 p = gvec3_add(b.r, gvec3_add(gvec3_scale(b.t1, x), gvec3_scale(b.t2, y)));
            double d2 = gvec3_dot(p, p);
            GVec3 o = gvec3_scale(p, 1.0 / sqrt(d2));
            if (o.z <= 0.0)
                continue; /* behind the sample's plane */
            rc = beam_reflect(&b, o);
            double c[3];
            if (rc == G_OK)
                rc = gcolor_to_xyz(&b.tmp, GCOLOR_LIGHT, c);
            if (rc != G_OK)
                break;
            /* target irradiance ~ L cos_o cos_psi / d^2; the printed grid every 0.1 absorbs a little */
            double f = o.z * gvec3_dot(o, b.r) / d2;
            double gx = fabs(x * 10.0 - floor(x * 10.0 + 0.5)), gy = fabs(y * 10.0 - floor(y * 10.0 + 0.5));
            double albedo = (gx < 0.04 || gy < 0.04) ? 0.75 : 1.0;
            long i = (long)py * width + px;
            for (int j = 0; j < 3; j++)
                xyz[i * 3 + j] = (float)(c[j] * f * albedo);
            if (c[1] * f > ymax)
                ymax = c[1] * f;
            out->kept[i] = (float)(b.sample >= 0 ? b.tmp.v[b.sample] * f : gcolor_brightness(&b.tmp) * f);
        }
    if (rc != G_OK) {
        gmem_free(xyz);
        gfluor_pattern_free(out);
        gscratch_release(scratch, mark);
        if (err && err->code == G_OK)
            gerror_set(err, rc, "laser pattern: evaluating '%s' failed", gmaterial_name(material));
        return rc;
    }
    /* exposure: the brightest point to 1, then 1 - exp(-k y) so the faint diffuse glow stays visible;
     * chromaticity kept, out-of-gamut negatives clipped */
    const double k = 6.0;
    for (long i = 0; i < npx; i++) {
        double c[3] = {xyz[i * 3], xyz[i * 3 + 1], xyz[i * 3 + 2]}, rgb[3];
        double y = ymax > 0.0 ? c[1] / ymax : 0.0;
        double s = y > 0.0 ? (1.0 - exp(-k * y)) / (1.0 - exp(-k)) / y / ymax : 0.0;
        gcie_xyz_to_rgb(c, rgb);
        for (int j = 0; j < 3; j++) {
            double v = rgb[j] * s;
            out->rgb[i * 3 + j] = (float)(v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v);
        }
    }
    gmem_free(xyz);
    long best = 0;
    for (long i = 1; i < npx; i++)
        if (out->kept[i] > out->kept[best])
            best = i;
    out->width = width;
    out->height = height;
    out->extent = extent;
    if (out->kept[best] > 0.0f) {
        int bx = (int)(best % width), by = (int)(best / width);
        out->kept_fwhm_h = fwhm(out->kept + (long)by * width, width, 1, bx, pixel);
        out->kept_fwhm_v = fwhm(out->kept + bx, height, width, by, pixel);
        out->aspect = out->kept_fwhm_h > 0.0 ? out->kept_fwhm_v / out->kept_fwhm_h : 0.0;
    }
    gscratch_release(scratch, mark);
    return G_OK;
}
