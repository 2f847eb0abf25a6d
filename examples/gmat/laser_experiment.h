/* laser_experiment.h - the laser experiment of Wilkie et al. (the paper's sections 3 and 6), for `gmat laser`
 * (laser_experiment.c). */
#ifndef GMAT_LASER_EXPERIMENT_H
#define GMAT_LASER_EXPERIMENT_H

#include <generic/material.h>


/** Rings gfluor_laser_split starts from, and steps around the mirror direction by default. */
#define GFLUOR_LASER_RINGS 192
/** Most rings gfluor_laser_split doubles to. */
#define GFLUOR_LASER_MAX_RINGS 6144
/** Largest change of kept and shifted between the last two ring counts when gfluor_laser_split stops. */
#define GFLUOR_LASER_TOLERANCE 1e-4

/** How finely gfluor_laser_split integrates over the hemisphere; zeros take the defaults. */
typedef struct GFluorLaserOptions {
    int n_theta; /**< rings around the mirror direction; 0: adaptive, from GFLUOR_LASER_RINGS doubled until
                      kept and shifted change by at most GFLUOR_LASER_TOLERANCE (at most GFLUOR_LASER_MAX_RINGS) */
    int n_phi;   /**< steps around the mirror direction (default GFLUOR_LASER_RINGS) */
} GFluorLaserOptions;

/** What a material does with a collimated monochromatic beam. Fractions are of the incident power. */
typedef struct GFluorLaserSplit {
    double wavelength;  /**< the model sample the beam was placed on, nm (0 in non-spectral models) */
    double elevation;   /**< beam elevation above the surface, degrees */
    double kept;        /**< reflected at the beam's own wavelength (sample) */
    double shifted;     /**< re-emitted at other wavelengths */
    double dominant_nm; /**< dominant wavelength of the shifted light against equal-energy white (negative:
                             complementary wavelength of a purple); 0 when nothing is shifted */
    double peak_nm;     /**< the sample holding the most shifted power; 0 when nothing is shifted */
    int rings;          /**< rings the integration used */
} GFluorLaserSplit;

/** Shines a collimated beam of wavelength nm onto `material` at elevation_deg above the surface (normal +z,
 * the beam in the x-z plane) and integrates the reflected power over the hemisphere. The beam is put on the
 * model sample nearest to nm; kept is the power leaving on that sample, shifted the power on all others.
 * In a non-spectral model (nsamples == 0) nothing can shift: kept is the whole reflected power (measured
 * with a white beam) and shifted 0. scratch: an arena for temporaries. */
GENERIC_NODISCARD int gfluor_laser_split(const GMaterial *material, GScratch *scratch, double nm, double elevation_deg,
                       const GFluorLaserOptions *opt, GFluorLaserSplit *out, GError *err);

/** A reflection pattern on a white diffuse target (see gfluor_laser_pattern). */
typedef struct GFluorPattern {
    int width, height;
    double extent;        /**< the target spans [-extent, extent] across, in units of its distance */
    float *rgb;           /**< width * height * 3 linear sRGB values, exposed and tone mapped to [0, 1] */
    float *kept;          /**< width * height irradiance on the target at the beam's own wavelength */
    double kept_fwhm_h;   /**< full width at half maximum of the kept light across the plane of incidence */
    double kept_fwhm_v;   /**< the same along the plane of incidence (target units) */
    double aspect;        /**< kept_fwhm_v / kept_fwhm_h: 1 for a round lobe */
} GFluorPattern;

/** Draws the pattern the beam of gfluor_laser_split leaves on a white diffuse target that faces the lit spot
 * across the mirror direction, at distance 1 and perpendicular to it (the geometry of the paper's Fig. 2;
 * horizontal on the image is across the plane of incidence, up is towards the surface normal). Target points
 * below the sample's plane stay dark; a faint grid is printed on the target as in the paper. Measures the
 * lobe of kept light (its widths at half maximum through the brightest point). Free with
 * gfluor_pattern_free. */
GENERIC_NODISCARD int gfluor_laser_pattern(const GMaterial *material, GScratch *scratch, double nm,
                                           double elevation_deg, int width, int height, double extent,
                                           GFluorPattern *out, GError *err);
/** Frees a pattern's pixels; NULL and freed patterns are no-ops. */
void gfluor_pattern_free(GFluorPattern *p);

/** Dominant wavelength (nm) of a chromaticity (x, y) against equal-energy white; negative: the complementary
 * wavelength of a purple; 0 at the white point. */
double gfluor_dominant_wavelength(double x, double y);

#endif
