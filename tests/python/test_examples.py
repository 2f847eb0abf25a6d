"""The examples of examples/python/ run, and write what they say they write."""
import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest

HAVE_MATPLOTLIB = importlib.util.find_spec("matplotlib") is not None


def run(source, name, outdir):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    r = subprocess.run([sys.executable, os.path.join(source, "examples", "python", name), str(outdir)], env=env,
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return r.stdout


def test_brdf_plot(source, tmp_path):
    out = run(source, "brdf_plot.py", tmp_path)
    table = np.loadtxt(tmp_path / "brdf.csv", delimiter=",", skiprows=1)
    header = (tmp_path / "brdf.csv").read_text().splitlines()[0].split(",")
    assert {"lambert", "phong", "mirror", "dielectric", "emitter"} <= set(header)
    assert table.shape == (1801, len(header))
    lambert = table[:, header.index("lambert")]
    assert np.allclose(lambert, lambert[0]) and lambert[0] > 0.1  # a constant f_r cos theta_in
    assert (tmp_path / "brdf.png").exists() == HAVE_MATPLOTLIB, out


def test_colormodels(source, tmp_path):
    out = run(source, "colormodels.py", tmp_path)
    for name in ("rgb", "spectrum9", "spectrum", "bispectral"):
        assert f"\n{name} " in out
    assert (tmp_path / "colormodels.png").exists() == HAVE_MATPLOTLIB


def test_python_material(source, tmp_path):
    out = run(source, "python_material.py", tmp_path)
    assert "clay: PASS" in out and "largest difference from the built-in lambert" in out
    assert (tmp_path / "python_material.png").stat().st_size > 0
