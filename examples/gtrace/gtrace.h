/* gtrace.h - the Whitted ray tracer's own types: scene, objects, lights, camera, render settings.
 *
 * The tracer touches colours and materials only through the generic interfaces (generic/color.h,
 * generic/material.h): it never names a colour model and never reads colour samples. Intersection goes
 * through Embree 3; the built-in shapes are Embree user geometries intersected analytically in double
 * precision (exact spheres for refraction, exact normals, no tessellation), meshes are native triangles. */
#ifndef GTRACE_H
#define GTRACE_H

#include <generic/color.h>
#include <generic/error.h>
#include <generic/material.h>
#include <generic/memory.h>
#include <generic/probe.h>
#include <generic/reader.h>
#include <generic/surfpoint.h>
#include <generic/vec.h>

#include <embree3/rtcore.h>
#include <stdint.h>
#include <stdio.h>

/* ---- affine transforms (transform.c) ---- */

/** world = m * object; inv is the inverse. Rows are x, y, z; column 3 is the translation. */
typedef struct Xform {
    double m[3][4];
    double inv[3][4];
} Xform;

/** The identity. */
void xform_identity(Xform *x);
/** x = x followed by a translation / rotation (degrees about an axis) / scale; return 0 or G_ERR_INVALID
 * for a singular result. */
int xform_translate(Xform *x, GVec3 t);
int xform_rotate(Xform *x, GVec3 axis, double degrees);
int xform_scale(Xform *x, GVec3 s);
/** x = x followed by the affine matrix rows (3x4). */
int xform_matrix(Xform *x, const double rows[3][4]);
/** Points, vectors and normals from object to world space and back. */
GVec3 xform_point(const Xform *x, GVec3 p);
GVec3 xform_vector(const Xform *x, GVec3 v);
GVec3 xform_normal(const Xform *x, GVec3 n);
GVec3 xform_inv_point(const Xform *x, GVec3 p);
GVec3 xform_inv_vector(const Xform *x, GVec3 v);
/** Two unit vectors t1, t2 with t1 x t2 = n (n unit). */
void frame_from_normal(GVec3 n, GVec3 *t1, GVec3 *t2);

/* ---- objects (scene.c, shapes.c, mesh.c) ---- */

typedef enum ShapeKind {
    SHAPE_SPHERE,
    SHAPE_PLANE,
    SHAPE_BOX,
    SHAPE_DISC,
    SHAPE_CYLINDER,
    SHAPE_MESH
} ShapeKind;

/** A triangle mesh read from an OBJ file. Positions are kept in object space (double) and world space
 * (the float buffer Embree reads); normals and (u,v) per corner, -1 where the file gave none. */
typedef struct Mesh {
    int nverts, ntris, nuvs, nnormals;
    double *pos;        /**< object space, 3 per vertex */
    double *uv;         /**< 2 per uv */
    double *normal;     /**< object space, 3 per normal */
    unsigned *tri;      /**< 3 vertex indices per triangle */
    int *tri_uv;        /**< 3 uv indices per triangle or -1 */
    int *tri_normal;    /**< 3 normal indices per triangle or -1 */
    int *tri_surface;   /**< group (usemtl/g) index per triangle: the surface index */
} Mesh;

/** One object: a shape in its own space, a transform to world space and a material. */
typedef struct Object {
    ShapeKind kind;
    GMaterial *material; /**< owned reference */
    Xform xf;
    int has_xf;
    /* shape parameters, object space */
    GVec3 center;     /**< sphere, disc: centre; plane: a point; cylinder: base centre */
    GVec3 normal;     /**< plane, disc: unit normal; cylinder: unit axis */
    GVec3 t1, t2;     /**< plane, disc, cylinder: frame with t1 x t2 = normal */
    double radius;    /**< sphere, disc, cylinder */
    double height;    /**< cylinder */
    int open;         /**< cylinder without caps */
    GVec3 lo, hi;     /**< box corners */
    Mesh *mesh;       /**< SHAPE_MESH */
    unsigned geom_id; /**< Embree geometry id */
} Object;

/* ---- lights (lights.c) ---- */

