"""Errors of the library as Python exceptions."""
import re

from ._native import ffi, lib

_POSITION = re.compile(r"^(?P<file>.*?):(?P<line>\d+):(?P<col>\d+): ")


class GenericError(Exception):
    """A failure reported by the library: `code` (a negative G_ERR_ status), `status` (its name), `message` (the
    library's message, "FILE:LINE:COL: ..." for an error in a text file), and `file`, `line`, `col` and `param`
    where the message places it (None when it does not)."""

    def __init__(self, message, code=lib.G_ERR_INVALID, param=None):
        super().__init__(message)
        self.message = message
        self.code = code
        self.status = ffi.string(lib.gstatus_string(code)).decode()
        self.param = param or None
        m = _POSITION.match(message)
        self.file = m.group("file") if m else None
        self.line = int(m.group("line")) if m else None
        self.col = int(m.group("col")) if m else None

    @classmethod
    def from_error(cls, err, code=None):
        """The exception of a filled GError (code: the status returned, when err holds none)."""
        message = ffi.string(err.message).decode("utf-8", "replace")
        c = err.code if err.code < 0 else (code if code is not None else lib.G_ERR_INVALID)
        if not message:
            message = ffi.string(lib.gstatus_string(c)).decode()
        return cls(message, c, ffi.string(err.param).decode("utf-8", "replace"))


def check(rc, err):
    """Raises the GenericError of err when rc is a failure; returns rc otherwise."""
    if rc < 0:
        raise GenericError.from_error(err, rc)
    return rc
