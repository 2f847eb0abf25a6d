"""The batch methods from numpy against the C API called one row at a time (bench_batch --reference), bit for bit;
their values against analytic ones; threads that do not change a bit."""
import os

import numpy as np
import pytest

import generic
from conftest import c_reference, rows

PLASTIC = "examples/materials/phong.mat"


def test_million_phong_in_spectrum_equal_c_bit_for_bit(source, tmp_path):
    n, seed = 1_000_000, 12345
    normal, wi, wo = rows(seed, n)
    mat = generic.load(os.path.join(source, PLASTIC), colormodel="spectrum").material("red_plastic")
    got = mat.reflection(normal, wi, wo)
    want = c_reference(tmp_path, os.path.join(source, PLASTIC), "red_plastic", "spectrum", "rgb", n, seed)
    assert got.shape == (n, 3) and got.dtype == np.float64
    assert np.count_nonzero(got) > n  # the lobe lights most rows
    assert got.tobytes() == want.tobytes()


def test_samples_equal_c_bit_for_bit(source, tmp_path):
    n, seed = 100_000, 99
    normal, wi, wo = rows(seed, n)
    mat = generic.load(os.path.join(source, PLASTIC), colormodel="spectrum").material("lacquer")
    got = mat.reflection(normal, wi, wo, output="samples")
    want = c_reference(tmp_path, os.path.join(source, PLASTIC), "lacquer", "spectrum", "samples", n, seed)
    assert got.shape == (n, 81)
    assert got.tobytes() == want.tobytes()


def test_lambert_is_albedo_over_pi_times_cosine(source):
    lib = generic.load(os.path.join(source, "examples/materials/lambert.mat"), colormodel="rgb")
    name = lib.materials()[0]
    mat = lib.material(name)
    normal, wi, wo = rows(5, 10_000)
    white = mat.reflection(normal, wi, wo, output="samples")
    cos_in = np.einsum("ij,ij->i", normal, wi)
    cos_out = np.einsum("ij,ij->i", normal, wo)
    lit = (cos_in > 0) & (cos_out > 0)
    rho = white[lit] / cos_in[lit, None] * np.pi
    assert np.allclose(rho, rho[0], rtol=1e-6, atol=1e-7)  # one albedo everywhere
    assert np.all(white[~lit] == 0)


def test_threads_do_not_change_a_bit(source):
    mat = generic.load(os.path.join(source, PLASTIC), colormodel="spectrum").material("red_plastic")
    normal, wi, wo = rows(3, 20_000)
    one = mat.reflection(normal, wi, wo, output="xyz", threads=1)
    many = mat.reflection(normal, wi, wo, output="xyz", threads=4)
    assert one.tobytes() == many.tobytes()


def test_single_rows_broadcast(source):
    mat = generic.load(os.path.join(source, PLASTIC)).material("red_plastic")
    normal, wi, wo = rows(8, 50)
    got = mat.reflection([0, 0, 1], wi, wo)
    want = mat.reflection(np.tile([0.0, 0.0, 1.0], (50, 1)), wi, wo)
    assert got.tobytes() == want.tobytes()


def test_sample_pdf_and_weight_agree(source):
    mat = generic.load(os.path.join(source, PLASTIC), colormodel="rgb").material("red_plastic")
    n = 20_000
    normal, _, wo = rows(11, n)
    u = np.random.default_rng(1).random((n, 2))
    wi, pdf, flags, weight = mat.sample(normal, wo, u, output="samples")
    drawn = flags != 0
    assert drawn.mean() > 0.5
    # the density sample() reports is the one pdf() gives for the drawn direction (no delta lobe here)
    again = mat.pdf(normal[drawn], wi[drawn], wo[drawn])
    assert np.allclose(again, pdf[drawn], rtol=1e-9)
    # the weight is reflection / pdf
    value = mat.reflection(normal[drawn], wi[drawn], wo[drawn], output="samples")
    ok = pdf[drawn] > 1e-3
    assert np.allclose(weight[drawn][ok], value[ok] / pdf[drawn][ok, None], rtol=1e-5, atol=1e-9)


def test_emission_and_refraction(source):
    lib = generic.load(os.path.join(source, "examples/materials/emitter.mat"), colormodel="spectrum")
    lamp = lib.material(lib.materials()[0])
    normal, _, wo = rows(2, 100)
    e = lamp.emission(normal, wo)
    front = np.einsum("ij,ij->i", normal, wo) > 0
    assert e.shape == (100, 3) and front.sum() > 50
    assert np.all(e[front] > 0) and np.all(e[front] == e[front][0])  # one radiance towards the front
    assert np.all(e[~front] == 0)  # one-sided
    glass = generic.load(os.path.join(source, "examples/materials/dielectric.mat")).material("bk7")
    below = -wo  # light from below the surface
    t = glass.refraction(normal, below, wo)
    assert t.shape == (100, 3) and np.all(np.isfinite(t))


def test_generator_values(tmp_path):
    path = tmp_path / "gen.mat"
    path.write_text("generator ramp gradient { space world slope 1 0 0 offset 0 }\n")
    g = generic.load(path).generator("ramp")
    x = np.linspace(0.05, 0.95, 19)
    pts = np.stack([x, np.zeros_like(x), np.zeros_like(x)], axis=1)
    v = g.value(pts)
    assert v.shape == (19,)
    assert np.all(np.diff(v) > 0)  # a ramp along x


def test_surface_point_constructor_and_single_evaluation(source):
    lib = generic.load(os.path.join(source, PLASTIC), colormodel="spectrum")
    mat = lib.material("red_plastic")
    normal, wi, wo = rows(21, 40)
    for i in range(40):
        sp = generic.SurfacePoint(lib.colormodel, [0, 0, 0], normal[i] * 2.0)  # normalised by the library
        for output in ("rgb", "samples"):
            one = mat.reflection_at(sp, wi[i], wo[i], output=output)
            assert one.tobytes() == mat.reflection(normal[i], wi[i], wo[i], output=output)[0].tobytes()
    assert sp.size > 200
    with pytest.raises(generic.GenericError, match="normal"):
        generic.SurfacePoint(lib.colormodel, [0, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="^point must have shape"):
        generic.SurfacePoint(lib.colormodel, [0, 0], [0, 0, 1])
