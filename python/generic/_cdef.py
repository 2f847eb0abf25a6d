"""The C declarations the package calls, written by hand from the public headers (include/generic/) and gtrace's
embedding header (examples/gtrace/embed/render_file.h). Structs whose fields Python reads or fills are laid out in
full; everything else is opaque. tests/python/test_cdef.py compiles a C file generated from this text against the
real headers, so that any drift (a changed prototype, field or constant) fails the tests."""

CDEF = r"""
typedef struct GColorModel GColorModel;
typedef struct GMaterial GMaterial;
typedef struct GGenerator GGenerator;
typedef struct GLibrary GLibrary;
typedef struct GScratch GScratch;
typedef struct GSurfPoint GSurfPoint;
typedef struct GTypeInfo GTypeInfo;
typedef struct GImageWriteOptions GImageWriteOptions;

typedef struct GVec3 { double x, y, z; } GVec3;

typedef struct GError {
    int code;
    int line, col;
    char param[32];
    char message[512];
} GError;

enum { G_OK = 0, G_ERR_INVALID = -1, G_ERR_NOMEM = -2, G_ERR_IO = -3, G_ERR_PARSE = -4, G_ERR_MISMATCH = -5,
       G_ERR_VERSION = -6, G_ERR_NOTFOUND = -7, G_ERR_EXISTS = -8, G_ERR_UNSUPPORTED = -9 };

typedef enum GColorRole { GCOLOR_REFLECTANCE = 0, GCOLOR_LIGHT = 1 } GColorRole;

typedef enum GKind { GKIND_COLORMODEL = 0, GKIND_COLOR = 1, GKIND_MATERIAL = 2, GKIND_NODE = 3,
                     GKIND_GENERATOR = 4 } GKind;

typedef struct GColorModelOptions { double step_nm; double min_nm; double max_nm; int uplift; } GColorModelOptions;

typedef struct GReaderOptions {
    const GColorModel *model;
    const char *colormodel;
    const GColorModelOptions *colormodel_options;
    int max_depth;
    size_t max_file_size;
    int no_plugins;
    int allow_plugins;
    const char *confine_dir;
    unsigned skip_kinds;
} GReaderOptions;

typedef enum GBatchOutput { GBATCH_SAMPLES = 0, GBATCH_XYZ = 1, GBATCH_RGB = 2 } GBatchOutput;

typedef struct GBatchPoints {
    size_t n;
    const double *normal;
    const double *point;
    const double *uv;
    const double *dpdu;
    const double *dpdv;
    int threads;
} GBatchPoints;

typedef struct GImage { int width; int height; int channels; float *pixels; } GImage;

typedef struct GtraceRenderRequest {
    const char *scene;
    const char *colormodel;
    int width, height;
    int spp;
    int depth;
    int integrator;
    int threads;
    int crop[4];
    int allow_plugins;
    const char *confine_dir;
} GtraceRenderRequest;

typedef struct GtraceImage {
    int width, height;
    int x, y, full_width, full_height;
    float *pixels;
} GtraceImage;

int generic_register_builtins(GError *err);
const char *gstatus_string(int code);
void gmem_free(void *ptr);

int gcolormodel_create(const char *name, const GColorModelOptions *opt, GColorModel **out, GError *err);
void gcolormodel_destroy(GColorModel *m);
const char *gcolormodel_name(const GColorModel *m);
int gcolormodel_wavelengths(const GColorModel *m, double *nm, int max);

int greader_load_file(const char *path, const GReaderOptions *opt, GLibrary **out, GError *err);
void glibrary_destroy(GLibrary *lib);
const GColorModel *glibrary_colormodel(const GLibrary *lib);
void *glibrary_find(const GLibrary *lib, GKind kind, const char *name);
GMaterial *glibrary_material(const GLibrary *lib, const char *name);
int glibrary_count(const GLibrary *lib, GKind kind);
void *glibrary_entry(const GLibrary *lib, GKind kind, int i, const char **name, const GTypeInfo **type);

void gregistry_names(GKind kind, char *buf, size_t size);
int gkind_find(const char *keyword, GKind *out);
int gkind_count(void);
const char *gkind_name(GKind kind);

const char *gmaterial_name(const GMaterial *m);
GMaterial *gmaterial_ref(GMaterial *m);
void gmaterial_unref(GMaterial *m);
const char *ggenerator_name(const GGenerator *g);

GScratch *gscratch_create(size_t bytes);
void gscratch_destroy(GScratch *s);
GSurfPoint *gsurfpoint_new(const GColorModel *model, GScratch *scratch, GVec3 point, GVec3 normal, GVec3 dpdu,
                           GVec3 dpdv, double u, double v, int surface, GError *err);
void gsurfpoint_free(GSurfPoint *sp);
size_t gsurfpoint_size(void);

int gbatch_output_width(const GColorModel *m, GBatchOutput output);
int gbatch_reflection(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out,
                      GBatchOutput output, double *result, GError *err);
int gbatch_refraction(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out,
                      GBatchOutput output, double *result, GError *err);
int gbatch_emission(const GMaterial *m, const GBatchPoints *pts, const double *out, GBatchOutput output,
                    double *result, GError *err);
int gbatch_pdf(const GMaterial *m, const GBatchPoints *pts, const double *in, const double *out, double *pdf,
               GError *err);
int gbatch_sample(const GMaterial *m, const GBatchPoints *pts, const double *out, const double *u,
                  GBatchOutput output, double *in, double *pdf, int *flags, double *weight, GError *err);
int gbatch_generator_value(const GGenerator *g, const GColorModel *model, const GBatchPoints *pts, double *value,
                           GError *err);
int gbatch_color_to(const GColorModel *m, size_t n, const float *samples, GColorRole role, GBatchOutput output,
                    double *result, int threads, GError *err);
int gbatch_color_from_rgb(const GColorModel *m, size_t n, const double *rgb, GColorRole role, float *samples,
                          int threads, GError *err);

int gimage_read(const char *path, unsigned flags, GImage *img, GError *err);
int gimage_write(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err);
void gimage_free(GImage *img);

typedef struct GColor {
    const GColorModel *model;
    float *v;
    int kind;
    int storage;
    int capacity;
} GColor;

struct GMaterial {
    const struct GMaterialClass *cls;
    const GColorModel *model;
    int refcount;
    int depth;
    int cost;
    unsigned flags;
};

typedef struct GMaterialSample { GVec3 in; double pdf; int flags; } GMaterialSample;

typedef struct GMaterialClass {
    int abi_version;
    const char *name;
    const char *description;
    void (*destroy)(GMaterial *self);
    int (*reflection)(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out, GColor *result);
    int (*refraction)(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, const GColor *rel_index,
                      GVec3 out, GColor *result);
    int (*refraction_index)(const GMaterial *self, GSurfPoint *sp, GColor *result);
    int (*reflection_dir)(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir);
    int (*refraction_dir)(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir);
    int (*emission)(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result);
    int (*ambient)(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result);
    int (*absorption)(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result);
    int (*normal)(const GMaterial *self, GSurfPoint *sp, GVec3 *n);
    int (*diffuse)(const GMaterial *self, GSurfPoint *sp, GColor *result);
    int (*opaque)(const GMaterial *self, GSurfPoint *sp);
    int (*sample)(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1, double u2,
                  GMaterialSample *s, GColor *weight);
    double (*pdf)(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index);
    int (*is_delta)(const GMaterial *self, GSurfPoint *sp);
} GMaterialClass;

enum { GMATERIAL_ABI_VERSION = 4 };

typedef struct GReader GReader;
typedef int (*GParseFn)(GReader *reader, const void *vtable, void **object, GError *err);
typedef enum GParamForm { GPARAM_NAMED = 0, GPARAM_POSITIONAL = 1 } GParamForm;
typedef struct GParamInfo {
    const char *name;
    GParamForm form;
    const char *type;
    const char *def;
    const char *range;
    const char *doc;
} GParamInfo;

struct GTypeInfo {
    GKind kind;
    const char *name;
    const void *vtable;
    GParseFn parse;
    const char *summary;
    void (*destroy)(void *object);
    const struct GParamInfo *params;
};

int gerror_set(GError *err, int code, const char *fmt, ...);
int gregistry_add(const GTypeInfo *info, GError *err);
const GTypeInfo *gregistry_find(GKind kind, const char *name);
int greader_param(GReader *r, const char **key, GError *err);
int greader_unknown_param(GReader *r, const char *expected, GError *err);
int greader_color(GReader *r, GColorRole role, GColor *out, GError *err);
int greader_number_in(GReader *r, double lo, double hi, double *out, GError *err);
const GColorModel *greader_colormodel(GReader *r);
int gmaterial_param_default(GReader *r, double grey, GColorRole role, GColor *c, GError *err);
int gmaterial_init(GMaterial *m, const GMaterialClass *cls, const GColorModel *model, GError *err);
double gmaterial_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n);
GVec3 gsurfpoint_normal(GSurfPoint *sp);
int gcolor_alloc(GColor *c, const GColorModel *m);
void gcolor_free(GColor *c);
int gcolor_copy(GColor *dst, const GColor *src);
void gcolor_black(GColor *c);
int gcolor_add(GColor *out, const GColor *a, const GColor *b);
int gcolor_mul(GColor *out, const GColor *a, const GColor *b);
int gcolor_mul_scaled(GColor *out, const GColor *a, const GColor *b, double s);
int gcolor_scale(GColor *out, const GColor *a, double s);
int gcolor_fill(GColor *out, double value);
double gcolor_brightness(const GColor *c);
double gcolor_brightness_as(const GColor *c, GColorRole role);
int gcolor_from_rgb(GColor *c, const double rgb[3], GColorRole role);
int gcolor_to_xyz(const GColor *c, GColorRole role, double xyz[3]);
int gcolor_to_rgb(const GColor *c, GColorRole role, double rgb[3]);
int gmaterial_reflection(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out, GColor *result);

int gmat_check_file(const char *file, const char *material, const char *colormodel, int samples, int allow_plugins,
                    GError *err);

int gtrace_embed_register(GError *err);
int gtrace_render_file(const GtraceRenderRequest *rq, GtraceImage *img, GError *err);
void gtrace_image_free(GtraceImage *img);
"""

# The headers the declarations come from (for the drift check).
HEADERS = ["generic/builtins.h", "generic/batch.h", "generic/reader.h", "generic/registry.h", "generic/memory.h",
           "generic/plugin.h", "generic/kit/material_kit.h", "generic/kit/material_params.h",
           "generic/services/image.h", "embed/render_file.h", "gmat/check_file.h"]
