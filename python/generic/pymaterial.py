"""Materials written in Python: a class whose methods the library calls back through cffi, registered as a material
type that the text format reads, `gmat check` checks (check()) and gtrace renders (render()).

Each call from C into a Python method takes the interpreter's lock (the GIL): a render's threads then take turns
in Python, and each call costs a few microseconds of crossing on top of the method's own work (docs/python.md).
"""
import math
import sys
import threading

from . import _native
from ._native import ffi, lib
from .errors import GenericError, check as _check

_lock = threading.Lock()
_types = {}      # keyword -> (class, its C records), alive for the process: the registry keeps pointers to them
_instances = {}  # address of a GMaterial header -> (Python object, header, its colours)


class Param:
    """A parameter of a Python material's entry: kind "color" (a reflectance, default an sRGB grey `default`) or
    "number" (default `default`, read within [lo, hi]), and its documentation."""

    def __init__(self, kind, default, doc="", lo=-1e300, hi=1e300):
        if kind not in ("color", "number"):
            raise ValueError(f"kind must be 'color' or 'number', not {kind!r}")
        self.kind, self.default, self.doc, self.lo, self.hi = kind, float(default), doc, float(lo), float(hi)


class Color:
    """A colour the library handed to a method (valid during the call only), or a parameter's colour. The
    operations are the library's (gcolor_*): a Python material never touches samples, so it works in every model."""

    def __init__(self, ptr):
        self._ptr = ptr

    def black(self):
        lib.gcolor_black(self._ptr)

    def copy(self, src):
        _status(lib.gcolor_copy(self._ptr, src._ptr))

    def add(self, a, b):
        _status(lib.gcolor_add(self._ptr, a._ptr, b._ptr))

    def mul(self, a, b):
        _status(lib.gcolor_mul(self._ptr, a._ptr, b._ptr))

    def mul_scaled(self, a, b, s):
        """self = a * b * s (a applied to b: a reflectance to a light)."""
        _status(lib.gcolor_mul_scaled(self._ptr, a._ptr, b._ptr, s))

    def scale(self, a, s):
        _status(lib.gcolor_scale(self._ptr, a._ptr, s))

    def fill(self, value):
        _status(lib.gcolor_fill(self._ptr, value))

    @property
    def brightness(self):
        return lib.gcolor_brightness(self._ptr)


class SurfacePointView:
    """The surface point of one call (valid during the call only): its shading normal and the cosine of a pair."""

    def __init__(self, ptr):
        self._ptr = ptr

    @property
    def normal(self):
        n = lib.gsurfpoint_normal(self._ptr)
        return (n.x, n.y, n.z)

    def cos_in(self, wi, wo):
        """The cosine of wi with the shading normal when wi and wo lie on the incident side, else 0
        (gmaterial_cos_in)."""
        return lib.gmaterial_cos_in(self._ptr, wi, wo, ffi.new("GVec3 *"))


def _status(rc):
    if rc < 0:
        raise GenericError(f"a colour operation failed ({ffi.string(lib.gstatus_string(rc)).decode()})", rc)


class PythonMaterial:
    """Base of the materials written in Python. A subclass names its type keyword (`keyword`), a one-line
    `description`, its parameters (`params`: name -> Param) and defines some of the methods below (the others take
    the library's defaults, material.h); register it with register_material(cls). Each entry of the type makes one
    instance, its parameters as attributes (colours as Color, numbers as float). Directions are (x, y, z) tuples,
    wi towards the light, wo towards the viewer; a method writes its colour into `result` (a Color) and returns
    nothing; an exception makes the call fail (the library sees G_ERR_INVALID) after its traceback is printed.

      reflection(sp, wi, illum, wo, result)             light reflected towards wo of illum arriving from wi
      refraction(sp, wi, illum, rel_index, wo, result)  the same through the surface
      emission(sp, wo, result)                          light emitted towards wo
      diffuse(sp, result)                               the Lambertian colour (previews, ambient light, sampling)
      ambient(sp, illum, result)                        ambient light reflected (default: diffuse times illum)
    """
    keyword = None
    description = "a material written in Python"
    params = {}


_SLOTS = {
    "reflection": "int(*)(const GMaterial *, GSurfPoint *, GVec3, const GColor *, GVec3, GColor *)",
    "refraction": "int(*)(const GMaterial *, GSurfPoint *, GVec3, const GColor *, const GColor *, GVec3, GColor *)",
    "emission": "int(*)(const GMaterial *, GSurfPoint *, GVec3, GColor *)",
    "diffuse": "int(*)(const GMaterial *, GSurfPoint *, GColor *)",
    "ambient": "int(*)(const GMaterial *, GSurfPoint *, const GColor *, GColor *)",
}


def _vec(v):
    return (v.x, v.y, v.z)


def _adapter(name):
    """The Python function behind the C slot `name`: finds the instance, converts the arguments, calls its method."""
    def call(self_ptr, sp, *args):
        obj = _instances[int(ffi.cast("uintptr_t", self_ptr))][0]
        conv = [(_vec(a) if ffi.typeof(a) is ffi.typeof("GVec3") else Color(a)) if isinstance(a, ffi.CData) else a
                for a in args]
        getattr(obj, name)(SurfacePointView(sp), *conv)
        return lib.G_OK
    return call


def _failed(exception, value, tb):
    sys.stderr.write("generic: a Python material's method failed:\n")
    import traceback
    traceback.print_exception(exception, value, tb)


def _destroy(header):
    entry = _instances.pop(int(ffi.cast("uintptr_t", header)), None)
    if entry:
        for c in entry[2].values():
            lib.gcolor_free(c)


