"""Bad input from Python: wrong shapes and dtypes raise exceptions naming the argument, library errors carry
file:line:col, and random shapes, dtypes and values never crash the interpreter."""
import os

import numpy as np
import pytest

import generic


@pytest.fixture
def plastic(source):
    return generic.load(os.path.join(source, "examples/materials/phong.mat")).material("red_plastic")


def test_shapes_name_the_argument(plastic):
    good = np.tile([0.0, 0.0, 1.0], (4, 1))
    with pytest.raises(ValueError, match=r"^normal must have shape \(N, 3\)"):
        plastic.reflection(np.zeros((4, 2)), good, good)
    with pytest.raises(ValueError, match=r"^wi must have shape \(N, 3\), not \(4, 3, 1\)"):
        plastic.reflection(good, np.zeros((4, 3, 1)), good)
    with pytest.raises(ValueError, match=r"^wo has 5 rows where normal has 4"):
        plastic.reflection(good, good, np.tile([0.0, 0.0, 1.0], (5, 1)))
    with pytest.raises(ValueError, match=r"^uv must have shape \(N, 2\)"):
        plastic.reflection(good, good, good, uv=np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"^u must have shape \(N, 2\)"):
        plastic.sample(good, good, np.zeros(4))
    with pytest.raises(ValueError, match="^output must be one of 'samples', 'xyz', 'rgb', not 'srgb'"):
        plastic.reflection(good, good, good, output="srgb")
    with pytest.raises(ValueError, match="^threads"):
        plastic.reflection(good, good, good, threads=-1)


def test_dtypes_name_the_argument(plastic):
    good = np.tile([0.0, 0.0, 1.0], (4, 1))
    with pytest.raises(TypeError, match="^wi must hold real numbers"):
        plastic.reflection(good, good.astype(complex), good)
    with pytest.raises(TypeError, match="^normal must hold real numbers"):
        plastic.reflection([["a", "b", "c"]], good, good)
    with pytest.raises(TypeError, match="^wo must hold real numbers"):
        plastic.reflection(good, good, np.ones((4, 3), dtype=bool))
    # other real dtypes are taken: float32, integers, non-contiguous views
    f32 = plastic.reflection(good.astype(np.float32), good[:, ::1], np.asfortranarray(good))
    ints = plastic.reflection(good.astype(np.int64), good, good)
    assert f32.tobytes() == ints.tobytes()


def test_library_errors_carry_file_line_col(tmp_path):
    bad = tmp_path / "bad.mat"
    bad.write_text("material ok lambert { reflectance rgb 0.5 0.5 0.5 }\n"
                   "material bad lambert { shininess 3 }\n")
    with pytest.raises(generic.GenericError) as e:
        generic.load(bad)
    assert e.value.file == str(bad) and e.value.line == 2 and e.value.col == 24
    assert str(e.value).startswith(f"{bad}:2:")
    assert e.value.code == generic.lib.G_ERR_INVALID or e.value.code < 0
    with pytest.raises(generic.GenericError) as e:
        generic.load(tmp_path / "missing.mat")
    assert e.value.status
    with pytest.raises(KeyError, match="defines no material named 'nothing'"):
        generic.load(_ok(tmp_path)).material("nothing")


def _ok(tmp_path):
    p = tmp_path / "ok.mat"
    p.write_text("material ok lambert { reflectance rgb 0.5 0.5 0.5 }\n")
    return p


def test_plugins_need_consent(tmp_path, build, monkeypatch):
    monkeypatch.delenv("GENERIC_ALLOW_PLUGINS", raising=False)
    p = tmp_path / "plug.mat"
    p.write_text(f'plugin "{build}/modules/lambert.so"\n')
    with pytest.raises(generic.GenericError, match="allow"):
        generic.load(p)


def test_bad_values_become_exceptions_naming_the_row(plastic):
    n = np.tile([0.0, 0.0, 1.0], (10, 1))
    wi = n.copy()
    wi[6, 1] = np.nan
    with pytest.raises(generic.GenericError, match="row 6: in is not finite"):
        plastic.reflection(n, wi, n)
    n[3] = 0.0
    with pytest.raises(generic.GenericError, match="row 3: normal is zero"):
        plastic.reflection(n, wi, wi)
    with pytest.raises(generic.GenericError, match="u is outside"):
        plastic.sample([0, 0, 1], [0, 0, 1], [[0.5, 1.5]])


def _random_array(rng):
    """Mostly (N, 3) or (N, 2) arrays of a few rows, sometimes other shapes, dtypes and non-finite values."""
    r = rng.random()
    if r < 0.6:
        shape = (int(rng.integers(0, 6)), int(rng.choice([2, 3, 3, 3])))
    elif r < 0.7:
        shape = (int(rng.choice([2, 3])),)
    else:
        shape = tuple(int(s) for s in rng.integers(0, 5, size=rng.integers(0, 4)))
    a = np.asarray(rng.uniform(-1, 1, size=shape) * rng.choice([1e-300, 1, 1e300]))
    if rng.random() < 0.2 and a.size:
        a.flat[0] = rng.choice([np.nan, np.inf, -np.inf, 0.0])
    if rng.random() < 0.15:
        dtype = rng.choice([np.float32, np.int32, np.uint8, np.complex64, np.bool_, object])
        with np.errstate(all="ignore"):
            return a.astype(dtype)
    return a


def test_fuzz_random_shapes_dtypes_and_values(source):
    lib = generic.load(os.path.join(source, "examples/materials/phong.mat"), colormodel="spectrum9")
    mat = lib.material("lacquer")
    rng = np.random.default_rng(2024)
    calls = {"ok": 0, "refused": 0}
    for _ in range(3000):
        args = [_random_array(rng) for _ in range(3)]
        method = rng.integers(0, 5)
        try:
            if method == 0:
                r = mat.reflection(*args, output=rng.choice(["rgb", "xyz", "samples"]))
            elif method == 1:
                r = mat.refraction(*args)
            elif method == 2:
                r = mat.pdf(*args, threads=int(rng.integers(0, 4)))
            elif method == 3:
                r = mat.sample(*args)
            else:
                r = lib.colormodel.to_rgb(_random_array(rng))
            calls["ok"] += 1
            assert r is not None
        except (ValueError, TypeError, generic.GenericError):
            calls["refused"] += 1
    assert calls["ok"] > 0 and calls["refused"] > 0
