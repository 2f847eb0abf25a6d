"""The C libraries through cffi's ABI mode: libgeneric.so, and libgtrace.so for scenes and rendering (opened on
first use: it maps Embree, and assimp once a PLY, STL or glTF mesh is read). The directory of both is
_config.LIBDIR, written when the package is built or installed (python/build.mk); GENERIC_LIBDIR in the environment
replaces it."""
import os
import threading

from cffi import FFI

from . import _config
from ._cdef import CDEF

ffi = FFI()
ffi.cdef(CDEF)

LIBDIR = os.environ.get("GENERIC_LIBDIR") or _config.LIBDIR

# Never unloaded (RTLD_NODELETE): the libraries' OpenMP worker threads and thread-local arenas outlive the
# interpreter's teardown of its objects, and must not find their code gone.
FLAGS = ffi.RTLD_NOW | ffi.RTLD_NODELETE

lib = ffi.dlopen(os.path.join(LIBDIR, "libgeneric.so.0"), FLAGS)

_gtrace = None
_gtrace_lock = threading.Lock()


def gtrace():
    """libgtrace.so, opened once, with gtrace's kinds (object, light, camera) registered."""
    global _gtrace
    with _gtrace_lock:
        if _gtrace is None:
            g = ffi.dlopen(os.path.join(LIBDIR, "libgtrace.so"), FLAGS)
            err = ffi.new("GError *")
            if g.gtrace_embed_register(err) != lib.G_OK:
                from .errors import GenericError
                raise GenericError.from_error(err)
            _gtrace = g
        return _gtrace


_gmat = None


def gmat():
    """libgmat.so (gmat check as a function), opened once."""
    global _gmat
    with _gtrace_lock:
        if _gmat is None:
            _gmat = ffi.dlopen(os.path.join(LIBDIR, "libgmat.so"), FLAGS)
        return _gmat
