/* metals.c - looking up the measured optical constants of lib/kit/metal_table.c (generic/kit/metals.h). */
#include "generic/kit/metals.h"
#include "generic/kit/fresnel.h"
#include "metal_table.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

int gmetal_count(void) { return gmetal_data_count; }

int gmetal_info(int i, GMetalInfo *out)
{
    memset(out, 0, sizeof *out);
    if (i < 0 || i >= gmetal_data_count)
        return G_ERR_INVALID;
    const GMetalData *d = &gmetal_data[i];
    out->name = d->name;
    out->description = d->description;
    out->source = d->source;
    out->min_nm = d->min_nm;
    out->max_nm = d->max_nm;
    return G_OK;
}

int gmetal_find(const char *name)
{
    for (int i = 0; name && i < gmetal_data_count; i++)
        if (strcasecmp(gmetal_data[i].name, name) == 0)
            return i;
    return -1;
}

size_t gmetal_names(char *buf, size_t size)
{
    size_t len = 0;
    if (size > 0)
        buf[0] = '\0';
    for (int i = 0; i < gmetal_data_count; i++) {
        const char *sep = i ? ", " : "";
        int n = snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, "%s%s", sep, gmetal_data[i].name);
        len += (size_t)n;
    }
    return len;
}

static double table_at(const float *v, double nm)
{
    double x = (nm - GMETAL_GRID_MIN) / GMETAL_GRID_STEP;
    if (!(x > 0.0)) /* also NaN */
        return v[0];
    if (x >= GMETAL_GRID_N - 1)
        return v[GMETAL_GRID_N - 1];
    int j = (int)x;
    double t = x - j;
    return (1.0 - t) * v[j] + t * v[j + 1];
}

double gmetal_eta_at(int i, double nm)
{
    return i >= 0 && i < gmetal_data_count ? table_at(gmetal_data[i].eta, nm) : NAN;
}

double gmetal_k_at(int i, double nm) { return i >= 0 && i < gmetal_data_count ? table_at(gmetal_data[i].k, nm) : NAN; }

int gmetal_colors(int i, GColor *eta, GColor *k)
{
    if (i < 0 || i >= gmetal_data_count || !eta || !k)
        return G_ERR_INVALID;
    if (eta->model != k->model)
        return G_ERR_MISMATCH;
    GSpectrumNM n_nm, k_nm;
    for (int j = 0; j < GNM_COUNT; j++) {
        n_nm.v[j] = (float)table_at(gmetal_data[i].eta, GNM_MIN + j);
        k_nm.v[j] = (float)table_at(gmetal_data[i].k, GNM_MIN + j);
    }
    return gmaterial_complex_index_from_nm(eta, k, &n_nm, &k_nm);
}
