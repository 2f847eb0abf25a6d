/* technique.c - technique names and the common entry point. */
#include "probe_internal.h"

#include <string.h>

static const char *const names[GPROBE_TECHNIQUE_COUNT] = {"mediancut", "adaptive", "kmeans", "irradiance",
                                                                   "variance"};

const char *gprobe_technique_name(GProbeTechnique t)
{
    return (unsigned)t < GPROBE_TECHNIQUE_COUNT ? names[t] : "unknown";
}

int gprobe_technique_parse(const char *name, GProbeTechnique *t, GError *err)
{
    for (int i = 0; i < GPROBE_TECHNIQUE_COUNT; i++)
        if (name && strcmp(name, names[i]) == 0) {
            *t = (GProbeTechnique)i;
            return G_OK;
        }
    return gerror_set(err, G_ERR_NOTFOUND,
                      "unknown technique '%s' (expected mediancut, adaptive, kmeans, irradiance or variance)",
                      name ? name : "");
}

int gprobe_approximate(const GProbe *p, GProbeTechnique t, int n, const GProbeOptions *opt, GProbeLight *lights,
                       GError *err)
{
    if (!p || !lights)
        return gerror_set(err, G_ERR_INVALID, "gprobe_approximate: no probe or output given");
    switch (t) {
    case GPROBE_MEDIANCUT: return gprobe_median_cut(p, n, lights, err);
    case GPROBE_ADAPTIVE: return gprobe_adaptive_median_cut(p, n, lights, err);
    case GPROBE_KMEANS: return gprobe_kmeans(p, n, opt, lights, err);
    case GPROBE_IRRADIANCE: return gprobe_irradiance_fit(p, n, opt, lights, NULL, err);
    case GPROBE_VARIANCE: return gprobe_variance_cut(p, n, lights, err);
    default: return gerror_set(err, G_ERR_INVALID, "unknown technique %d", (int)t);
    }
}
