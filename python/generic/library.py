"""Loading text files, and the materials and generators they define evaluated over numpy arrays."""
import os

import numpy as np

from . import _native, arrays
from ._native import ffi, lib
from .colors import ColorModel
from .errors import GenericError, check


def _points(normal, wi_wo, point, uv, dpdu, dpdv, threads):
    """The rows of a batch: the arrays checked and repeated to a common N, the GBatchPoints over them (kept
    alive by the returned list)."""
    named = [("normal", arrays.as_rows("normal", normal, 3))]
    named += [(n, arrays.as_rows(n, a, 3)) for n, a in wi_wo]
    for n, a, w in (("point", point, 3), ("uv", uv, 2), ("dpdu", dpdu, 3), ("dpdv", dpdv, 3)):
        if a is not None:
            named.append((n, arrays.as_rows(n, a, w)))
    n, rows = arrays.common_rows(named)
    by_name = dict(zip((nm for nm, _ in named), rows))
    pts = ffi.new("GBatchPoints *", {"n": n, "normal": arrays.ptr(by_name["normal"]),
                                     "point": arrays.ptr(by_name.get("point")), "uv": arrays.ptr(by_name.get("uv")),
                                     "dpdu": arrays.ptr(by_name.get("dpdu")), "dpdv": arrays.ptr(by_name.get("dpdv")),
                                     "threads": arrays.threads_arg(threads)})
    return n, pts, by_name, rows


