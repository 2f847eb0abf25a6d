"""A material written in Python: registered as a type, read from text, checked by gmat check in this process, and
rendered by gtrace within 1e-6 of the built-in lambert; failures inside Python become errors, not crashes."""
import math

import numpy as np
import pytest

import generic


class PyLambert(generic.PythonMaterial):
    keyword = "py_lambert"
    description = "ideal diffuse reflector written in Python (f = rho / pi)"
    params = {"reflectance": generic.Param("color", 0.8, "the albedo rho (f = rho / pi)")}

    def reflection(self, sp, wi, illum, wo, result):
        c = sp.cos_in(wi, wo)
        if c <= 0.0:
            result.black()
        else:
            result.mul_scaled(self.reflectance, illum, c / math.pi)

    def diffuse(self, sp, result):
        result.copy(self.reflectance)


class Broken(generic.PythonMaterial):
    keyword = "py_broken"
    params = {"gain": generic.Param("number", 1.0, "a factor", 0.0, 10.0)}

    def reflection(self, sp, wi, illum, wo, result):
        raise RuntimeError("this method fails on purpose")


generic.register_material(PyLambert)
generic.register_material(Broken)

SCENE = """colormodel {model}
camera pinhole {{ from <0, 1.5, 4> at <0, 0.4, 0> fov 40 width 40 height 30 spp 2 depth 2 }}
light point {{ position <-3, 5, 4> intensity rgb 40 40 40 }}
light ambient {{ color rgb 0.1 0.1 0.1 }}
object plane {{ point <0, 0, 0> normal <0, 1, 0> material {lambert} {{ reflectance rgb 0.6 0.6 0.55 }} }}
object sphere {{ center <0, 0.6, 0> radius 0.6 material {lambert} {{ reflectance rgb 0.7 0.3 0.2 }} }}
"""


@pytest.mark.parametrize("model", ["rgb", "spectrum"])
def test_renders_within_1e6_of_the_builtin(tmp_path, model):
    images = {}
    for lam in ("lambert", "py_lambert"):
        path = tmp_path / f"{lam}.scene"
        path.write_text(SCENE.format(model=model, lambert=lam))
        images[lam] = generic.render(path, threads=2)
    assert images["lambert"].max() > 0.05
    assert np.abs(images["py_lambert"] - images["lambert"]).max() <= 1e-6


def test_passes_gmat_check(tmp_path, capfd):
    path = tmp_path / "py.mat"
    path.write_text("material clay py_lambert { reflectance rgb 0.7 0.5 0.2 }\n")
    assert generic.check(path, "clay") is True
    out = capfd.readouterr().out
    assert "clay (py_lambert)" in out and "clay: PASS" in out and "chi2" in out


def test_batch_equals_the_builtin(tmp_path):
    path = tmp_path / "two.mat"
    path.write_text("material a py_lambert { reflectance rgb 0.7 0.5 0.2 }\n"
                    "material b lambert { reflectance rgb 0.7 0.5 0.2 }\n")
    lib = generic.load(path, colormodel="spectrum")
    rng = np.random.default_rng(4)
    wi, wo = rng.normal(size=(2, 500, 3))
    normal = np.tile([0.0, 0.0, 1.0], (500, 1))
    a = lib.material("a").reflection(normal, wi, wo, output="samples")
    b = lib.material("b").reflection(normal, wi, wo, output="samples")
    assert np.count_nonzero(b) > 0 and a.tobytes() == b.tobytes()


def test_parameters_and_errors(tmp_path, capfd):
    path = tmp_path / "bad.mat"
    path.write_text("material x py_lambert { shine 3 }\n")
    with pytest.raises(generic.GenericError) as e:
        generic.load(path)
    assert e.value.line == 1 and "expected one of: reflectance" in str(e.value)
    path.write_text("material y py_broken { gain 11 }\n")
    with pytest.raises(generic.GenericError, match=r":1:29: value 11 is out of range \[0, 10\]"):
        generic.load(path)
    path.write_text("material z py_broken { gain 2 }\n")
    z = generic.load(path).material("z")
    with pytest.raises(generic.GenericError, match="row 0"):
        z.reflection([0, 0, 1], [0, 0, 1], [0, 0, 1])
    assert "this method fails on purpose" in capfd.readouterr().err
    with pytest.raises(generic.GenericError, match="registered already"):
        generic.register_material(type("Other", (generic.PythonMaterial,), {"keyword": "py_lambert"}))
    assert generic.register_material(PyLambert) is PyLambert
    assert "py_lambert" in generic.types("material")