typedef enum LightKind {
    LIGHT_POINT,       /**< intensity I: illum = I / d^2 */
    LIGHT_DIRECTIONAL, /**< irradiance E perpendicular to the direction: illum = E */
    LIGHT_SPOT,        /**< point light with a smooth cone */
    LIGHT_SPHERE,      /**< sphere of uniform radiance, sampled by solid angle */
    LIGHT_RECT,        /**< one-sided rectangle of uniform radiance, stratified samples */
    LIGHT_AMBIENT,     /**< (text only) ambient light: summed into Scene.ambient */
    LIGHT_BACKGROUND,  /**< (text only) radiance of rays that leave the scene: Scene.background */
    LIGHT_PROBE        /**< a whole light probe, Monte Carlo with importance sampling (probe_sample.c) */
} LightKind;

typedef struct Light {
    LightKind kind;
    GColor color;            /**< intensity, irradiance or radiance (heap storage, owned) */
    GVec3 position;          /**< point, spot, sphere centre, rectangle corner */
    GVec3 direction;         /**< directional, spot: unit direction the light travels */
    GVec3 edge1, edge2;      /**< rectangle edges; the lit side is edge1 x edge2 */
    double radius;           /**< sphere */
    double cos_inner, cos_outer; /**< spot cone (full intensity inside inner, none outside outer) */
    int samples;             /**< area lights, probe: shadow samples per shading point */
    const struct ProbeEnv *env; /**< LIGHT_PROBE: the probe it samples (owned by the probe entry) */
} Light;

/* ---- camera (camera.c) ---- */

typedef struct Camera {
    GVec3 from, at, up;
    double fov;            /**< vertical field of view in degrees */
    int width, height;     /**< image size (command line overrides) */
    int spp, depth;        /**< samples per pixel, recursion depth */
    double cutoff;         /**< adaptive depth: rays whose weight in the pixel falls below this are not traced */
    double exposure;       /**< stops applied to .png/.jpg output */
    GMaterial *medium;     /**< the medium the camera is in (borrowed from the library; NULL: vacuum) */
    /* derived by camera_setup */
    GVec3 eye, right, upv, forward;
    double half_h, half_w; /**< tan of the half angles */
    double spread;         /**< ray cone spread angle per pixel (radians) */
} Camera;

/* ---- the scene ---- */

typedef struct Scene {
    const GColorModel *model; /**< colour model of every colour in the scene */
    GColorModel *owned_model; /**< destroyed with the scene (NULL: the model belongs to someone else) */
    Object **objects;
    int nobjects, cap_objects;
    Light **lights;
    int nlights, cap_lights;
    Camera camera;
    int have_camera;
    GColor background;     /**< radiance of rays that leave the scene */
    GColor ambient;        /**< ambient light handed to material.ambient */
    int have_ambient;
    GMaterial *medium;     /**< the medium the camera is in (NULL: vacuum; a reference) */
    GLibrary *lib;         /**< when loaded from text: owns the objects and lights (and the model) */
    /* Embree (accel.c) */
    RTCDevice device;
    RTCScene rtc;
    Object **by_geom;      /**< geometry id -> object */
    unsigned nby_geom;
    const struct ProbeEnv *env; /**< light probe seen by rays that leave the scene (NULL: background) */
} Scene;

/** An empty scene in the given colour model (not owned; set owned_model to hand one over). */
int scene_create(const GColorModel *model, Scene **out, GError *err);
/** Frees everything (NULL: no-op). */
void scene_destroy(Scene *s);
/** Takes ownership of o (freed with the scene also when this fails). */
int scene_add_object(Scene *s, Object *o, GError *err);
/** Takes ownership of l. */
int scene_add_light(Scene *s, Light *l, GError *err);
/** A zeroed object of a kind with an identity transform holding a new reference to material. */
Object *object_new(ShapeKind kind, GMaterial *material);
void object_free(Object *o);
/** A light with defaults whose colour has heap storage in the model (black). */
Light *light_new(const GColorModel *model, LightKind kind);
void light_free(Light *l);
/** Shape constructors in object space (they fill the frames); return G_ERR_INVALID for bad parameters. */
int object_sphere(Object *o, GVec3 center, double radius, GError *err);
int object_plane(Object *o, GVec3 point, GVec3 normal, GError *err);
int object_box(Object *o, GVec3 lo, GVec3 hi, GError *err);
int object_disc(Object *o, GVec3 center, GVec3 normal, double radius, GError *err);
int object_cylinder(Object *o, GVec3 base, GVec3 top, double radius, int open, GError *err);
/** Reads an OBJ file into o (v, vt, vn, f with polygons as fans; usemtl/g start new surface indices). */
int object_mesh_load(Object *o, const char *path, GError *err);
void mesh_free(Mesh *m);
/** Registers the object, light and camera types with the registry (idempotent). */
int gtrace_register_types(GError *err);
/** Builds a scene from a loaded library (name: for messages), which the scene then owns (also on failure:
 * it is destroyed). */