class Material:
    """A material (or texture tree) of a loaded library. The batch methods take (N, 3) arrays (a single row (3,)
    is repeated to N) and evaluate row i at a surface point with geometric normal normal[i] (at point[i], with
    (u, v) uv[i] and tangents dpdu[i], dpdv[i] when given; the origin, (0, 0) and no tangents otherwise) on the
    material's outside; wi points towards the light, wo towards the viewer. The light is unit white light (rgb
    1 1 1 as a light), as `gmat eval` shines it. output: "rgb" (linear sRGB, (N, 3)), "xyz" (CIE XYZ) or "samples"
    (the colour model's values, (N, nvalues)). threads: None for OpenMP's default."""

    def __init__(self, library, ptr, name):
        self._library = library  # keeps the owner of the material alive
        self._ptr = ptr
        self.name = name
        self.type = ffi.string(lib.gmaterial_name(ptr)).decode()
        self.colormodel = library.colormodel

    def _colour_call(self, fn, normal, dirs, output, threads, **geometry):
        code = arrays.choice("output", output, arrays.OUTPUTS)
        n, pts, rows, keep = _points(normal, dirs, threads=threads, **geometry)
        out = np.zeros((n, lib.gbatch_output_width(self.colormodel._ptr, code)), dtype=np.float64)
        err = ffi.new("GError *")
        args = [arrays.ptr(rows[name]) for name, _ in dirs]
        check(fn(self._ptr, pts, *args, code, arrays.ptr(out), err), err)
        return out

    def reflection(self, normal, wi, wo, output="rgb", point=None, uv=None, dpdu=None, dpdv=None, threads=None):
        """The light reflected towards wo of unit white light arriving from wi: f_r cos(theta_in), or the
        reflectance along an ideal mirror pair. (N, 3) for rgb and xyz, (N, nvalues) for samples."""
        return self._colour_call(lib.gbatch_reflection, normal, [("wi", wi), ("wo", wo)], output, threads,
                                 point=point, uv=uv, dpdu=dpdu, dpdv=dpdv)

    def refraction(self, normal, wi, wo, output="rgb", point=None, uv=None, dpdu=None, dpdv=None, threads=None):
        """The light passed on towards wo of unit white light arriving through the surface from wi (below it),
        with the relative index 1 / n of light entering the material from vacuum."""
        return self._colour_call(lib.gbatch_refraction, normal, [("wi", wi), ("wo", wo)], output, threads,
                                 point=point, uv=uv, dpdu=dpdu, dpdv=dpdv)

    def emission(self, normal, wo, output="rgb", point=None, uv=None, dpdu=None, dpdv=None, threads=None):
        """The light emitted towards wo."""
        return self._colour_call(lib.gbatch_emission, normal, [("wo", wo)], output, threads,
                                 point=point, uv=uv, dpdu=dpdu, dpdv=dpdv)

    def pdf(self, normal, wi, wo, point=None, uv=None, dpdu=None, dpdv=None, threads=None):
        """The density (per unit solid angle) with which sample() draws wi for wo, non-delta lobes only: (N,)."""
        n, pts, rows, keep = _points(normal, [("wi", wi), ("wo", wo)], point, uv, dpdu, dpdv, threads)
        out = np.zeros(n, dtype=np.float64)
        err = ffi.new("GError *")
        check(lib.gbatch_pdf(self._ptr, pts, arrays.ptr(rows["wi"]), arrays.ptr(rows["wo"]), arrays.ptr(out), err),
              err)
        return out

    def sample(self, normal, wo, u, output="rgb", point=None, uv=None, dpdu=None, dpdv=None, threads=None):
        """Directions drawn for light leaving towards wo from the random numbers u ((N, 2) in [0, 1)): a tuple
        (wi (N, 3), pdf (N,), flags (N,) of GSAMPLE_ bits, 0 where nothing was drawn; weight value / pdf)."""
        code = arrays.choice("output", output, arrays.OUTPUTS)
        u = arrays.as_rows("u", u, 2)
        n, pts, rows, keep = _points(normal, [("wo", wo)], point, uv, dpdu, dpdv, threads)
        if u.shape[0] != n:
            if u.shape[0] == 1:
                u = np.ascontiguousarray(np.broadcast_to(u, (n, 2)))
            elif n == 1:
                return self.sample(np.broadcast_to(np.asarray(normal, float).reshape(-1, 3), (u.shape[0], 3)),
                                   np.broadcast_to(np.asarray(wo, float).reshape(-1, 3), (u.shape[0], 3)), u, output,
                                   point, uv, dpdu, dpdv, threads)
            else:
                raise ValueError(f"u has {u.shape[0]} rows where the others have {n}")
        wi = np.zeros((n, 3), dtype=np.float64)
        pdf = np.zeros(n, dtype=np.float64)
        flags = np.zeros(n, dtype=np.intc)
        weight = np.zeros((n, lib.gbatch_output_width(self.colormodel._ptr, code)), dtype=np.float64)
        err = ffi.new("GError *")
        check(lib.gbatch_sample(self._ptr, pts, arrays.ptr(rows["wo"]), arrays.ptr(u), code, arrays.ptr(wi),
                                arrays.ptr(pdf), arrays.ptr(flags, "int *"), arrays.ptr(weight), err), err)
        return wi, pdf, flags, weight

    def reflection_at(self, sp, wi, wo, output="rgb"):
        """reflection() at one SurfacePoint (made by the library's constructor, gsurfpoint_new) for one pair of
        directions (3 numbers each): a (3,) array (rgb, xyz) or (nvalues,) (samples). The point has no material
        and vacuum on both sides, as gsurfpoint_new leaves it."""
        code = arrays.choice("output", output, arrays.OUTPUTS)
        if not isinstance(sp, SurfacePoint) or sp.colormodel._ptr != self.colormodel._ptr:
            raise TypeError("sp must be a SurfacePoint of the material's colour model")
        wi = arrays.as_rows("wi", wi, 3)
        wo = arrays.as_rows("wo", wo, 3)
        if wi.shape[0] != 1 or wo.shape[0] != 1:
            raise ValueError("wi and wo must be single directions (3,)")
        model = self.colormodel._ptr
        white, result = ffi.new("GColor *"), ffi.new("GColor *")
        try:
            _status_of(lib.gcolor_alloc(white, model))
            _status_of(lib.gcolor_alloc(result, model))
            _status_of(lib.gcolor_from_rgb(white, [1.0, 1.0, 1.0], lib.GCOLOR_LIGHT))
            _status_of(lib.gmaterial_reflection(self._ptr, sp._ptr, tuple(wi[0]), white, tuple(wo[0]), result))
            if code == lib.GBATCH_SAMPLES:
                n = lib.gbatch_output_width(model, code)
                return np.frombuffer(ffi.buffer(result.v, 4 * n), dtype=np.float32).astype(np.float64)
            out = ffi.new("double[3]")
            fn = lib.gcolor_to_xyz if code == lib.GBATCH_XYZ else lib.gcolor_to_rgb
            _status_of(fn(result, lib.GCOLOR_LIGHT, out))
            return np.array(list(out))
        finally:
            lib.gcolor_free(white)
            lib.gcolor_free(result)

    def __repr__(self):
        return f"<generic.Material {self.name} ({self.type}, {self.colormodel.name})>"


def _status_of(rc):
    if rc < 0:
        raise GenericError(f"the material failed ({ffi.string(lib.gstatus_string(rc)).decode()})", rc)


class SurfacePoint:
    """A surface point made by the library's constructor (gsurfpoint_new), for single evaluations
    (Material.reflection_at) without laying the C struct out: in colormodel, at `point` with geometric normal
    `normal` (normalised by the library), tangents dpdu and dpdv, (u, v) and the surface index. Bad numbers raise
    GenericError. It owns its scratch arena; use it from one thread at a time."""

    def __init__(self, colormodel, point, normal, dpdu=(0.0, 0.0, 0.0), dpdv=(0.0, 0.0, 0.0), uv=(0.0, 0.0),
                 surface=0):
        if not isinstance(colormodel, ColorModel):
            raise TypeError("colormodel must be a generic.ColorModel")
        vec = {name: tuple(arrays.as_rows(name, v, 3)[0]) for name, v in
               (("point", point), ("normal", normal), ("dpdu", dpdu), ("dpdv", dpdv))}
        u, v = (float(x) for x in arrays.as_rows("uv", uv, 2)[0])
        self.colormodel = colormodel
        self._scratch = ffi.gc(lib.gscratch_create(0), lib.gscratch_destroy)
        err = ffi.new("GError *")
        p = lib.gsurfpoint_new(colormodel._ptr, self._scratch, vec["point"], vec["normal"], vec["dpdu"], vec["dpdv"],
                               u, v, int(surface), err)
        if p == ffi.NULL:
            raise GenericError.from_error(err)
        self._ptr = ffi.gc(p, lib.gsurfpoint_free)

    @property
    def size(self):
        """sizeof(GSurfPoint) in the library (gsurfpoint_size), which the package never lays out."""
        return lib.gsurfpoint_size()


