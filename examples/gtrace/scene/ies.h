/* ies.h - IES LM-63 photometric data (ies.c): a luminaire's candela distribution read from an LM-63-1995 or -2002
 * file (and the 1986 form without a version line), photometric types C and B, every symmetry the standard allows;
 * the intensity in any direction and the luminous flux the table holds. */
#ifndef GTRACE_IES_H
#define GTRACE_IES_H

#include <generic/error.h>
#include <generic/vec.h>

#include <stddef.h>

/** Largest number of vertical and of horizontal angles a file may give, and of candela values in all. */
#define IES_MAX_ANGLES 1441
#define IES_MAX_VALUES 1000000
/** Largest IES file read, in bytes. */
#define IES_MAX_FILE_SIZE (16u << 20)

/** Photometric types (LM-63's field 6). */
typedef enum IesType { IES_TYPE_C = 1, IES_TYPE_B = 2 } IesType;

/** A candela table: cd[h * nv + v] at vertical angle v[v] and horizontal angle h[h], in degrees, already
 * multiplied by the file's candela multiplier and ballast factors. */
typedef struct IesData {
    int type;     /**< an IesType */
    int nv, nh;
    double *v, *h;
    double *cd;
    double lumens; /**< the lamps' rated lumens (number of lamps times lumens per lamp); -1: absolute photometry */
    int version;   /**< 1986, 1995 or 2002 */
} IesData;

/** Reads an LM-63 text of len bytes (name: the file's name in messages) into d. Every value is checked: counts
 * that disagree with the values present, truncation, numbers that are not finite, angles out of range or not
 * increasing, negative candela, tables beyond IES_MAX_ANGLES or IES_MAX_VALUES, photometric type A and TILT from
 * another file are refused with "NAME:LINE:COL: message" (G_ERR_INVALID, or G_ERR_UNSUPPORTED for what the
 * standard allows but gtrace does not read). On failure d is left empty. */
int ies_parse(const char *text, size_t len, const char *name, IesData *d, GError *err);
/** Reads the file at path (at most IES_MAX_FILE_SIZE bytes) with ies_parse. */
int ies_read(const char *path, IesData *d, GError *err);
/** Frees the tables (d itself is the caller's; a zeroed or freed d is a no-op). */
void ies_free(IesData *d);
/** The intensity in candela towards the photometric angles (vertical, horizontal) in degrees: type C, vertical
 * from nadir (0) to zenith (180) and horizontal around the vertical axis; type B, vertical the elevation (-90 to
 * 90) from the plane through the aim perpendicular to the horizontal polar axis and horizontal the rotation about
 * that axis. The table is unfolded by its symmetry and interpolated bilinearly; 0 outside the vertical range it
 * covers. */
double ies_candela(const IesData *d, double vertical, double horizontal);
/** The intensity in candela towards a unit direction given in the luminaire's frame: `aim` is the photometric
 * axis (type C: nadir; type B: the direction of angles 0, 0), `along` the direction of horizontal angle 0 (type
 * C) or the polar axis (type B), `third` = aim x along. */
double ies_candela_dir(const IesData *d, GVec3 dir, GVec3 aim, GVec3 along, GVec3 third);
/** The luminous flux of the table in lumens, the integral of the intensity over the sphere (numerically, on a grid
 * of steps fine enough for the table's angles). */
double ies_flux(const IesData *d);

#endif
