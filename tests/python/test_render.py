"""generic.render against gtrace's EXR of the same scene and options, bit for bit; its options and errors."""
import os
import subprocess

import numpy as np
import pytest

import generic


def gtrace_exr(build, tmp_path, scene, *options):
    out = tmp_path / "gtrace.exr"
    subprocess.run([os.path.join(build, "bin", "gtrace"), scene, "-o", str(out), "-q", *options], check=True)
    img = generic.read_image(out)
    out.unlink()
    return img[:, :, :3]


@pytest.mark.parametrize("scene, options, kwargs", [
    ("examples/scenes/demo.scene", ["--width", "96", "--spp", "2"], {"width": 96, "spp": 2}),
    ("examples/scenes/material_dielectric.scene", ["--width", "64", "--colormodel", "spectrum"],
     {"width": 64, "colormodel": "spectrum"}),
    ("examples/scenes/cornell.scene", ["--width", "48", "--height", "40", "--spp", "4", "--integrator", "path"],
     {"width": 48, "height": 40, "spp": 4, "integrator": "path"}),
    ("examples/scenes/node_interpolate.scene", ["--width", "120", "--crop", "20,10,90,50", "--threads", "1"],
     {"width": 120, "crop": (20, 10, 90, 50), "threads": 1}),
])
def test_render_equals_gtrace_exr(source, build, tmp_path, scene, options, kwargs):
    path = os.path.join(source, scene)
    want = gtrace_exr(build, tmp_path, path, *options)
    got = generic.render(path, **kwargs)
    assert got.dtype == np.float32 and got.ndim == 3 and got.shape[2] == 3
    assert got.shape == want.shape
    assert got.max() > 0.01  # a picture, not a black frame
    assert got.tobytes() == want.tobytes()


def test_render_size_follows_the_camera(source):
    img = generic.render(os.path.join(source, "examples/scenes/demo.scene"), height=30, spp=1)
    assert img.shape[0] == 30 and img.shape[1] > 30  # the camera's aspect is wider than tall


def test_render_errors(source, tmp_path):
    bad = tmp_path / "bad.scene"
    bad.write_text("camera pinhole { from <0, 0, 5> at <0, 0, 0> fov 40 width 32 height 32 }\n"
                   "object sphere { center <0, 0, 0> radius -1 }\n")
    with pytest.raises(generic.GenericError) as e:
        generic.render(bad)
    assert e.value.file == str(bad) and e.value.line == 2 and e.value.col > 1
    with pytest.raises(generic.GenericError):
        generic.render(tmp_path / "missing.scene")
    with pytest.raises(ValueError, match="integrator"):
        generic.render(os.path.join(source, "examples/scenes/demo.scene"), integrator="bidir")
    with pytest.raises(ValueError, match="width"):
        generic.render(os.path.join(source, "examples/scenes/demo.scene"), width=-3)
    with pytest.raises(ValueError, match="crop"):
        generic.render(os.path.join(source, "examples/scenes/demo.scene"), crop=(1, 2, 3))
    with pytest.raises(generic.GenericError, match="crop"):
        generic.render(os.path.join(source, "examples/scenes/demo.scene"), width=32, crop=(0, 0, 64, 8))


def test_write_and_read_image(tmp_path):
    ramp = np.linspace(0, 2, 4 * 6 * 3, dtype=np.float32).reshape(4, 6, 3)
    generic.write_image(tmp_path / "ramp.exr", ramp)
    assert generic.read_image(tmp_path / "ramp.exr")[:, :, :3].tobytes() == ramp.tobytes()
    with pytest.raises(ValueError, match="pixels"):
        generic.write_image(tmp_path / "bad.exr", np.zeros((4, 6, 7)))
    with pytest.raises(TypeError, match="pixels"):
        generic.write_image(tmp_path / "bad.exr", np.array([["a"]]))


EXIT_SCRIPT = """
import sys
import numpy as np
import generic
sys.path.insert(0, {tests!r})
import test_pymaterial  # registers py_lambert
kept = generic.load({mat!r}).material("clay")   # alive at exit: released during the interpreter's teardown
kept.reflection(np.tile([0.0, 0.0, 1.0], (5000, 1)), [0, 0.6, 0.8], [0, -0.6, 0.8], threads=2)
generic.render({scene!r}, width=32, threads=2)
"""


def test_the_interpreter_exits_cleanly(source, tmp_path):
    """OpenMP's threads and the libraries' thread-local arenas outlive the interpreter's objects: exiting after
    threaded work, with a Python material alive, ends with status 0 (the libraries are never unloaded)."""
    import subprocess
    import sys
    mat = tmp_path / "clay.mat"
    mat.write_text("material clay py_lambert { reflectance rgb 0.7 0.5 0.2 }\n")
    script = EXIT_SCRIPT.format(tests=os.path.dirname(__file__), mat=str(mat),
                                scene=os.path.join(source, "examples/scenes/demo.scene"))
    for _ in range(4):
        r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
        assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr
