"""Colour models: creating one by name, its wavelengths, colours to and from numpy."""
import numpy as np

from . import arrays
from ._native import ffi, lib
from .errors import GenericError, check


class ColorModel:
    """A colour model: `name`, `nvalues` (floats in a colour), `wavelengths` (nm of its samples; empty for rgb).
    Create one by name (`ColorModel("spectrum", step_nm=10)`), or take a library's (`Library.colormodel`)."""

    def __init__(self, name, step_nm=None, min_nm=None, max_nm=None, _ptr=None, _owner=None):
        if _ptr is not None:
            self._ptr, self._owner = _ptr, _owner
        else:
            if not isinstance(name, str):
                raise TypeError(f"name must be a colour model's name (str), not {type(name).__name__}")
            opt = ffi.new("GColorModelOptions *", {"step_nm": step_nm or 0.0, "min_nm": min_nm or 0.0,
                                                   "max_nm": max_nm or 0.0})
            out = ffi.new("GColorModel **")
            err = ffi.new("GError *")
            check(lib.gcolormodel_create(name.encode(), opt, out, err), err)
            self._ptr, self._owner = ffi.gc(out[0], lib.gcolormodel_destroy), None
        self.name = ffi.string(lib.gcolormodel_name(self._ptr)).decode()
        self.nvalues = lib.gbatch_output_width(self._ptr, lib.GBATCH_SAMPLES)

    @property
    def wavelengths(self):
        """The wavelengths (nm) of the model's samples, an array of nvalues (empty for a model without them)."""
        n = lib.gcolormodel_wavelengths(self._ptr, ffi.NULL, 0)
        nm = np.zeros(max(n, 0), dtype=np.float64)
        if n > 0:
            lib.gcolormodel_wavelengths(self._ptr, arrays.ptr(nm), n)
        return nm

    def from_rgb(self, rgb, role="reflectance", threads=None):
        """Linear sRGB (N, 3) to colours of the model: (N, nvalues) float32."""
        role = arrays.choice("role", role, arrays.ROLES)
        rgb = arrays.as_rows("rgb", rgb, 3)
        out = np.zeros((rgb.shape[0], self.nvalues), dtype=np.float32)
        err = ffi.new("GError *")
        check(lib.gbatch_color_from_rgb(self._ptr, rgb.shape[0], arrays.ptr(rgb), role, arrays.ptr(out, "float *"),
                                        arrays.threads_arg(threads), err), err)
        return out

    def convert(self, samples, output="rgb", role="reflectance", threads=None):
        """Colours of the model (N, nvalues) to linear sRGB or XYZ (N, 3) float64 (output "rgb" or "xyz"), or
        their samples widened to float64 ("samples")."""
        code = arrays.choice("output", output, arrays.OUTPUTS)
        role = arrays.choice("role", role, arrays.ROLES)
        s = arrays.as_rows("samples", samples, self.nvalues, np.float32)
        out = np.zeros((s.shape[0], lib.gbatch_output_width(self._ptr, code)), dtype=np.float64)
        err = ffi.new("GError *")
        check(lib.gbatch_color_to(self._ptr, s.shape[0], arrays.ptr(s, "float *"), role, code, arrays.ptr(out),
                                  arrays.threads_arg(threads), err), err)
        return out

    def to_rgb(self, samples, role="reflectance", threads=None):
        """Colours of the model (N, nvalues) to linear sRGB (N, 3)."""
        return self.convert(samples, "rgb", role, threads)

    def to_xyz(self, samples, role="reflectance", threads=None):
        """Colours of the model (N, nvalues) to CIE XYZ (N, 3)."""
        return self.convert(samples, "xyz", role, threads)

    def brightness(self, samples, role="reflectance"):
        """The brightness of each row of samples (n x nvalues) read in role (gcolor_brightness_as): a light's is its
        Y (CIE 1931, equal-energy white = 1) in every model; a reflectance's the model's own weighting."""
        role = arrays.choice("role", role, arrays.ROLES)
        s = np.ascontiguousarray(np.atleast_2d(np.asarray(samples, dtype=np.float32)))
        if s.ndim != 2 or s.shape[1] != self.nvalues:
            raise GenericError(f"samples must be n x {self.nvalues} for {self.name}, not {s.shape}")
        c = ffi.new("GColor *")
        if lib.gcolor_alloc(c, self._ptr) != lib.G_OK:
            raise MemoryError("no memory for a colour")
        try:
            out = np.empty(s.shape[0], dtype=np.float64)
            for i in range(s.shape[0]):
                ffi.memmove(c.v, ffi.from_buffer(s[i]), 4 * self.nvalues)
                out[i] = lib.gcolor_brightness_as(c, role)
            return out
        finally:
            lib.gcolor_free(c)

    def __repr__(self):
        return f"<generic.ColorModel {self.name} ({self.nvalues} values)>"


def kinds():
    """The registered kinds' keywords (colormodel, color, material, node, generator, and any an application
    added, such as gtrace's object, light and camera once a scene was loaded)."""
    return [ffi.string(lib.gkind_name(k)).decode() for k in range(lib.gkind_count())]


def types(kind="material"):
    """The names of the registered types of a kind (a keyword of kinds())."""
    if not isinstance(kind, str):
        raise TypeError(f"kind must be a kind's keyword (str), not {type(kind).__name__}")
    k = ffi.new("GKind *")
    if lib.gkind_find(kind.encode(), k) != 1:
        raise GenericError(f"no kind '{kind}' (registered: {', '.join(kinds())})", lib.G_ERR_NOTFOUND)
    buf = ffi.new("char[]", 8192)
    lib.gregistry_names(k[0], buf, 8192)
    return ffi.string(buf).decode().replace(",", " ").split()


def colormodels():
    """The names of the registered colour models."""
    return types("colormodel")