class Generator:
    """A texture generator of a loaded library: value(point, ...) over (N, 3) points, with the geometry of
    Material's methods (normal defaults to +z)."""

    def __init__(self, library, ptr, name):
        self._library = library
        self._ptr = ptr
        self.name = name
        self.type = ffi.string(lib.ggenerator_name(ptr)).decode()

    def value(self, point, normal=(0.0, 0.0, 1.0), uv=None, dpdu=None, dpdv=None, threads=None):
        """The generator's value at each row: (N,)."""
        n, pts, rows, keep = _points(normal, [], point, uv, dpdu, dpdv, threads)
        out = np.zeros(n, dtype=np.float64)
        err = ffi.new("GError *")
        check(lib.gbatch_generator_value(self._ptr, self._library.colormodel._ptr, pts, arrays.ptr(out), err), err)
        return out


class Library:
    """The objects a text file defines (generic.load): materials, nodes, generators, and the colour model."""

    def __init__(self, ptr, path):
        self._ptr = ffi.gc(ptr, lib.glibrary_destroy)
        self.path = path
        self.colormodel = ColorModel(None, _ptr=lib.glibrary_colormodel(ptr), _owner=self)

    def _names(self, kind):
        names = []
        name = ffi.new("const char **")
        for i in range(lib.glibrary_count(self._ptr, kind)):
            lib.glibrary_entry(self._ptr, kind, i, name, ffi.NULL)
            if name[0] != ffi.NULL:
                names.append(ffi.string(name[0]).decode())
        return names

    def materials(self):
        """The names of the named materials and texture nodes, in the file's order."""
        return self._names(lib.GKIND_MATERIAL) + self._names(lib.GKIND_NODE)

    def generators(self):
        """The names of the named generators."""
        return self._names(lib.GKIND_GENERATOR)

    def material(self, name):
        """The material or node `name`; KeyError naming the file's materials when there is none."""
        if not isinstance(name, str):
            raise TypeError(f"name must be a str, not {type(name).__name__}")
        p = lib.glibrary_material(self._ptr, name.encode())
        if p == ffi.NULL:
            raise KeyError(f"{self.path} defines no material named '{name}' (it defines: "
                           f"{', '.join(self.materials()) or 'none'})")
        return Material(self, p, name)

    def generator(self, name):
        """The generator `name`; KeyError when there is none."""
        if not isinstance(name, str):
            raise TypeError(f"name must be a str, not {type(name).__name__}")
        p = lib.glibrary_find(self._ptr, lib.GKIND_GENERATOR, name.encode())
        if p == ffi.NULL:
            raise KeyError(f"{self.path} defines no generator named '{name}' (it defines: "
                           f"{', '.join(self.generators()) or 'none'})")
        return Generator(self, ffi.cast("GGenerator *", p), name)

    def __repr__(self):
        return f"<generic.Library {self.path} ({self.colormodel.name}, {len(self.materials())} materials)>"


def load(path, colormodel=None, allow_plugins=False, confine=None):
    """Reads a text file (materials, texture trees, a scene) into a Library. colormodel: a model's name to use
    instead of the file's. A `plugin` statement loads native code: it needs allow_plugins=True (or
    GENERIC_ALLOW_PLUGINS=1 in the environment), as the tools' --allow-plugins. confine: a directory every file
    the load reads must lie under. Errors raise GenericError with the file:line:col of the library's message."""
    path = os.fspath(path)
    if colormodel is not None and not isinstance(colormodel, str):
        raise TypeError(f"colormodel must be a colour model's name (str) or None, not {type(colormodel).__name__}")
    try:
        _native.gtrace()  # scene files: gtrace's kinds object, light and camera
    except OSError:
        pass  # built without libgtrace: material and texture files only
    keep = [path.encode()]
    opt = ffi.new("GReaderOptions *")
    if colormodel is not None:
        keep.append(ffi.new("char[]", colormodel.encode()))
        opt.colormodel = keep[-1]
    opt.allow_plugins = 1 if allow_plugins else 0
    if confine is not None:
        keep.append(ffi.new("char[]", os.fspath(confine).encode()))
        opt.confine_dir = keep[-1]
    out = ffi.new("GLibrary **")
    err = ffi.new("GError *")
    check(lib.greader_load_file(keep[0], opt, out, err), err)
    return Library(out[0], path)
