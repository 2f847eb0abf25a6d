/* camera.h - the pinhole camera and the pixel samples (camera.c). */
#ifndef GTRACE_CAMERA_H
#define GTRACE_CAMERA_H

#include "ray.h"
#include "rng.h"

#include <generic/material.h>
#include <generic/vec.h>

typedef struct Camera {
    GVec3 from, at, up;
    double fov;            /**< vertical field of view in degrees */
    int width, height;     /**< image size (command line overrides) */
    int spp, depth;        /**< samples per pixel, recursion depth */
    double cutoff;         /**< adaptive depth: rays whose weight in the pixel falls below this are not traced */
    double exposure;       /**< stops applied to .png/.jpg output */
    int bands;             /**< most wavelength groups a dispersive refraction splits into (bands.h) */
    GMaterial *medium;     /**< the medium the camera is in (borrowed from the library; NULL: vacuum) */
    /* derived by camera_setup */
    GVec3 eye, right, upv, forward;
    double half_h, half_w; /**< tan of the half angles */
    double spread;         /**< ray cone spread angle per pixel (radians) */
} Camera;

/** Default camera: looking down -z from (0,0,5), 40 degrees, 320x240, 1 spp, depth 8. */
void camera_defaults(Camera *c);
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

#endif
