"""libgeneric from Python: load the library's text files, evaluate materials, generators and colour conversions
over numpy arrays in one call each (the C batch API, generic/batch.h, parallel with OpenMP), render scenes into
numpy through gtrace's library. docs/python.md is the guide.

    import generic
    lib = generic.load("examples/materials/phong.mat", colormodel="spectrum")
    mat = lib.material("red_plastic")
    rgb = mat.reflection(normal, wi, wo)            # (N, 3) arrays in, (N, 3) linear sRGB out
    img = generic.render("examples/scenes/demo.scene", width=320)   # (H, W, 3) float32
"""
from ._native import ffi, lib
from .colors import ColorModel, colormodels, kinds, types
from .errors import GenericError
from .library import Generator, Library, Material, SurfacePoint, load
from .pymaterial import Color, Param, PythonMaterial, check, register_material
from .render import read_image, render, write_image

__all__ = ["Color", "ColorModel", "GenericError", "Generator", "Library", "Material", "Param", "PythonMaterial",
           "SurfacePoint", "check", "colormodels", "kinds", "load", "read_image", "register_material", "render",
           "types",
           "write_image"]


def _register():
    err = ffi.new("GError *")
    if lib.generic_register_builtins(err) != lib.G_OK:
        raise GenericError.from_error(err)


_register()
