/* startup.h - how every tool of examples/ begins: the library's built-in types registered, then the modules that
 * --plugin FILE.so names loaded (those options taken out of argv), before the tool reads its own options. Header
 * only (a static function), on the public headers. */
#ifndef EXAMPLES_STARTUP_H
#define EXAMPLES_STARTUP_H

#include <generic/builtins.h>
#include <generic/plugin.h>

#include <stdio.h>

/** Registers the built-in types and loads the --plugin modules of argv (removing those options from *argc,
 * argv). Returns -1 to go on, else the exit status with its message printed: 1 when a registration or a load
 * failed ("PROG: message" for a load), 2 when a --plugin option is given wrong. */
static inline int startup(const char *prog, int *argc, char **argv)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    if (gplugin_load_args(argc, argv, &err) != G_OK) {
        fprintf(stderr, "%s: %s\n", prog, err.message);
        return err.code == G_ERR_INVALID ? 2 : 1;
    }
    return -1;
}

#endif
