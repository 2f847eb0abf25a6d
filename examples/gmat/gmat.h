/* gmat.h - the parts of the gmat material inspector (examples/gmat/). */
#ifndef GMAT_H
#define GMAT_H

#include <generic/material.h>
#include <generic/reader.h>

#include "../common/cli.h"

/** Where on the surface a measurement is made (the geometry stays the xy plane with normal +z): the fields
 * texture generators read. */
typedef struct GmatPlace {
    double u, v;
    GVec3 point; /**< world and object point */
    int surface;
} GmatPlace;

/** Everything a subcommand needs: the loaded file, the material and a surface point facing +z. */
typedef struct GmatContext {
    GLibrary *lib;
    const GColorModel *model;
    GMaterial *material;
    const char *material_name;
    GScratch *scratch;
    GColor white;  /**< the unit white light: rgb 1 1 1 as a light (D65, Y = 1) */
    GColor result; /**< storage for one evaluation */
    const GmatPlace *place; /**< NULL: u = v = 0.5 at the origin, surface 0 */
    const GColor *light;    /**< the light measurements use; NULL: white */
} GmatContext;

/** A direction from polar angles in degrees about +z (theta from the normal, phi from +x). */
GVec3 gmat_direction(double theta_deg, double phi_deg);
/** Deterministic uniform numbers in [0, 1) from the state *s (a small LCG: the checks draw the same pairs on every
 * run; measure.c). */
double gmat_uniform(unsigned long long *s);
/** A light of random values in [0.25, 1] (from *s) into light: each of m's nvalues samples drawn on its own when
 * the library reads m's values as plain samples (no fill slot), else a random spectrum (a value every 10 nm)
 * through m's own conversion from nm, so that a plug-in model's representation is respected (measure.c). */
int gmat_random_light(const GColorModel *m, unsigned long long *s, GColor *light);
/** Light reflected towards out for the unit white light arriving from in (into ctx->result). */
int gmat_reflect(GmatContext *ctx, GVec3 in, GVec3 out);
/** The ideal specular part for light from in: its direction and reflected colour (into ctx->result); 0 when the
 * material has no ideal reflection ray. */
int gmat_specular(GmatContext *ctx, GVec3 in, GVec3 *dir);
/** Adds to total the light from in (upper hemisphere) that refraction() (below != 0) or reflection() (below = 0)
 * sends into the lower or upper hemisphere, integrated over an n x 2n grid (midpoints in sin^2(theta) and phi) and
 * divided by in's cosine with the geometric normal: the non-ideal part of gmat_albedo and gmat_transmittance. */
int gmat_integrate(GmatContext *ctx, GVec3 in, int n, int below, GColor *total);
/** The ideal refraction ray for light from in: its direction (into the lower hemisphere) and transmitted colour
 * (into ctx->result); 0 when the material has none there. */
int gmat_ideal_refraction(GmatContext *ctx, GVec3 in, GVec3 *dir);
/** Directional-hemispherical reflectance for light from in, integrated over an n x 2n grid (midpoints in
 * sin^2(theta) and phi, exact for a Lambertian surface) plus the ideal specular part: the reflected colour goes
 * to `total` (storage of the model) and the luminance fractions to *y_total and *y_specular. */
int gmat_albedo(GmatContext *ctx, GVec3 in, int n, GColor *total, double *y_total, double *y_specular);
/** The surface point of a measurement at ctx->place: seen from outside (normal +z, from vacuum into the
 * material) or, with below != 0, from inside (normal -z, from the material into vacuum). */
void gmat_surface_point(GmatContext *ctx, GSurfPoint *sp, int below);
/** Light from in (upper hemisphere) that the material transmits into the lower hemisphere, as a fraction of
 * the incident light like gmat_albedo's: refraction() integrated over the lower hemisphere on the same grid
 * plus the ideal refraction ray. Adds into `total`; *y_ideal gets the ideal ray's luminance fraction. */
int gmat_transmittance(GmatContext *ctx, GVec3 in, int n, GColor *total, double *y_ideal);
/** Prints a colour as linear sRGB and XYZ (read as a light), with its spectrum when spectrum != 0. */
void gmat_print_color(const char *label, const GColor *c, int spectrum);
/** Decades below the maximum that a logarithmic radius shows. */
#define GMAT_PLOT_DECADES 4
/** How `gmat plot` draws. */
typedef struct GmatPlotOptions {
    int size;         /**< width in pixels (height 3/4 of it) */
    int log_radius;   /**< logarithmic radius over GMAT_PLOT_DECADES decades (a diffuse lobe beside a specular one) */
    const char *data; /**< also write the plotted table here (NULL: no) */
} GmatPlotOptions;
/** Writes the polar plot (gnuplot) of the light reflected in the plane of incidence of light from theta_in
 * degrees. */
