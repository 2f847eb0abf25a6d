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

typedef struct GColorModelOptions { double step_nm; double min_nm; double max_nm; } GColorModelOptions;

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

int gtrace_embed_register(GError *err);
int gtrace_render_file(const GtraceRenderRequest *rq, GtraceImage *img, GError *err);
void gtrace_image_free(GtraceImage *img);
"""

# The headers the declarations come from (for the drift check).
HEADERS = ["generic/builtins.h", "generic/batch.h", "generic/reader.h", "generic/registry.h", "generic/memory.h",
           "generic/services/image.h", "embed/render_file.h"]