int scene_from_library(GLibrary *lib, const char *name, Scene **out, GError *err);
/** Reads a scene file (registering the types first); colormodel overrides the file's model (NULL: keep). */
int scene_load(const char *path, const char *colormodel, Scene **out, GError *err);
/** Default camera: looking down -z from (0,0,5), 40 degrees, 320x240, 1 spp, depth 8. */
void camera_defaults(Camera *c);

/* ---- geometry: intersection and the surface at a hit (shapes.c, mesh.c, accel.c) ---- */

/** A ray in double precision; the cone gives the pixel footprint (width at the origin, spread angle). */
typedef struct Ray {
    GVec3 o, d; /**< d is unit length so t is a distance */
    double tmin, tmax;
    double cone_width, cone_spread;
} Ray;

/** What Embree reports for a hit. */
typedef struct Hit {
    const Object *obj;
    double t;
    unsigned prim;
    double bu, bv; /**< barycentrics (meshes) */
    int surface;   /**< surface index from the user geometry */
} Hit;

/** The geometry at a hit in world space: outward unit normal (of the object, before facing), shading
 * normal from mesh normals (equal to the outward normal otherwise), tangents, parameters. */
typedef struct HitGeom {
    GVec3 p, op, n_out, n_smooth, dpdu, dpdv;
    GVec3 odpdu, odpdv; /**< tangents in object space */
    double u, v;
    int surface;
} HitGeom;

/** Object-space ray-shape intersection in (tmin, tmax); 1 with *t and *surface when hit. */
int shape_intersect(const Object *o, GVec3 ro, GVec3 rd, double tmin, double tmax, double *t, int *surface);
/** Object-space bounds of a shape (planes are bounded at SHAPE_PLANE_EXTENT). */
void shape_bounds(const Object *o, GVec3 *lo, GVec3 *hi);
/** Surface details of an analytic shape at a hit. */
void shape_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);
/** Surface details of a mesh triangle at a hit. */
void mesh_hit_geom(const Object *o, const Ray *r, const Hit *h, HitGeom *g);

/** Half size of a plane's bounded extent in its own units. */
#define SHAPE_PLANE_EXTENT 1.0e5

/** Builds the Embree scene from the objects (after all are added). */
int accel_build(Scene *s, GError *err);
/** Releases Embree objects. */
void accel_release(Scene *s);
/** Closest hit along r; 1 when something was hit. */
int accel_intersect(const Scene *s, const Ray *r, Hit *h);
/** 1 when anything lies on r between tmin and tmax. */
int accel_occluded(const Scene *s, const Ray *r);

/* ---- rendering ---- */

/** Small fast generator (PCG32), one per pixel so images do not depend on the thread count. */
typedef struct Rng {
    uint64_t state, inc;
} Rng;
void rng_seed(Rng *r, uint64_t seed, uint64_t stream);
/** Uniform in [0,1). */
double rng_next(Rng *r);

/** Per-thread tracing state. */
typedef struct TraceCtx {
    const Scene *scene;
    GScratch *scratch;
    Rng rng;
    int max_depth;
    double cutoff;  /**< smallest path weight still traced (0: trace to max_depth) */
    double weight;  /**< weight of the current path in its pixel (product of the branches' brightness) */
    GColor unit;    /**< 1 in every sample (the vacuum's refraction index): probes a branch's weight */
    uint64_t rays;  /**< rays cast through Embree */
    int status;     /**< first error (G_OK while fine) */
    const char *culprit; /**< type of the material whose call failed first (NULL: none or not a material) */
} TraceCtx;

/** The media a ray travels through: bottom = the camera's medium, top = the current one. */
#define MEDIA_MAX 16
typedef struct Media {
    const GMaterial *m[MEDIA_MAX];
    int n;
} Media;

/** Fills sp for a hit of r: geometry, normal on the incident side, footprint from the ray cone, and the
 * materials on both sides from the media; *facing is the true face normal on the incident side (for
 * offsetting secondary rays; it differs from the geometric_normal field on meshes with vertex normals). */