int gmat_plot(GmatContext *ctx, double theta_in, const GmatPlotOptions *o, const char *path, GError *err);

/** `gmat check FILE MATERIAL` (check.c): the conformance checks (albedo, reciprocity, finite values, Snell's
 * law, defaults), one line each with its figure and PASS/FAIL; samples is the albedo grid (0 = 64). Returns the
 * exit status: 0 when every property passes, 1 otherwise. */
int gmat_check(GmatContext *ctx, int samples);
/** Prints one property's line (check.c): its name, the worst figure, the tolerance, PASS or FAIL. */
typedef void (*GmatReportFn)(void *checker, const char *property, double worst, double tol, const char *detail);
/** The most places a check of `gmat check` measures at. */
#define GMAT_MAX_PLACES 16
/** The albedo property of `gmat check` (albedo.c): at each of places[0 .. nplaces) and a sweep of incidences, light
 * leaving per light arriving, by a samples x 2 samples quadrature (or by sample() where that exceeds the
 * tolerance), one line through report. */
void gmat_check_albedo(GmatContext *ctx, const GmatPlace *places, int nplaces, int samples, GmatReportFn report,
                       void *checker);
/** The sampling checks of `gmat check` (sampling.c): chi2 of sample() against pdf(), the pdf's integral, the
 * weights; at places[0] and places[2 % nplaces], nsamples draws per incidence (0 = 20000). */
void gmat_check_sampling(GmatContext *ctx, const GmatPlace *places, int nplaces, int nsamples, GmatReportFn report,
                         void *checker);
/** The albedo seen from out (upper side) at ctx->place, estimated by the material's own sample() (sampling.c):
 * the mean over n draws (stratified in u1) of the weights of white light, reflected and transmitted, ideal lobes
 * included, into mean[j] and its standard error into se[j], one entry per sample of ctx->model. By reciprocity it
 * is the albedo for light from out; unbiased when sample() agrees with pdf() (the sampling checks). G_OK, or a
 * negative status (the material failed, or a weight that is not finite). */
int gmat_albedo_sampled(GmatContext *ctx, GVec3 out, int n, double *mean, double *se);
/** The no-emission check of `gmat check` (flags.c): a material with GMAT_NO_EMISSION must get black from its
 * class's own emission slot at the places given, over the directions of the finite check. */
void gmat_check_no_emission(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                            void *checker);
/** The opaque-flag check of `gmat check` (flags.c): a material with GMAT_OPAQUE must get 1 from its class's own
 * opaque slot at the places given, on both sides. */
void gmat_check_opaque_flag(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                            void *checker);
/** The geometric-normal check of `gmat check` (flags.c): a material with GMAT_GEOMETRIC_NORMAL must get the
 * geometric normal (within rounding) from its class's own normal slot at the places given, on both sides. */
void gmat_check_geometric_normal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                                 void *checker);
/** The lambertian check of `gmat check` (flags.c): a material with GMAT_LAMBERTIAN must reflect, by its class's own
 * reflection slot, its diffuse colour times the light times gmaterial_cos_in / pi (relative 1e-5) over random pairs of
 * directions and lights at the places given, on both sides, and its is_delta slot (if any) must say 0. */
void gmat_check_lambertian(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                           void *checker);
/** The diagonal check of `gmat check` (flags.c): a material with GMAT_DIAGONAL must pass on, by its class's own
 * reflection and refraction slots (with the relative indices 1 and 1.5), of any light what they pass on of white
 * (1 in every sample) times that light (relative 1e-5) over random pairs of directions, the ideal ones included,
 * and random lights at the places given, on both sides. */
void gmat_check_diagonal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker);
/** The no-ideal check of `gmat check` (flags.c): a material with GMAT_NO_IDEAL must get 0 (not valid) from its
 * class's own reflection_dir and refraction_dir slots at the places given, for views from both sides. */
void gmat_check_no_ideal(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker);
/** The no-rel-index check of `gmat check` (relindex.c): a material with GMAT_NO_REL_INDEX must give the same results,
 * bit for bit, from its class's own slots at the places given, on both sides, with the relative index 1.5 and with
 * 1 / 1.5 (on the point and as the argument). */
void gmat_check_no_rel_index(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                             void *checker);
/** The constant-index check of `gmat check` (constindex.c): a material with GMAT_CONSTANT_INDEX must give the same
 * colour, bit for bit, from its class's own refraction_index at the places given and at points drawn around them, on
 * both sides, as for sp NULL. */
void gmat_check_constant_index(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report,
                               void *checker);
