/* bad_module.c - broken modules for tests/test_plugin.c, built four ways by the test plug-in table (tests/build.mk):
 *   -DBAD_ABI       exports another generic_module_abi than the library's (must be refused, naming both);
 *   -DFAIL_INIT     registers a type and then fails its init (nothing may stay registered);
 *   -DNO_INIT       exports the version but no entry point;
 *   -DNOT_A_MODULE  a shared object without either module symbol (built as constructor_only.so).
 * Each has an ELF constructor that creates the file named by GENERIC_TEST_CONSTRUCTOR_MARK (when set): the
 * loader must refuse all but FAIL_INIT before their constructor runs. */
#include <generic/plugin.h>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

__attribute__((constructor)) static void mark_constructor_ran(void)
{
    const char *mark = getenv("GENERIC_TEST_CONSTRUCTOR_MARK");
    int fd = mark ? open(mark, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600) : -1;
    if (fd >= 0)
        close(fd);
}

#ifndef NOT_A_MODULE

#ifdef BAD_ABI
GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION + 41;
#else
GENERIC_MODULE_EXPORT const int generic_module_abi = GMODULE_ABI_VERSION;
#endif

#ifndef NO_INIT
static const GMaterialClass never_class = {.abi_version = GMATERIAL_ABI_VERSION, .name = "never_registered"};

GENERIC_MODULE_EXPORT int generic_module_init(GModuleApi *api, GError *err)
{
    static const GTypeInfo type = {GKIND_MATERIAL, "never_registered", &never_class, NULL, "must not stay", NULL, NULL};
    int rc = api->add_type(api, &type, err);
#ifdef FAIL_INIT
    if (rc == G_OK)
        rc = gerror_set(err, G_ERR_INVALID, "this module always fails");
#endif
    return rc;
}
#endif
#endif /* NOT_A_MODULE */
