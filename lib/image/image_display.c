/* image_display.c - display transforms (generic/services/image.h, GImageDisplay): which OpenColorIO config is used, and
 * the check before any work. The transform itself is OpenColorIO's, in the OpenImageIO module
 * (lib/image/ocio_display.cpp). */
#include "image_display.h"
#include "oiio_module.h"

#include "generic/services/file.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef GENERIC_DATADIR
#define GENERIC_DATADIR "/usr/local/share"
#endif

#define SHIPPED "share/generic/ocio/config.ocio"

/* DIR/../SHIPPED for the directory of the file at path; 1 when it exists (then in out). */
static int beside(const char *file, char *out, size_t size)
{
    char real[PATH_MAX];
    if (!file || !realpath(file, real))
        return 0;
    char *slash = strrchr(real, '/');
    if (!slash)
        return 0;
    *slash = 0;
    slash = strrchr(real, '/');
    if (slash)
        *slash = 0; /* DIR/.. */
    int n = snprintf(out, size, "%s/" SHIPPED, real);
    return n > 0 && (size_t)n < size && access(out, R_OK) == 0;
}

int gimage_display_config(const GImageDisplay *d, char *path, size_t size, GError *err)
{
    const char *named = d && d->config && *d->config ? d->config : secure_getenv("OCIO");
    if (named && *named) {
        if ((size_t)snprintf(path, size, "%s", named) >= size)
            return gerror_set(err, G_ERR_IO, "OpenColorIO config path too long");
        return G_OK;
    }
    Dl_info self;
    if (dladdr((void *)&gimage_display_config, &self) && self.dli_fname && strchr(self.dli_fname, '/') &&
        beside(self.dli_fname, path, size))
        return G_OK;
    if (beside("/proc/self/exe", path, size))
        return G_OK;
    int n = snprintf(path, size, "%s", GENERIC_DATADIR "/generic/ocio/config.ocio");
    if (n > 0 && (size_t)n < size && access(path, R_OK) == 0)
        return G_OK;
    return gerror_set(err, G_ERR_IO, "no OpenColorIO config: none given, $OCIO unset, and the shipped one (" SHIPPED
                      ") is neither beside the library or the program nor in " GENERIC_DATADIR "/generic/ocio/");
}

int gimage_display_check(const GImageDisplay *d, char *config_used, size_t size, GError *err)
{
    char path[PATH_MAX + 64];
    int rc = gimage_display_config(d, path, sizeof path, err);
    if (rc != G_OK)
        return rc;
    if (config_used && size)
        snprintf(config_used, size, "%s", path);
    int fd = gfile_open_input(path, err); /* a regular file: not a FIFO OpenColorIO would wait on */
    if (fd < 0)
        return fd;
    close(fd);
    const GOiioOps *o = goiio_ops(err);
    return o ? o->display_transform(path, d ? d->confine_dir : NULL, d ? d->display : NULL, d ? d->view : NULL, NULL, 0,
                                    0, 0, err)
             : G_ERR_IO;
}