/** 1 when the two colours hold the same kind and the same samples, bit for bit (constindex.c). */
int gmat_same_colour(const GColor *a, const GColor *b);
/** sp moved to a point drawn around it (constindex.c): position, normal on the same side, tangents, (u, v), surface,
 * footprints and distance t, its caches invalidated. */
void gmat_draw_point(GSurfPoint *sp, unsigned long long *seed);
/** A check's work at one surface point: what it adds to the check's count of failures. */
typedef int (*GmatPointVisit)(GmatContext *ctx, GSurfPoint *sp, void *user);
/** Calls visit at each of the places (ctx->place set to it) on both sides, at the place's own point and then at
 * `drawn` points drawn around it with gmat_draw_point from *seed, in that order (constindex.c); ctx->place is NULL
 * afterwards. Returns the sum of what visit returned. */
int gmat_each_point_around(GmatContext *ctx, const GmatPlace *places, int nplaces, int drawn, unsigned long long *seed,
                           GmatPointVisit visit, void *user);
/** The clear check of `gmat check` (clear.c): a material with GMAT_CLEAR must give back the light itself, bit for
 * bit, from its class's absorption at the places given and at points drawn around them, on both sides, and for
 * sp NULL, over lengths from 0 to 1e3 and lights of generated values, black included. */
void gmat_check_clear(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker);
/** The no-uv check of `gmat check` (uvflag.c): a material with GMAT_NO_UV must give the same colours, normal and
 * opacity at the places given, on both sides, with the surface's parametrisation set and with it zero. */
void gmat_check_no_uv(GmatContext *ctx, const GmatPlace *places, int nplaces, GmatReportFn report, void *checker);
/** The relative index n(from) / n(to) at sp as a colour, as a renderer hands it to refraction() (storage of the
 * model; temporaries on sp's arena). */
int gmat_relative_index(GSurfPoint *sp, GColor *out);
/** The scalar of that colour (gsurfpoint_scalar_index): the relative index a material refracts with at sp. For a
 * dispersive index it is not 1 / the scalar of n from outside (the brightness of 1 / n is not 1 / that of n: a
 * Cauchy glass with B = 0.1 differs by 1e-3). NaN on error. */
double gmat_relative_eta(GSurfPoint *sp);

/** `gmat laser FILE MATERIAL ...` (laser.c): the laser experiment of Wilkie et al., reading FILE with the reader
 * options base (--allow-plugins, --confine); returns the exit status. */
int gmat_laser(int argc, char **argv, const GReaderOptions *base);
/** `gmat metals [--markdown]` (metals.c): the measured metals `conductor { metal NAME }` knows. */
int gmat_metals(int argc, char **argv);

/** `gmat swatch FILE MATERIAL ...` (swatch.c): renders a material or texture tree read with the reader options
 * base; returns the exit status. */
int gmat_swatch(int argc, char **argv, const GReaderOptions *base);
/** `gmat glasses [--markdown]` (glasses.c): the named glasses of the dispersion kit; returns the exit status. */
int gmat_glasses(int argc, char **argv);

/** Reports a usage error of subcommand cmd (NULL: of gmat itself) on stderr: "gmat CMD: ", fmt with arg, and
 * where to find help (main.c). Returns 2, the exit status of usage errors. */
int gmat_usage_error(const char *cmd, const char *fmt, const char *arg);
/** Reads the whole string s as a finite number in [lo, hi] into *out: 0, or -1 (out untouched) when it is
 * not one. */
int gmat_number(const char *s, double lo, double hi, double *out);
/** The operands FILE and MATERIAL of subcommand cmd after its options (missing ones NULL): 0, or the usage
 * error's status 2 (message printed) when there are more than `want`. */
int gmat_operands(const char *cmd, const CliParser *p, int want, const char **file, const char **material);
/** The options of a listing subcommand prog ("gmat CMD", kept: a literal) `[--markdown] OPERAND...` (the common
 * ones and --markdown) parsed into *p (cli_operands gives the operands) and *markdown. Returns -1 to go on, else
 * the exit status (help, version or a usage error: printed). */
int gmat_markdown_option(const char *prog, int argc, char **argv, void (*usage)(FILE *), CliParser *p, int *markdown);
/** Reads file with the reader options base, computing in the colour model `colormodel` (NULL: the file's) with
 * its samples `step` nm apart (0: the model's default), and skipping the entries of the kinds in skip_kinds
 * (a bit per GKind, as GReaderOptions.skip_kinds). */
int gmat_read(const char *file, const GReaderOptions *base, const char *colormodel, double step, unsigned skip_kinds,
              GLibrary **lib, GError *err);

#endif
