"""Rendering a scene into numpy through libgtrace, and images to and from files."""
import os

import numpy as np

from . import _native, arrays
from ._native import ffi, lib
from .errors import check

INTEGRATORS = {"whitted": 0, "path": 1}


def _count(name, value, lo, hi):
    if value is None:
        return 0
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not lo <= value <= hi:
        raise ValueError(f"{name} must be a whole number in [{lo}, {hi}] or None, not {value!r}")
    return int(value)


def render(scene_path, width=None, height=None, spp=None, integrator="whitted", colormodel=None, threads=None,
           crop=None, depth=None, allow_plugins=False, confine=None):
    """Renders a scene file as `gtrace SCENE -o OUT.exr` with the same options: an (H, W, 3) float32 array of
    linear sRGB, the pixels gtrace writes into the EXR. None keeps the scene's value (the camera's size, samples
    and depth; one of width and height given: the other by the camera's aspect). crop (x0, y0, x1, y1): only that
    region of the full image, its pixels as the full render has them. Errors raise GenericError."""
    rq = ffi.new("GtraceRenderRequest *")
    keep = [ffi.new("char[]", os.fspath(scene_path).encode())]
    rq.scene = keep[0]
    if colormodel is not None:
        if not isinstance(colormodel, str):
            raise TypeError(f"colormodel must be a colour model's name (str) or None, not {type(colormodel).__name__}")
        keep.append(ffi.new("char[]", colormodel.encode()))
        rq.colormodel = keep[-1]
    rq.width = _count("width", width, 1, 1 << 20)
    rq.height = _count("height", height, 1, 1 << 20)
    rq.spp = _count("spp", spp, 1, 1 << 24)
    rq.depth = -1 if depth is None else _count("depth", depth, 0, 1000)
    rq.integrator = arrays.choice("integrator", integrator, INTEGRATORS)
    rq.threads = arrays.threads_arg(threads)
    if crop is not None:
        c = list(crop) if isinstance(crop, (list, tuple)) else None
        if c is None or len(c) != 4 or not all(isinstance(v, (int, np.integer)) and not isinstance(v, bool)
                                               for v in c):
            raise ValueError(f"crop must be four whole numbers (x0, y0, x1, y1), not {crop!r}")
        rq.crop = [int(v) for v in c]
    rq.allow_plugins = 1 if allow_plugins else 0
    if confine is not None:
        keep.append(ffi.new("char[]", os.fspath(confine).encode()))
        rq.confine_dir = keep[-1]
    g = _native.gtrace()
    img = ffi.new("GtraceImage *")
    err = ffi.new("GError *")
    check(g.gtrace_render_file(rq, img, err), err)
    try:
        n = img.width * img.height * 3
        pixels = np.frombuffer(ffi.buffer(img.pixels, n * 4), dtype=np.float32).reshape(img.height, img.width, 3)
        return pixels.copy()
    finally:
        g.gtrace_image_free(img)


def read_image(path):
    """An image file (any format OpenImageIO reads) as an (H, W, C) float32 array of linear values, C 3 or 4."""
    img = ffi.new("GImage *")
    err = ffi.new("GError *")
    check(lib.gimage_read(os.fspath(path).encode(), 0, img, err), err)
    try:
        n = img.width * img.height * img.channels
        a = np.frombuffer(ffi.buffer(img.pixels, n * 4), dtype=np.float32)
        return a.reshape(img.height, img.width, img.channels).copy()
    finally:
        lib.gimage_free(img)


def write_image(path, pixels):
    """Writes an (H, W, C) (C 1..4) or (H, W) array of linear values; the extension picks the format (.exr and
    .hdr keep the floats, .png and the others are sRGB-encoded and clamped)."""
    a = np.asarray(pixels)
    if a.dtype == object or not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise TypeError(f"pixels must hold real numbers, not dtype {a.dtype}")
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3 or not 1 <= a.shape[2] <= 4 or a.shape[0] < 1 or a.shape[1] < 1:
        raise ValueError(f"pixels must have shape (H, W) or (H, W, C) with C in 1..4, not {np.shape(pixels)}")
    a = np.ascontiguousarray(a, dtype=np.float32)
    img = ffi.new("GImage *", {"width": a.shape[1], "height": a.shape[0], "channels": a.shape[2],
                               "pixels": arrays.ptr(a, "float *")})
    err = ffi.new("GError *")
    check(lib.gimage_write(os.fspath(path).encode(), img, ffi.NULL, err), err)
