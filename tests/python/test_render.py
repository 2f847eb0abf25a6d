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
