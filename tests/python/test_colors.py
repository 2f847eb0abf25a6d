"""Colour models from Python: listing, wavelengths, conversions to and from numpy."""
import numpy as np
import pytest

import generic


def test_registered_names():
    assert {"rgb", "spectrum", "spectrum9", "bispectral"} <= set(generic.colormodels())
    assert {"lambert", "phong", "mirror", "dielectric", "emitter"} <= set(generic.types("material"))
    assert "checker" in generic.types("generator")
    with pytest.raises(generic.GenericError, match="no kind 'shader'"):
        generic.types("shader")


@pytest.mark.parametrize("name, n", [("rgb", 3), ("spectrum9", 9), ("spectrum", 81)])
def test_round_trip(name, n):
    m = generic.ColorModel(name)
    assert m.nvalues == n
    rgb = np.random.default_rng(3).uniform(0.05, 0.95, (500, 3))
    samples = m.from_rgb(rgb)
    assert samples.shape == (500, n) and samples.dtype == np.float32
    assert np.allclose(m.to_rgb(samples), rgb, atol=2e-3)


def test_wavelengths_and_steps():
    assert generic.ColorModel("rgb").wavelengths.size == 0
    s = generic.ColorModel("spectrum", step_nm=10)
    assert s.nvalues == 41
    assert np.array_equal(s.wavelengths, np.arange(380.0, 781.0, 10.0))


def test_white_light_is_y_one():
    m = generic.ColorModel("spectrum")
    white = m.from_rgb([1.0, 1.0, 1.0], role="light")
    assert m.to_xyz(white, role="light")[0, 1] == pytest.approx(1.0, abs=1e-3)


def test_a_lights_brightness_is_its_y_in_every_model():
    rgb = np.random.default_rng(5).uniform(0.0, 1.0, (40, 3))
    per_model = []
    for name in ("rgb", "spectrum9", "spectrum", "bispectral"):
        m = generic.ColorModel(name)
        light = m.from_rgb(rgb, role="light")
        b = m.brightness(light, role="light")
        assert np.allclose(b, m.to_xyz(light, role="light")[:, 1], atol=1e-5)
        per_model.append(b)
    for b in per_model[1:]:
        assert np.allclose(b, per_model[0], atol=1e-3)
    with pytest.raises(generic.GenericError):
        generic.ColorModel("rgb").brightness(np.zeros((2, 4)))


def test_bad_arguments():
    with pytest.raises(generic.GenericError):
        generic.ColorModel("cmyk")
    m = generic.ColorModel("spectrum9")
    with pytest.raises(ValueError, match="^samples must have shape"):
        m.to_rgb(np.zeros((2, 3)))
    with pytest.raises(ValueError, match="^role"):
        m.from_rgb([0.5, 0.5, 0.5], role="paint")