void surfpoint_fill(TraceCtx *c, const Ray *r, const Hit *h, const Media *media, GSurfPoint *sp, GVec3 *facing);
/** The current medium (NULL: vacuum). */
const GMaterial *media_top(const Media *m);
/** The media after crossing the surface of mat: entering pushes it, leaving removes it. */
void media_cross(const Media *in, const GMaterial *mat, int entering, Media *out);

/** Radiance arriving along r (Fig. 4: closest hit, then shade). out must have storage. */
int trace_ray(TraceCtx *c, const Ray *r, const Media *media, int depth, GColor *out);
/** Scratch colours for light_shade, allocated once per shading point and shared by all lights. */
typedef struct LightTmp {
    GColor illum, refl, tmp;
} LightTmp;
/** Allocates the temporaries on the thread's arena. */
int light_temps(TraceCtx *c, LightTmp *t);
/** Adds to result the light reflected towards out_dir by sp from one light source, shadowed and absorbed
 * (Fig. 4, light.shade); opaque: the material's opaque() at sp (culls lights behind the surface). */
int light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                int opaque, LightTmp *t, GColor *result);
/** Offsets a point off a surface to the side `dir` leaves on, against self-intersection. */
GVec3 offset_origin(GVec3 p, GVec3 n, GVec3 dir);

/** Computes the camera frame for an image size. */
void camera_setup(Camera *c, int width, int height);
/** The primary ray through image position (x, y) in pixels (y down from the top). */
void camera_ray(const Camera *c, double x, double y, Ray *r);
/** The side of the jittered grid for n samples when n is a square above 1, else 0. */
int strata_grid(int n);
/** A random permutation of 0..n-1 (pairs the x and y strata of N-rooks sampling). */
void strata_shuffle(Rng *rng, int n, int *perm);
/** Sample position i of n in the unit square: a jittered grid when grid = strata_grid(n) is not 0,
 * otherwise N-rooks (stratified in x and in y, paired by perm); n = 1 gives the centre. */
void pixel_sample(Rng *rng, int i, int n, int grid, const int *perm, double *sx, double *sy);

typedef struct RenderSettings {
    int width, height, spp, depth, threads, quiet;
    double cutoff; /**< adaptive depth control threshold (0: off) */
} RenderSettings;

/** Linear sRGB pixels (from the model's XYZ), row by row from the top. */
typedef struct Framebuffer {
    int width, height;
    float *pixels; /**< 3 floats per pixel */
} Framebuffer;

typedef struct RenderStats {
    double seconds;
    uint64_t rays;
    uint64_t nonfinite; /**< samples that were NaN or infinite (replaced by black) */
    int threads;
} RenderStats;

/** Renders the scene (accel_build must have run). fb->pixels is allocated here (free with framebuffer_free). */
int render_image(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err);
void framebuffer_free(Framebuffer *fb);

/** Progress bar on stderr (progress.c): shown only when stderr is a terminal and not quiet. */
typedef struct Progress {
    int enabled;
    long total, done;
    double start, last;
} Progress;
void progress_start(Progress *p, long total, int quiet);
/** Adds finished work; redraws at most ten times a second (call from one thread at a time). */
void progress_add(Progress *p, long n);
void progress_finish(Progress *p);
/** Seconds on a monotonic clock. */
double now_seconds(void);

/** Writes the framebuffer by extension: .exr linear float; .png/.jpg/.jpeg sRGB-encoded after
 * 2^exposure scaling, clamped to [0,1]. Writes a temporary file and renames it, so a failed write
 * leaves no partial file. */
int output_write(const char *path, const Framebuffer *fb, double exposure, GError *err);

/* ---- light probes (probe_light.c, probe_sample.c) ---- */

/** The probe as a piecewise-constant distribution over its pixels, proportional to each pixel's brightness
 * in the scene's colour model times its solid angle (probe_sample.c). */
typedef struct ProbeDist {
    int w, h;
    double *row_cdf; /**< h + 1 running sums of the rows' weights */
    double *col_cdf; /**< h rows of w + 1 running sums of the pixels' weights */
} ProbeDist;

/** The technique value of the reference mode (next to the library's GProbeTechnique values). */
#define PROBE_REFERENCE GPROBE_TECHNIQUE_COUNT

