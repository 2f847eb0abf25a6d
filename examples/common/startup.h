/* startup.h - how every tool of examples/ begins: the library's built-in types registered, the memory budget's
 * limit set by --memory-limit SIZE (or checked in the environment), then the modules that --plugin FILE.so names
 * loaded (those options taken out of argv), before the tool reads its own options. Header only (static functions),
 * on the public headers. */
#ifndef EXAMPLES_STARTUP_H
#define EXAMPLES_STARTUP_H

#include <generic/builtins.h>
#include <generic/memory.h>
#include <generic/plugin.h>

#include <stdio.h>
#include <string.h>

/** Takes --memory-limit SIZE and --memory-limit=SIZE out of argv (the last one counts; none after "--") and sets
 * the memory budget's limit (generic/memory.h: "512" MiB, "2G", ...); without it, checks GENERIC_MEMORY_LIMIT_MB and
 * GENERIC_IMAGE_BUDGET_MB. Returns -1 to go on, or 2 with a message naming the option or the variable. */
static inline int startup_memory_limit(const char *prog, int *argc, char **argv)
{
    const char *value = NULL;
    int out = 1, i = 1;
    for (; i < *argc && strcmp(argv[i], "--") != 0; i++) {
        if (strcmp(argv[i], "--memory-limit") == 0) {
            if (i + 1 >= *argc) {
                fprintf(stderr, "%s: option '--memory-limit' needs a value (see %s --help)\n", prog, prog);
                return 2;
            }
            value = argv[++i];
        } else if (strncmp(argv[i], "--memory-limit=", 15) == 0) {
            value = argv[i] + 15;
        } else {
            argv[out++] = argv[i];
        }
    }
    while (i < *argc)
        argv[out++] = argv[i++];
    argv[out] = NULL;
    *argc = out;
    GError err;
    size_t bytes;
    if (value && gmem_budget_parse(value, &bytes, &err) != G_OK) {
        fprintf(stderr, "%s: --memory-limit: %s (see %s --help)\n", prog, err.message, prog);
        return 2;
    }
    if (value)
        gmem_budget_set_limit(bytes);
    else if (gmem_budget_check_env(&err) != G_OK) {
        fprintf(stderr, "%s: %s\n", prog, err.message);
        return 2;
    }
    return -1;
}

/** Registers the built-in types, sets the memory limit (startup_memory_limit) and loads the --plugin modules of argv
 * (removing those options from *argc, argv). Returns -1 to go on, else the exit status with its message printed: 1
 * when a registration or a load failed ("PROG: message" for a load), 2 when a --plugin or --memory-limit option or
 * the environment's limit is given wrong. */
static inline int startup(const char *prog, int *argc, char **argv)
{
    int limit = startup_memory_limit(prog, argc, argv);
    if (limit >= 0)
        return limit;
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
