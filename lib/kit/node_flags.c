/* node_flags.c - the node kit's GMAT_NO_EMISSION, GMAT_OPAQUE, GMAT_GEOMETRIC_NORMAL, GMAT_LAMBERTIAN, GMAT_NO_UV,
 * GMAT_DIAGONAL, GMAT_NO_IDEAL and GMAT_NO_REL_INDEX (generic/kit/node_kit.h): a node whose emission only combines its
 * children's emits nothing when none of them does, one whose opacity is its children's is opaque everywhere when each
 * of them is, one whose normal blends its children's keeps the geometric normal when each of them does, so the dispatch
 * answers it without a call; a blend whose reflection and diffuse colour are the same blend of its children's is
 * Lambertian when each of them is, so a renderer reflects the light of all its samples at once, and so is a one-child
 * node whose reflection and diffuse colour are its child's times the same factor, at a point with the same normals
 * (bump, scale, image, transform); one whose reflection and refraction sum its children's filters light sample by
 * sample when each of them does (GMAT_DIAGONAL); one whose ideal rays are its children's has none when none of them has
 * (GMAT_NO_IDEAL); one that reads the point only through a generator not in (u, v) space, over children that never read
 * (u, v), lets the renderer skip the parametrisation; one that reads no relative index itself, over children that
 * read none, lets the renderer skip computing it (GMAT_NO_REL_INDEX); one whose refraction index is its one
 * child's has a constant index when the child has (GMAT_CONSTANT_INDEX); and one whose absorption is always one
 * child's absorbs nothing when those children absorb nothing (GMAT_CLEAR). */
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

int gnode_children_no_rel_index(GMaterial *const *children, int n)
{
    return children_all(children, n, GMAT_NO_REL_INDEX);
}

void gnode_inherit_no_rel_index(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && gnode_children_no_rel_index(children, n))
        node->flags |= GMAT_NO_REL_INDEX;
}

/* 1 when every slot of c is empty, the kit's pass-through or the kit's blend. */
static int kit_slots_only(const GMaterialClass *c)
{
    int kit = 1;
#define KIT_SLOT(name, NAME, type, attr, unless, dispatch, blend, params, args)                                    \
    kit = kit && (!c->name || c->name == gnode_child_##name || c->name == gnode_blended_##name);
    GMATERIAL_METHODS(KIT_SLOT)
#undef KIT_SLOT
    return kit;
}

void gnode_inherit_kit_no_rel_index(GMaterial *node, GMaterial *const *children, int n)
{
    if (!node || !kit_slots_only(node->cls))
        return;
    const GMaterialClass *c = node->cls;
    if (c->refraction == gnode_blended_refraction || c->sample == gnode_blended_sample)
        for (int i = 0; i < n; i++) /* the blend's ideal-refraction test reads the index where a child has a ray */
            if (!children || !children[i] || !(children[i]->flags & (GMAT_OPAQUE | GMAT_NO_IDEAL)))
                return;
    gnode_inherit_no_rel_index(node, children, n);
}

void gnode_inherit_constant_index(GMaterial *node, const GMaterial *child)
{
    if (node && child && (child->flags & GMAT_CONSTANT_INDEX))
        node->flags |= GMAT_CONSTANT_INDEX;
}

void gnode_inherit_kit_constant_index(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && node->cls->refraction_index == gnode_child_refraction_index && n == 1 && children)
        gnode_inherit_constant_index(node, children[0]);
}

void gnode_inherit_clear(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && children_all(children, n, GMAT_CLEAR))
        node->flags |= GMAT_CLEAR;
}

void gnode_inherit_kit_clear(GMaterial *node, GMaterial *const *children, int n)
{
    if (node && node->cls->absorption == gnode_child_absorption && n == 1)
        gnode_inherit_clear(node, children, 1);
}
