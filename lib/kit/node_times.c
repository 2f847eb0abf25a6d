/* node_times.c - one-child nodes whose light-carrying results are the child's times a colour at the point
 * (GNodeTimes, generic/kit/node_kit.h). */
#include "generic/kit/node_kit.h"

static int times(const GMaterial *self, GSurfPoint *sp, int rc, GColor *result)
{
    return rc != G_OK ? rc : ((const GNodeTimes *)self)->times(self, sp, result);
}

int gnode_times_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                           GColor *result)
{
    return times(self, sp, gmaterial_reflection(gnode_child_of(self), sp, in, illum, out, result), result);
}

int gnode_times_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                           const GColor *rel_index, GVec3 out, GColor *result)
{
    return times(self, sp, gmaterial_refraction(gnode_child_of(self), sp, in, illum, rel_index, out, result),
                 result);
}

int gnode_times_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    return times(self, sp, gmaterial_emission(gnode_child_of(self), sp, out, result), result);
}

int gnode_times_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    return times(self, sp, gmaterial_ambient(gnode_child_of(self), sp, illum, result), result);
}

int gnode_times_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return times(self, sp, gmaterial_diffuse(gnode_child_of(self), sp, result), result);
}

int gnode_times_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                       double u2, GMaterialSample *s, GColor *weight)
{
    int rc = gmaterial_sample(gnode_child_of(self), sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        return rc;
    rc = ((const GNodeTimes *)self)->times(self, sp, weight);
    return rc ? rc : 1;
}
