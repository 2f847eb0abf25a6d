#!/usr/bin/env python3
"""make_grid.py - writes the small OpenVDB files of gtrace's grid media examples and tests (python3-openvdb).

  make_grid.py constant OUT     density 1 on 25^3 voxels of 0.1 centred at the origin (index -12..12)
  make_grid.py gradient OUT     density 0.5 + 0.04 i + 0.03 j + 0.05 k on 21^3 voxels of 0.1 (i, j, k = 0..20 from
                                index -10), a linear field that trilinear interpolation reproduces
  make_grid.py cloud OUT [N]    a cloud of smooth noisy blobs on N^3 voxels (default 64) filling [-1, 1]^3
  make_grid.py lying OUT        the constant grid, whose stated bounding box (file_bbox_max) is made smaller than
                                its voxels
  make_grid.py huge OUT         two voxels 200000 apart: a bounding box of 8e15 voxels
  make_grid.py vector OUT       a grid 'density' of vectors instead of floats
  make_grid.py negative OUT     the constant grid with one voxel of density -1
"""
import struct
import sys

import numpy as np
import pyopenvdb as vdb


def float_grid(values, origin, voxel):
    g = vdb.FloatGrid(0.0)
    g.name = "density"
    g.copyFromArray(np.ascontiguousarray(values, dtype=np.float32), ijk=origin)
    g.transform = vdb.createLinearTransform(voxelSize=voxel)
    return g


def constant():
    return float_grid(np.ones((25, 25, 25)), (-12, -12, -12), 0.1)


def gradient():
    i, j, k = np.meshgrid(np.arange(21), np.arange(21), np.arange(21), indexing="ij")
    return float_grid(0.5 + 0.04 * i + 0.03 * j + 0.05 * k, (-10, -10, -10), 0.1)


def cloud(n):
    rng = np.random.default_rng(7)
    c = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    x, y, z = np.meshgrid(c, c, c, indexing="ij")
    d = np.zeros_like(x)
    for _ in range(40):  # blobs in a flattened ellipsoid: a cumulus with a flat base
        p = rng.normal(size=3)
        p *= np.array([0.7, 0.28, 0.55]) * rng.random() ** 0.5 / np.linalg.norm(p)
        p[1] = abs(p[1]) - 0.2
        r = 0.14 + 0.22 * rng.random()
        d += np.exp(-((x - p[0]) ** 2 + (y - p[1]) ** 2 + (z - p[2]) ** 2) / (r * r))
    wobble = 1.0 + 0.5 * np.sin(13 * x + 2) * np.sin(17 * y + 1) * np.sin(11 * z + 3)
    d = np.clip(d * wobble - 0.5, 0.0, None) * (y > -0.45)
    d[d < 1e-3] = 0.0
    return float_grid(d, (-n // 2, -n // 2, -n // 2), 2.0 / n)


def write(grid, out):
    vdb.write(out, grids=[grid])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    what, out = sys.argv[1], sys.argv[2]
    if what == "constant":
        write(constant(), out)
    elif what == "gradient":
        write(gradient(), out)
    elif what == "cloud":
        write(cloud(int(sys.argv[3]) if len(sys.argv) > 3 else 64), out)
    elif what == "lying":
        write(constant(), out)
        data = bytearray(open(out, "rb").read())
        at = data.find(b"file_bbox_max")
        if at < 0:
            sys.exit("make_grid.py: no file_bbox_max in the written file")
        at += len(b"file_bbox_max")
        (tlen,) = struct.unpack_from("<I", data, at)
        at += 4 + tlen + 4  # the type name, the value's size
        struct.pack_into("<3i", data, at, 0, 0, 0)  # the voxels reach 12, 12, 12
        open(out, "wb").write(bytes(data))
    elif what == "huge":
        g = vdb.FloatGrid(0.0)
        g.name = "density"
        a = g.getAccessor()
        a.setValueOn((0, 0, 0), 1.0)
        a.setValueOn((200000, 200000, 200000), 1.0)
        write(g, out)
    elif what == "vector":
        g = vdb.Vec3SGrid()
        g.name = "density"
        g.getAccessor().setValueOn((0, 0, 0), (1.0, 1.0, 1.0))
        write(g, out)
    elif what == "negative":
        g = constant()
        g.getAccessor().setValueOn((3, 4, 5), -1.0)
        write(g, out)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