/** A `light probe` entry: its settings, the probe once loaded, and the lights made from it. */
typedef struct ProbeEnv {
    /* settings: the scene file's, then the command line's */
    char *file;          /**< the probe image (resolved against the scene file's directory) */
    int technique;       /**< a GProbeTechnique, or PROBE_REFERENCE */
    int count;           /**< technique: number of lights */
    int samples;         /**< reference: samples per shading point */
    int fit_normals;     /**< irradiance: normals the fit uses (0: the library's default) */
    GVec3 rotate;        /**< degrees about x, then y, then z (gprobe_rotation_xyz) */
    double scale;        /**< multiplies the probe's radiance */
    int background;      /**< the probe is what rays leaving the scene see */
    int shadows;         /**< reference: cast shadow rays */
    GProbeFormat format; /**< how the image maps to directions */
    char where[256];     /**< "file:line:col" of the entry, for messages */
    /* made by probe_attach */
    GProbe *probe;
    double R[9];         /**< probe space -> world, row-major */
    Light **lights;      /**< the lights it gave the scene (owned) */
    int nlights;
    ProbeDist dist;      /**< reference: the sampling distribution */
    double seconds;      /**< loading and approximating */
    double error_mean;   /**< technique: mean irradiance error of the lights in percent (the paper's measure) */
} ProbeEnv;

/** Command-line replacements for the settings of the scene's `light probe` entries (NULL, 0 or -1: keep). */
typedef struct ProbeOverride {
    const char *file;      /**< probe image, relative to the current directory */
    const char *technique; /**< mediancut, adaptive, kmeans, irradiance or reference */
    int count;             /**< number of lights */
    int samples;           /**< reference: samples per shading point */
    double scale;          /**< radiance scale */
    int shadows;           /**< reference: 1 on, 0 off, -1 keep */
} ProbeOverride;

/** The parse routine and destructor of `light probe` (registered by gtrace_register_types). */
int probe_light_parse(GReader *r, const void *vtable, void **object, GError *err);
void probe_light_destroy(void *object);
/** Applies command-line replacements to every probe entry of a loaded library (before scene_from_library);
 * G_ERR_INVALID when the library has none or a value does not fit. */
int probe_override_apply(GLibrary *lib, const ProbeOverride *ov, GError *err);
/** Loads the probe of an entry, makes its lights (directional lights of a technique, or one LIGHT_PROBE light
 * for the reference) and adds them to the scene; the probe becomes the scene's background unless the entry
 * says `background off`. Called by scene_from_library; the entry keeps owning what it made. */
int probe_attach(Scene *s, ProbeEnv *env, GError *err);
/** A direction of the probe in world space (turned by the entry's rotation). */
GVec3 probe_to_world(const ProbeEnv *env, GVec3 d);
/** Radiance seen along direction d leaving the scene (d in world space). */
int probe_background(const ProbeEnv *env, GVec3 d, GColor *out);
/** Prints one line per probe entry of the scene (file, size, technique, lights, time, irradiance error). */
void probe_describe(const Scene *s, FILE *f);
/** Reads a scene file like scene_load, applying ov (NULL: nothing) to its light probes before they load. */
int scene_load_with(const char *path, const char *colormodel, const ProbeOverride *ov, Scene **out, GError *err);

/** Adds the light of one sample (lights.c): color * scale arrives from direction `in` over dist (INFINITY
 * for distant light), reflected by the material towards out_dir and shadowed. */
int sample_light(TraceCtx *c, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 in, double dist,
                 const GColor *color, double scale, GVec3 out_dir, LightTmp *t, GColor *result);

/** Builds the distribution of probe p with brightness measured in model. */
int probe_dist_build(ProbeDist *d, const GProbe *p, const GColorModel *model, GError *err);
/** Frees the tables (a zeroed ProbeDist is fine). */
void probe_dist_free(ProbeDist *d);
/** Maps (u1, u2) in [0,1)^2 to a direction in probe space inside pixel (*u, *v), uniform in solid angle within
 * the pixel; returns the density of the direction in solid angle (0: the probe is black). */
double probe_dist_sample(const ProbeDist *d, const GProbe *p, double u1, double u2, int *u, int *v,
                         GVec3 *dir);
/** Density in solid angle of a direction in probe space. */
double probe_dist_pdf(const ProbeDist *d, const GProbe *p, GVec3 dir);
/** The reference mode of a probe: its direct light at sp estimated from l->samples directions drawn from the
 * distribution (stratified), each shadowed and reflected through the material like any light. */
int probe_light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media,
                      GVec3 out_dir, int opaque, LightTmp *t, GColor *result);

#endif
