/* mesh_format.c - which reader a mesh file goes to: its content decides (a binary STL named .obj is still an STL
 * file, a PLY named .gltf still a PLY file), and each format's own check runs before assimp reads a byte; only OBJ,
 * which has no signature and gtrace reads itself, is known by its name or as text. */
#include "mesh_format.h"

#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* Bytes of a file's start that mesh_format_of reads. */
#define MESH_HEAD_BYTES 512

static int starts_with(const unsigned char *head, size_t n, const char *s)
{
    size_t k = strlen(s);
    return n >= k && memcmp(head, s, k) == 0;
}

static unsigned long long le32(const unsigned char *p)
{
    return (unsigned long long)p[0] | (unsigned long long)p[1] << 8 | (unsigned long long)p[2] << 16 |
           (unsigned long long)p[3] << 24;
}

/* The extension of path's last component, with its dot ("" for none). */
static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    return dot && (!slash || dot > slash) ? dot : "";
}

MeshFormat mesh_format_detect(const unsigned char *head, size_t n, unsigned long long size, const char *path,
                              char *what, size_t what_size)
{
    snprintf(what, what_size, "%s", "a mesh file");
    if (starts_with(head, n, "ply\n") || starts_with(head, n, "ply\r\n"))
        return MESH_FORMAT_PLY;
    if (n >= 84 && le32(head + 80) > 0 && 84 + 50 * le32(head + 80) == size) /* a binary STL's exact size */
        return MESH_FORMAT_STL;
    size_t i = 0;
    while (i < n && (head[i] == ' ' || head[i] == '\t'))
        i++;
    if (starts_with(head + i, n - i, "solid") && (i + 5 == n || head[i + 5] == ' ' || head[i + 5] == '\t' ||
                                                  head[i + 5] == '\r' || head[i + 5] == '\n'))
        return MESH_FORMAT_STL;
    if (starts_with(head, n, "glTF"))
        return MESH_FORMAT_GLTF;
    for (i = 0; i < n && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n'); i++)
        ;
    if (i < n && head[i] == '{') /* JSON: glTF is the only mesh format of JSON */
        return MESH_FORMAT_GLTF;
    const char *ext = extension(path);
    if ((n >= 6 && head[0] == 0x4d && head[1] == 0x4d && le32(head + 2) >= 6 && le32(head + 2) <= size) ||
        strcasecmp(ext, ".3ds") == 0) { /* the 3DS main chunk: id 0x4d4d and its length */
        snprintf(what, what_size, "%s", "a 3DS (3D Studio) file");
        return MESH_FORMAT_UNSUPPORTED;
    }
    if (strcasecmp(ext, ".ply") == 0) /* not PLY by content: mesh_ply_check says why */
        return MESH_FORMAT_PLY;
    if (strcasecmp(ext, ".stl") == 0)
        return MESH_FORMAT_STL;
    if (strcasecmp(ext, ".gltf") == 0 || strcasecmp(ext, ".glb") == 0)
        return MESH_FORMAT_GLTF;
    if (strcasecmp(ext, ".obj") != 0 && ext[0] && mesh_assimp_reads_extension(ext)) {
        snprintf(what, what_size, "a %.20s file", ext);
        return MESH_FORMAT_UNSUPPORTED;
    }
    const unsigned char *nl = memchr(head, '\n', n);
    if (memchr(head, '\0', nl ? (size_t)(nl - head) : n)) {
        snprintf(what, what_size, "%s", "binary data (a NUL byte in its first line)");
        return MESH_FORMAT_UNSUPPORTED;
    }
    return MESH_FORMAT_OBJ;
}

int mesh_decimal_number(const char *w, size_t len)
{
    size_t i = len > 0 && (w[0] == '-' || w[0] == '+'), digits = 0;
    for (; i < len && w[i] >= '0' && w[i] <= '9'; i++)
        digits++;
    if (i < len && w[i] == '.')
        for (i++; i < len && w[i] >= '0' && w[i] <= '9'; i++)
            digits++;
    if (digits && i < len && (w[i] == 'e' || w[i] == 'E')) {
        i += 1 + (i + 1 < len && (w[i + 1] == '-' || w[i + 1] == '+'));
        size_t exp = i;
        for (; i < len && w[i] >= '0' && w[i] <= '9'; i++)
            ;
        if (i == exp)
            return 0;
    }
    return digits > 0 && i == len;
}

MeshFormat mesh_format_of(int fd, const char *path, char *what, size_t what_size)
{
    unsigned char head[MESH_HEAD_BYTES];
    off_t at = lseek(fd, 0, SEEK_CUR), size = lseek(fd, 0, SEEK_END);
    ssize_t n = pread(fd, head, sizeof head, 0);
    if (at < 0 || size < 0 || lseek(fd, at, SEEK_SET) != at || n < 0)
        n = 0, size = 0; /* the reader the name picks reports the read error */
    return mesh_format_detect(head, (size_t)n, (unsigned long long)size, path, what, what_size);
}
