/* node_flags.c - the node kit's GMAT_NO_EMISSION, GMAT_OPAQUE, GMAT_GEOMETRIC_NORMAL, GMAT_LAMBERTIAN, GMAT_NO_UV,
 * GMAT_DIAGONAL and GMAT_NO_IDEAL (generic/kit/node_kit.h): a node whose emission only combines its children's
 * emits nothing when none of them does, one whose opacity is its children's is opaque everywhere when each of them
 * is, one whose normal blends its children's keeps the geometric normal when each of them does, so the dispatch
 * answers it without a call; a blend whose reflection and diffuse colour are the same blend of its children's is
 * Lambertian when each of them is, so a renderer reflects the light of all its samples at once, and so is a
 * one-child node whose reflection and diffuse colour are its child's times the same factor, at a point with the same
 * normals (bump, scale, image, transform); one whose reflection and refraction sum its children's filters light
 * sample by sample when each of them does (GMAT_DIAGONAL); one whose ideal rays are its children's has none when
 * none of them has (GMAT_NO_IDEAL); and one that reads the point only through a generator not in (u, v) space, over
 * children that never read (u, v), lets the renderer skip the parametrisation. */
#include "generic/kit/node_kit.h"
#include "generic/texture.h"

/* 1 when each of the n children has the GMAT_* bit `flag`. */
static int children_all(GMaterial *const *children, int n, unsigned flag)
{
    if (!children || n <= 0)
        return 0;
    for (int i = 0; i < n; i++)
        if (!children[i] || !(children[i]->flags & flag))
            return 0;
    return 1;
}

int gnode_children_dark(GMaterial *const *children, int n) { return children_all(children, n, GMAT_NO_EMISSION); }

void gnode_inherit_no_emission(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_dark(children, n))
        node->flags |= GMAT_NO_EMISSION;
}

int gnode_children_opaque(GMaterial *const *children, int n) { return children_all(children, n, GMAT_OPAQUE); }

void gnode_inherit_opaque(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_opaque(children, n))
        node->flags |= GMAT_OPAQUE;
}

int gnode_children_geometric_normal(GMaterial *const *children, int n)
{
    return children_all(children, n, GMAT_GEOMETRIC_NORMAL);
}

void gnode_inherit_geometric_normal(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_geometric_normal(children, n))
        node->flags |= GMAT_GEOMETRIC_NORMAL;
}

void gnode_inherit_kit_normal(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && (node->cls->normal == gnode_blended_normal || node->cls->normal == gnode_child_normal))
        gnode_inherit_geometric_normal(node, children, n);
}

int gnode_children_lambertian(GMaterial *const *children, int n)
{
    return children_all(children, n, GMAT_LAMBERTIAN);
}

void gnode_inherit_lambertian(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && node->cls->reflection == gnode_blended_reflection && node->cls->diffuse == gnode_blended_diffuse &&
        gnode_children_lambertian(children, n))
        node->flags |= GMAT_LAMBERTIAN;
}

void gnode_inherit_lambertian_child(GMaterial *node, GMaterial *child)
{
    if (node && child && node != child && gnode_children_lambertian(&child, 1))
        node->flags |= GMAT_LAMBERTIAN;
}

int gnode_children_diagonal(GMaterial *const *children, int n)
{
    return children_all(children, n, GMAT_DIAGONAL);
}

void gnode_inherit_diagonal(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_diagonal(children, n))
        node->flags |= GMAT_DIAGONAL;
}

void gnode_inherit_kit_diagonal(GMaterial *node, GMaterial *const *children, int n)
{
    if (!node)
        return;
    const GMaterialClass *c = node->cls;
    if ((!c->reflection || c->reflection == gnode_blended_reflection || c->reflection == gnode_child_reflection) &&
        (!c->refraction || c->refraction == gnode_blended_refraction || c->refraction == gnode_child_refraction))
        gnode_inherit_diagonal(node, children, n);
}

int gnode_children_no_uv(GMaterial *const *children, int n, const GGenerator *gen)
{
    return children_all(children, n, GMAT_NO_UV) && !(gen && gen->space == GGENERATOR_SPACE_UV);
}

void gnode_inherit_no_uv(GMaterial *node, GMaterial *const *children, int n, const GGenerator *gen)
{
    if (node && gnode_children_no_uv(children, n, gen))
        node->flags |= GMAT_NO_UV;
}

int gnode_children_no_ideal(GMaterial *const *children, int n) { return children_all(children, n, GMAT_NO_IDEAL); }

void gnode_inherit_no_ideal(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_no_ideal(children, n))
        node->flags |= GMAT_NO_IDEAL;
}

void gnode_inherit_kit_no_ideal(GMaterial *node, GMaterial *const *children, int n)
{
    if (!node)
        return;
    const GMaterialClass *c = node->cls;
    if ((!c->reflection_dir || c->reflection_dir == gnode_blended_reflection_dir ||
         c->reflection_dir == gnode_child_reflection_dir) &&
        (!c->refraction_dir || c->refraction_dir == gnode_blended_refraction_dir ||
         c->refraction_dir == gnode_child_refraction_dir))
        gnode_inherit_no_ideal(node, children, n);
}
