"""numpy arrays in and out of the C API: checked shapes and dtypes, contiguous buffers, cffi pointers."""
import numpy as np

from ._native import ffi, lib

OUTPUTS = {"samples": lib.GBATCH_SAMPLES, "xyz": lib.GBATCH_XYZ, "rgb": lib.GBATCH_RGB}
ROLES = {"reflectance": lib.GCOLOR_REFLECTANCE, "light": lib.GCOLOR_LIGHT}


def choice(name, value, table):
    """table[value], or ValueError naming the argument and the choices."""
    try:
        return table[value]
    except (KeyError, TypeError):
        raise ValueError(f"{name} must be one of {', '.join(repr(k) for k in table)}, not {value!r}") from None


def as_rows(name, value, width, dtype=np.float64):
    """value as a C-contiguous (N, width) array of dtype; a single row (width,) is (1, width). TypeError naming the
    argument for a dtype that is not a real number, ValueError for another shape."""
    a = np.asarray(value)
    if a.dtype == object or not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)) \
            or a.dtype == np.bool_:
        raise TypeError(f"{name} must hold real numbers (a float or integer array), not dtype {a.dtype}")
    if a.ndim == 1 and a.shape[0] == width:
        a = a.reshape(1, width)
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{name} must have shape (N, {width}), not {a.shape}")
    return np.ascontiguousarray(a, dtype=dtype)


def common_rows(arrays):
    """The N of several (N, k) arrays, those of one row repeated to it. ValueError naming the first argument
    whose N differs from an earlier one's."""
    first = next(((name, a.shape[0]) for name, a in arrays if a.shape[0] != 1), (arrays[0][0], 1))
    n = first[1]
    out = []
    for name, a in arrays:
        if a.shape[0] == 1 and n != 1:
            a = np.ascontiguousarray(np.broadcast_to(a, (n, a.shape[1])))
        elif a.shape[0] != n:
            raise ValueError(f"{name} has {a.shape[0]} rows where {first[0]} has {n}")
        out.append(a)
    return n, out


def ptr(a, ctype="double *"):
    """A pointer to a contiguous array's data (NULL for None)."""
    if a is None:
        return ffi.NULL
    return ffi.cast(ctype, ffi.from_buffer(a))


def threads_arg(threads):
    """The threads argument of the C API (0: OpenMP's default)."""
    if threads is None:
        return 0
    if not isinstance(threads, (int, np.integer)) or isinstance(threads, bool) or threads < 0:
        raise ValueError(f"threads must be a whole number >= 0 or None, not {threads!r}")
    return int(threads)
