/* image_path.h - an image file's name: its extension, by which an output's format is chosen (header only). */
#ifndef GENERIC_IMAGE_PATH_H
#define GENERIC_IMAGE_PATH_H

#include <string.h>
#include <strings.h>

/** The extension of path's last component (after its last '/'): from that component's last '.', the dot included,
 * to the end ("a/b.tar.EXR": ".EXR"; "a/.exr": ".exr"); NULL when the component has no '.'. */
static inline const char *gimage_path_extension(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    return dot && (!slash || dot > slash) ? dot : NULL;
}

/** Whether path's extension (gimage_path_extension) is ext, a dot and letters (".exr"), in any case: 1 or 0. */
static inline int gimage_path_has_extension(const char *path, const char *ext)
{
    const char *dot = gimage_path_extension(path);
    return dot && !strcasecmp(dot, ext);
}

#endif
