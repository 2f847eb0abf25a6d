/* param_tables.c - the parameter tables of gtrace's object, light and camera types (GParamInfo,
 * generic/registry.h), registered with them by parse.c: `gtrace types --markdown` prints them
 * (docs/reference/scene-types.md); tests/scripts/type_params.sh checks them against the parse routines' lists. */
#include "param_tables.h"

#define P_MATERIAL {"material", GPARAM_NAMED, "material", NULL, NULL, "the surface's material"}
#define P_INTERIOR                                                                                                     \
    {"interior", GPARAM_NAMED, "medium", "none", NULL,                                                                 \
     "the participating medium inside (path integrator; it belongs to the object's material)"}
#define P_TRANSFORM                                                                                                  \
    {"transform", GPARAM_NAMED, "block", "none",                                                                     \
     "{ translate <x, y, z>  rotate <ax, ay, az>  rotate_axis <axis> DEG  scale S | <x, y, z> ... }",               \
     "places the object: the steps in the order written (rotate: degrees about x, then y, then z)"}
#define P_VEC(name, def, doc) {name, GPARAM_NAMED, "vector", def, NULL, doc}
static const GParamInfo sphere_params[] = {
    P_VEC("center", "<0, 0, 0>", "the centre"),
    {"radius", GPARAM_NAMED, "number", "1", "[1e-12, 1e30]", "the radius"},
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo plane_params[] = {
    P_VEC("point", "<0, 0, 0>", "a point of the plane"),
    P_VEC("normal", "<0, 1, 0>", "the normal (not zero); the plane is bounded at 1e5 units"),
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo box_params[] = {
    P_VEC("min", "<-1, -1, -1>", "the corner with the smallest coordinates"),
    P_VEC("max", "<1, 1, 1>", "the opposite corner"),
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo disc_params[] = {
    P_VEC("center", "<0, 0, 0>", "the centre"),
    P_VEC("normal", "<0, 1, 0>", "the normal (not zero)"),
    {"radius", GPARAM_NAMED, "number", "1", "[1e-12, 1e30]", "the radius"},
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo cylinder_params[] = {
    P_VEC("base", "<0, 0, 0>", "the centre of the base (surface 1)"),
    P_VEC("top", "<0, 1, 0>", "the centre of the top (surface 2)"),
    {"radius", GPARAM_NAMED, "number", "1", "[1e-12, 1e30]", "the radius"},
    {"open", GPARAM_NAMED, "bool", "no", NULL, "yes: the side (surface 0) without the caps"},
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo mesh_params[] = {
    {"file", GPARAM_NAMED, "path", NULL, ".obj, .ply, .gltf, .glb",
     "the mesh; an OBJ's usemtl and g number the surfaces"},
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo quad_params[] = {
    P_VEC("corner", "<0, 0, 0>", "the corner P: the quad is P + u edge1 + v edge2, (u, v) in [0, 1]^2"),
    P_VEC("edge1", "<1, 0, 0>", "the edge along u"),
    P_VEC("edge2", "<0, 1, 0>", "the edge along v (the normal is edge1 x edge2)"),
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo triangle_params[] = {
    P_VEC("a", "<0, 0, 0>", "the first corner: the point is a + u (b - a) + v (c - a)"),
    P_VEC("b", "<1, 0, 0>", "the second corner"),
    P_VEC("c", "<0, 1, 0>", "the third corner (the normal is (b - a) x (c - a))"),
    P_MATERIAL, P_INTERIOR, P_TRANSFORM, {NULL},
};
static const GParamInfo group_params[] = {
    {"OBJECT", GPARAM_POSITIONAL, "object", NULL, "a nested object entry or the name of one, at least one",
     "the members, any number: one Embree scene that instances place; each becomes a prototype"},
    P_TRANSFORM, {NULL},
};
static const GParamInfo instance_params[] = {
    {"of", GPARAM_NAMED, "object", NULL, "a nested object entry or the name of one",
     "the object or group placed (it becomes a prototype)"},
    {"material", GPARAM_NAMED, "material", "the objects' own", NULL,
     "replaces the material of everything placed (the outermost instance that gives one wins)"},
    P_TRANSFORM, {NULL},
};
const GParamInfo *const scene_shape_tables[SCENE_SHAPE_TYPES] = {
    sphere_params, plane_params, box_params,      disc_params,  cylinder_params,
    mesh_params,   quad_params,  triangle_params, group_params, instance_params};

#define P_SAMPLES {"samples", GPARAM_NAMED, "integer", "16", "[1, 256]", "shadow rays per shading point"}
#define P_VISIBLE {"visible", GPARAM_NAMED, "bool", "no", NULL, "camera rays see the light's surface"}
static const GParamInfo point_params[] = {
    P_VEC("position", "<0, 0, 0>", "where the light is"),
    {"intensity", GPARAM_NAMED, "color", NULL, "luminance >= 0",
     "the intensity I, read as a light: the illumination at distance d is I / d^2"},
    {NULL},
};
static const GParamInfo directional_params[] = {
    P_VEC("direction", "<0, -1, 0>", "the direction the light travels (not zero)"),
    {"irradiance", GPARAM_NAMED, "color", NULL, "luminance >= 0", "the irradiance on a surface facing the light"},
    {NULL},
};
static const GParamInfo spot_params[] = {
    P_VEC("position", "<0, 0, 0>", "where the light is"),
    {"at", GPARAM_NAMED, "vector", NULL, "not the position", "the point the cone is aimed at"},
    {"intensity", GPARAM_NAMED, "color", NULL, "luminance >= 0", "the intensity on the cone's axis"},
    {"inner", GPARAM_NAMED, "number", "20", "[0, 180]", "the full opening angle of full intensity, in degrees"},
    {"outer", GPARAM_NAMED, "number", "30", "[0, 180], not below inner",
     "the full opening angle beyond which the light is dark, in degrees (smooth in between)"},
    {NULL},
};
static const GParamInfo sphere_light_params[] = {
    P_VEC("center", "<0, 0, 0>", "the centre"),
    {"radius", GPARAM_NAMED, "number", "1", "[1e-9, 1e30]", "the radius"},
    {"radiance", GPARAM_NAMED, "color", NULL, "luminance >= 0", "the radiance of its surface"},
    P_SAMPLES, P_VISIBLE, {NULL},
};
static const GParamInfo rectangle_params[] = {
    P_VEC("corner", "<-0.5, 2, 0.5>", "a corner P: the light is P + u edge1 + v edge2, (u, v) in [0, 1]^2"),
    P_VEC("edge1", "<1, 0, 0>", "one edge"),
    P_VEC("edge2", "<0, 0, -1>", "the other edge (not parallel); the lit side is that of edge1 x edge2"),
    {"radiance", GPARAM_NAMED, "color", NULL, "luminance >= 0", "the radiance of its lit side"},
    P_SAMPLES, P_VISIBLE, {NULL},
};
static const GParamInfo ambient_params[] = {
    {"color", GPARAM_NAMED, "color", NULL, "luminance >= 0",
     "the ambient light handed to every material's ambient() (several add up)"},
    {NULL},
};
static const GParamInfo background_params[] = {
    {"color", GPARAM_NAMED, "color", NULL, "luminance >= 0", "the radiance of rays that leave the scene"},
    {NULL},
};
static const GParamInfo ies_params[] = {
    {"file", GPARAM_NAMED, "path", NULL, "LM-63-1986, -1995 or -2002; types C and B; TILT=NONE or INCLUDE",
     "the luminaire's photometry: its candela table"},
    P_VEC("position", "<0, 0, 0>", "the photometric centre"),
    P_VEC("direction", "<0, -1, 0>", "the photometric axis: type C's nadir (vertical angle 0), type B's aim"),
    P_VEC("along", "perpendicular to direction", "type C: the direction of horizontal angle 0 (the luminaire's "
          "length); type B: the polar axis; its part perpendicular to direction is taken"),
    {"color", GPARAM_NAMED, "color", NULL, "luminance > 0",
     "the light's colour, e.g. illuminant A: the candela are converted with its luminous efficacy (683 lm/W times "
     "its luminous sum), so the light is in W/(sr nm)"},
    {"scale", GPARAM_NAMED, "number", "1", "[0, 1e30]", "multiplies the intensity"},
    {NULL},
};
const GParamInfo *const scene_light_tables[SCENE_LIGHT_TYPES] = {point_params,     directional_params, spot_params,
                                                 sphere_light_params, rectangle_params, ambient_params,
                                                 background_params, ies_params};

#define P_CAMERA_VIEW                                                                                                \
    P_VEC("from", "<0, 0, 5>", "the eye"), P_VEC("at", "<0, 0, 0>", "the point looked at (not from)"),                \
    P_VEC("up", "<0, 1, 0>", "the image's up direction"),                                                            \
    {"frame", GPARAM_NAMED, "number", "none", "[0, 10]",                                                             \
     "fits the scene's bounds (planes left out) into the view widened by 1 + MARGIN: `from` moves along the view "   \
     "line, `at` to the point nearest the bounds' centre; an orthographic camera's size is set"}
#define P_CAMERA_IMAGE                                                                                               \
    {"width", GPARAM_NAMED, "integer", "320", "[1, 65536]", "the image width in pixels (--width overrides)"},          \
    {"height", GPARAM_NAMED, "integer", "240", "[1, 65536]", "the image height in pixels"},                           \
    {"spp", GPARAM_NAMED, "integer", "1", "[1, 65536]",                                                               \
     "samples per pixel: a jittered grid when a square, else N-rooks"},                                               \
    {"depth", GPARAM_NAMED, "integer", "8", "[0, 1000]", "the recursion depth of reflected and refracted rays"},       \
    {"cutoff", GPARAM_NAMED, "number", "1e-3", "[0, 1]",                                                              \
     "rays whose weight in their pixel is below it are not traced (0: every ray to the depth)"},                     \
    {"exposure", GPARAM_NAMED, "number", "0", "[-30, 30]", "stops applied to display-encoded output (.png, .jpg)"},   \
    {"medium", GPARAM_NAMED, "material", "none (vacuum)", NULL,                                                       \
     "the material the camera sits in (its absorption applies along every ray in it)"},                              \
    {"atmosphere", GPARAM_NAMED, "medium", "none", NULL,                                                               \
     "the participating medium outside every object (path integrator)"},                                               \
    {"bands", GPARAM_NAMED, "integer", "16", "[1, 1024]",                                                             \
     "the most wavelength groups a dispersive refraction splits into (1: no dispersion)"}
#define P_FOV {"fov", GPARAM_NAMED, "number", "40", "[0.01, 179]", "the vertical field of view, in degrees"}
static const GParamInfo pinhole_params[] = {P_CAMERA_VIEW, P_FOV, P_CAMERA_IMAGE, {NULL}};
static const GParamInfo thinlens_params[] = {
    P_CAMERA_VIEW,
    P_FOV,
    {"aperture", GPARAM_NAMED, "number", "0", "[0, 1e6]",
     "the lens diameter in scene units (0: exactly the pinhole's image)"},
    {"focus_distance", GPARAM_NAMED, "number", "|at - from|", "[1e-9, 1e15]",
     "the distance of the plane in focus along the view direction"},
    P_CAMERA_IMAGE,
    {NULL},
};
static const GParamInfo orthographic_params[] = {
    P_CAMERA_VIEW,
    {"size", GPARAM_NAMED, "number", "2", "[1e-9, 1e15]", "the height of the window of parallel rays, in scene units"},
    P_CAMERA_IMAGE,
    {NULL},
};
const GParamInfo *const scene_camera_tables[SCENE_CAMERA_TYPES] = {pinhole_params, thinlens_params,
                                                                   orthographic_params};
