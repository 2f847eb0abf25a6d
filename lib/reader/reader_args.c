/* reader_args.c - the reader options every tool takes on its command line (--allow-plugins, --confine DIR). */
#include "generic/reader.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>

int greader_options_args(int *argc, char **argv, GReaderOptions *opt, GError *err)
{
    static const char confine[] = "--confine";
    int n = 1;
    for (int i = 1; i < *argc; i++) {
        const char *dir = NULL;
        if (strcmp(argv[i], "--allow-plugins") == 0) {
            opt->allow_plugins = 1;
            continue;
        } else if (strcmp(argv[i], confine) == 0) {
            if (i + 1 >= *argc)
                return gerror_set(err, G_ERR_INVALID, "--confine needs a value (a directory)");
            dir = argv[++i];
        } else if (strncmp(argv[i], confine, sizeof confine - 1) == 0 && argv[i][sizeof confine - 1] == '=') {
            dir = argv[i] + sizeof confine;
        } else {
            argv[n++] = argv[i];
            continue;
        }
        struct stat st;
        if (stat(dir, &st) != 0)
            return gerror_set(err, G_ERR_INVALID, "--confine \"%s\": %s", dir, strerror(errno));
        if (!S_ISDIR(st.st_mode))
            return gerror_set(err, G_ERR_INVALID, "--confine \"%s\": not a directory", dir);
        opt->confine_dir = dir;
    }
    *argc = n;
    argv[n] = NULL;
    return G_OK;
}
