/* camera.h - the pinhole, thin-lens and orthographic cameras and the pixel samples (camera.c). */
#ifndef GTRACE_CAMERA_H
#define GTRACE_CAMERA_H

#include "geometry/ray.h"
#include "rng.h"

#include <generic/error.h>
#include <generic/material.h>
#include <generic/vec.h>

/** How the camera maps image positions to rays. */
typedef enum CameraProjection {
    CAMERA_PINHOLE,      /**< all rays from `from`, vertical field of view `fov` */
    CAMERA_THINLENS,     /**< a lens of diameter `aperture` focused at `focus_distance`: depth of field */
    CAMERA_ORTHOGRAPHIC  /**< parallel rays along the view direction through a window `size` units high */
} CameraProjection;

typedef struct Camera {
    CameraProjection projection;
    GVec3 from, at, up;
    double fov;            /**< vertical field of view in degrees (pinhole, thin lens) */
    double aperture;       /**< thin lens: diameter of the lens in scene units (0: a pinhole) */
    double focus_distance; /**< thin lens: distance of the plane in focus along the view direction (0: |at - from|) */
    double size;           /**< orthographic: height of the view in scene units */
    int width, height;     /**< image size (command line overrides) */
    int spp, depth;        /**< samples per pixel, recursion depth */
    double cutoff;         /**< adaptive depth: rays whose weight in the pixel falls below this are not traced */
    double exposure;       /**< stops applied to .png/.jpg output */
    int bands;             /**< most wavelength groups a dispersive refraction splits into (0: the renderer's
                                default, integrators/bands.h) */
    GMaterial *medium;     /**< the medium the camera is in (borrowed from the library; NULL: vacuum) */
    const struct Medium *atmosphere; /**< the participating medium outside every object (borrowed; NULL: none) */
    double frame;          /**< >= 0: the view fitted to the scene's bounds with this margin (camera_frame); < 0: off */
    GVec3 frame_lo, frame_hi; /**< the box camera_frame last fitted the view to */
    /* derived by camera_setup */
    GVec3 eye, right, upv, forward;
    double half_h, half_w; /**< tan of the half angles; orthographic: half the window in scene units */
    double focus;          /**< thin lens: the focus distance in use */
    double spread;         /**< ray cone spread angle per pixel (radians) */
} Camera;

/** Default camera: looking down -z from (0,0,5), 40 degrees, 320x240, 1 spp, depth 8, the default bands. */
void camera_defaults(Camera *c);
/** Fits the view to the box lo..hi for a width x height image, keeping the view direction and up. A pinhole or
 * thin-lens camera moves along its view line until every corner of the box lies within the field of view narrowed
 * by 1 + c->frame (c->frame 0.1 leaves a tenth of the half view free around the box); an orthographic camera sets
 * size so that the box fits its window narrowed so, and stands before the box. from is the new eye and at the point
 * of the view line nearest the box's centre (a thin lens without focus_distance is focused there). Records lo, hi
 * in frame_lo, frame_hi, so that it can be fitted again for another image size. G_ERR_INVALID when the box is
 * empty or not finite, or the eye would lie beyond the scene's coordinate limit (SCENE_MAX_COORD). */
int camera_frame(Camera *c, GVec3 lo, GVec3 hi, int width, int height, GError *err);
/** Computes the camera frame for an image size. */
void camera_setup(Camera *c, int width, int height);
/** The primary ray through image position (x, y) in pixels (y down from the top), through the centre of a
 * thin lens. */
void camera_ray(const Camera *c, double x, double y, Ray *r);
/** camera_ray through a random point of the lens (two numbers from rng, drawn only when the camera has a lens
 * of non-zero aperture: other cameras leave rng untouched and give camera_ray's ray). */
void camera_ray_lens(const Camera *c, double x, double y, Rng *rng, Ray *r);
/** 1 when camera_ray_lens draws nothing from rng (no lens, or one of zero aperture): its ray is camera_ray's, which
 * a renderer may then compute ahead of the pixel. */
int camera_is_pinhole(const Camera *c);
/** The side of the jittered grid for n samples when n is a square above 1, else 0. */
int strata_grid(int n);
/** A random permutation of 0..n-1 (pairs the x and y strata of N-rooks sampling). */
void strata_shuffle(Rng *rng, int n, int *perm);
/** Sample position i of n in the unit square: a jittered grid when grid = strata_grid(n) is not 0,
 * otherwise N-rooks (stratified in x and in y, paired by perm); n = 1 gives the centre. */
void pixel_sample(Rng *rng, int i, int n, int grid, const int *perm, double *sx, double *sy);

#endif
