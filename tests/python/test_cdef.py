"""Drift between the package's hand-written declarations (python/generic/_cdef.py) and the real headers: a C file
generated from the cdef is compiled against include/generic/ and gtrace's embed/render_file.h, and must agree on
every function's type, every struct's size and field offsets, and every constant's value."""
import os
import re
import subprocess

import pytest

from generic import _cdef
from generic._native import ffi, lib

PROTOTYPE = re.compile(r"^(?P<ret>[\w\s\*]+?[\s\*])(?P<name>g\w+)\((?P<args>[^;]*)\);", re.M | re.S)


def prototypes():
    return [(m.group("ret").strip(), m.group("name"), " ".join(m.group("args").split()))
            for m in PROTOTYPE.finditer(_cdef.CDEF)]


def c_source():
    lines = ["#include <stddef.h>", "#include <stdio.h>"]
    lines += [f"#include <{h}>" for h in _cdef.HEADERS]
    for ret, name, args in prototypes():
        # the function's real type must be the cdef's (compatible types, as C defines them)
        lines.append(f"_Static_assert(__builtin_types_compatible_p(__typeof__(&{name}), {ret} (*)({args})), "
                     f'"{name}: the cdef differs from the header");')
    lines.append("int main(void) {")
    for struct in STRUCTS:
        lines.append(f'    printf("{struct} %zu\\n", sizeof({struct}));')
        for field, _ in ffi.typeof(struct).fields:
            lines.append(f'    printf("{struct}.{field} %zu\\n", offsetof({struct}, {field}));')
    for const in CONSTANTS:
        lines.append(f'    printf("{const} %lld\\n", (long long){const});')
    lines += ["    return 0;", "}"]
    return "\n".join(lines) + "\n"


STRUCTS = ["GVec3", "GError", "GColorModelOptions", "GReaderOptions", "GBatchPoints", "GImage", "GColor",
           "GMaterial", "GMaterialSample", "GMaterialClass", "GTypeInfo", "GParamInfo", "GtraceRenderRequest",
           "GtraceImage"]
CONSTANTS = sorted(n for n in dir(lib)
                   if re.match(r"^(G_OK|G_ERR_|GCOLOR_REFL|GCOLOR_LIGHT|GKIND_|GBATCH_|GPARAM_|GMATERIAL_ABI)", n))
INCLUDES = ["include", "examples/gtrace", "examples"]


def test_every_prototype_is_checked():
    names = {name for _, name, _ in prototypes()}
    assert len(names) >= 40
    assert {"gbatch_reflection", "gtrace_render_file", "greader_load_file", "gimage_write"} <= names


def test_cdef_matches_the_headers(source, tmp_path):
    src = tmp_path / "cdef_check.c"
    src.write_text(c_source())
    exe = tmp_path / "cdef_check"
    cc = os.environ.get("CC", "cc")
    build = subprocess.run([cc, "-std=c11", "-D_GNU_SOURCE", "-Wall", "-Werror",
                            *[f"-I{os.path.join(source, d)}" for d in INCLUDES], "-o", str(exe), str(src)],
                           capture_output=True, text=True)
    assert build.returncode == 0, build.stderr
    run = subprocess.run([str(exe)], capture_output=True, text=True, check=True)
    facts = dict(line.rsplit(" ", 1) for line in run.stdout.splitlines())
    for struct in STRUCTS:
        assert int(facts[struct]) == ffi.sizeof(struct), struct
        for field, f in ffi.typeof(struct).fields:
            assert int(facts[f"{struct}.{field}"]) == f.offset, f"{struct}.{field}"
    for const in CONSTANTS:
        assert int(facts[const]) == getattr(lib, const), const


def test_a_drifted_declaration_is_caught(source, tmp_path, monkeypatch):
    """The check fails when a prototype differs: the cdef with one argument's type changed."""
    drifted = _cdef.CDEF.replace("int gbatch_pdf(const GMaterial *m", "int gbatch_pdf(GMaterial *m")
    monkeypatch.setattr(_cdef, "CDEF", drifted)
    src = tmp_path / "drift.c"
    src.write_text(c_source())
    build = subprocess.run([os.environ.get("CC", "cc"), "-std=c11", "-D_GNU_SOURCE", "-Wall", "-Werror", "-c",
                            *[f"-I{os.path.join(source, d)}" for d in INCLUDES], "-o", str(tmp_path / "drift.o"),
                            str(src)], capture_output=True, text=True)
    assert build.returncode != 0 and "gbatch_pdf" in build.stderr
