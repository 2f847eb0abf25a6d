/* bad_module.c - broken modules for tests/test_plugin.c, built three ways by the Makefile's plug-in section:
 *   -DBAD_ABI    exports another generic_module_abi than the library's (must be refused, naming both);
 *   -DFAIL_INIT  registers a type and then fails its init (nothing may stay registered);
 *   -DNO_INIT    exports the version but no entry point. */
#include <generic/plugin.h>

#ifdef BAD_ABI
GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION + 41;
#else
GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;
#endif

#ifndef NO_INIT
static const GMaterialClass never_class = {.abi_version = GMATERIAL_ABI_VERSION, .name = "never_registered"};

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    static const GTypeInfo type = {GKIND_MATERIAL, "never_registered", &never_class, NULL, "must not stay", NULL};
    int rc = api->add_type(api, &type, err);
#ifdef FAIL_INIT
    if (rc == G_OK)
        rc = gerror_set(err, G_ERR_INVALID, "this module always fails");
#endif
    return rc;
}
#endif