def _parse_for(cls, records):
    """The parse routine of cls's entries: its parameters read, defaults given, an instance made."""
    expected = ", ".join(cls.params).encode() or b"(none)"

    def parse(reader, vtable, obj, err):
        colours, numbers = {}, {}
        try:
            key = ffi.new("const char **")
            while True:
                rc = lib.greader_param(reader, key, err)
                if rc <= 0:
                    break
                name = ffi.string(key[0]).decode()
                p = cls.params.get(name)
                if p is None:
                    rc = lib.greader_unknown_param(reader, expected, err)
                elif p.kind == "color":
                    if name in colours:
                        lib.gcolor_free(colours[name])
                    colours[name] = ffi.new("GColor *")
                    rc = lib.greader_color(reader, lib.GCOLOR_REFLECTANCE, colours[name], err)
                else:
                    value = ffi.new("double *")
                    rc = lib.greader_number_in(reader, p.lo, p.hi, value, err)
                    numbers[name] = value[0]
                if rc < 0:
                    break
            for name, p in cls.params.items():
                if rc < 0:
                    break
                if p.kind == "color" and name not in colours:
                    colours[name] = ffi.new("GColor *")
                    rc = lib.gmaterial_param_default(reader, p.default, lib.GCOLOR_REFLECTANCE, colours[name], err)
                elif p.kind == "number" and name not in numbers:
                    numbers[name] = p.default
            if rc < 0:
                raise _Failed(rc)
            header = ffi.new("GMaterial *")
            rc = lib.gmaterial_init(header, records["class"], lib.greader_colormodel(reader), err)
            if rc < 0:
                raise _Failed(rc)
            instance = cls.__new__(cls)
            for name, c in colours.items():
                setattr(instance, name, Color(c))
            for name, v in numbers.items():
                setattr(instance, name, v)
            if hasattr(instance, "init"):
                instance.init()
            _instances[int(ffi.cast("uintptr_t", header))] = (instance, header, colours)
            obj[0] = header
            return lib.G_OK
        except _Failed as f:
            for c in colours.values():
                lib.gcolor_free(c)
            return f.rc
        except Exception as e:  # the entry's own constructor failed
            for c in colours.values():
                lib.gcolor_free(c)
            return lib.gerror_set(err, lib.G_ERR_INVALID, b"%s", ffi.new("char[]", f"{cls.keyword}: {e}".encode()))
    return parse


class _Failed(Exception):
    def __init__(self, rc):
        self.rc = rc


def register_material(cls):
    """Registers cls (a PythonMaterial subclass) as a material type of the process's registry under cls.keyword,
    with its parameter table; files loaded afterwards (load, render, check) may use it. Registering the same class
    again does nothing; another class under a taken keyword raises GenericError (G_ERR_EXISTS). Returns cls."""
    if not (isinstance(cls, type) and issubclass(cls, PythonMaterial)) or not isinstance(cls.keyword, str):
        raise TypeError("register_material takes a PythonMaterial subclass with a keyword (str)")
    with _lock:
        if cls.keyword in _types:
            if _types[cls.keyword][0] is cls:
                return cls
            raise GenericError(f"material type '{cls.keyword}' is registered already", lib.G_ERR_EXISTS)
        keep = {}
        slots = {}
        for name, ctype in _SLOTS.items():
            if callable(getattr(cls, name, None)):
                keep[name] = ffi.callback(ctype, _adapter(name), error=lib.G_ERR_INVALID, onerror=_failed)
                slots[name] = keep[name]
        keep["destroy"] = ffi.callback("void(*)(GMaterial *)", _destroy)
        keep["keyword"] = ffi.new("char[]", cls.keyword.encode())
        keep["description"] = ffi.new("char[]", (cls.description or "").encode())
        keep["class"] = ffi.new("GMaterialClass *", dict(abi_version=lib.GMATERIAL_ABI_VERSION, name=keep["keyword"],
                                                         description=keep["description"], destroy=keep["destroy"],
                                                         **slots))
        keep["parse"] = ffi.callback("GParseFn", _parse_for(cls, keep), error=lib.G_ERR_INVALID, onerror=_failed)
        table = ffi.new("GParamInfo[]", len(cls.params) + 1)
        for i, (name, p) in enumerate(cls.params.items()):
            texts = [name, "color" if p.kind == "color" else "number",
                     f"rgb {p.default:g} {p.default:g} {p.default:g}" if p.kind == "color" else f"{p.default:g}",
                     p.doc or name]
            cs = [ffi.new("char[]", t.encode()) for t in texts]
            keep.setdefault("texts", []).extend(cs)
            table[i] = {"name": cs[0], "form": lib.GPARAM_NAMED, "type": cs[1], "def": cs[2], "doc": cs[3]}
        keep["params"] = table
        keep["info"] = ffi.new("GTypeInfo *", {"kind": lib.GKIND_MATERIAL, "vtable": keep["class"],
                                               "parse": keep["parse"], "params": table})
        err = ffi.new("GError *")
        _check(lib.gregistry_add(keep["info"], err), err)
        _types[cls.keyword] = (cls, keep)
    return cls


def check(path, material, colormodel=None, samples=0, allow_plugins=False):
    """`gmat check FILE MATERIAL` in this process, so that types registered from Python are checked too: True when
    every property passes, False when one fails (the report is printed on standard output, as gmat prints it).
    GenericError when the file cannot be read or has no such material."""
    import os
    g = _native.gmat()
    err = ffi.new("GError *")
    model = ffi.new("char[]", colormodel.encode()) if colormodel else ffi.NULL
    sys.stdout.flush()
    rc = g.gmat_check_file(os.fspath(path).encode(), material.encode(), model, int(samples),
                           1 if allow_plugins else 0, err)
    _check(rc, err)
    return rc == 0
