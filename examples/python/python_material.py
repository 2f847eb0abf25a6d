"""python_material.py [OUTDIR] - a material written in Python: a Lambertian reflector registered as the type
py_lambert, checked with gmat check in this process, evaluated beside the built-in lambert, and rendered by gtrace
(OUTDIR/python_material.png); the render's cost shows what the interpreter's lock and a callback per evaluation
cost (docs/python.md).
    PYTHONPATH=build/python /usr/bin/python3 examples/python/python_material.py /tmp
"""
import math
import os
import sys
import tempfile
import time

import numpy as np

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


SCENE = """colormodel spectrum
camera pinhole {{ from <0, 1.5, 4> at <0, 0.4, 0> fov 40 width 160 height 120 spp 1 depth 2 }}
light point {{ position <-3, 5, 4> intensity rgb 40 40 40 }}
light ambient {{ color rgb 0.1 0.1 0.1 }}
object plane {{ point <0, 0, 0> normal <0, 1, 0> material {m} {{ reflectance rgb 0.6 0.6 0.55 }} }}
object sphere {{ center <0, 0.6, 0> radius 0.6 material {m} {{ reflectance rgb 0.7 0.3 0.2 }} }}
"""


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "."
    generic.register_material(PyLambert)
    with tempfile.TemporaryDirectory() as tmp:
        mat = os.path.join(tmp, "clay.mat")
        with open(mat, "w") as f:
            f.write("material clay py_lambert { reflectance rgb 0.7 0.5 0.2 }\n")
        if not generic.check(mat, "clay"):
            sys.exit("python_material: gmat check failed")
        seconds = {}
        images = {}
        for m in ("lambert", "py_lambert"):
            scene = os.path.join(tmp, f"{m}.scene")
            with open(scene, "w") as f:
                f.write(SCENE.format(m=m))
            t = time.perf_counter()
            images[m] = generic.render(scene)
            seconds[m] = time.perf_counter() - t
    diff = np.abs(images["py_lambert"] - images["lambert"]).max()
    print(f"python_material: largest difference from the built-in lambert {diff:.3g}; "
          f"render {seconds['lambert']:.3f} s "
          f"(lambert), {seconds['py_lambert']:.3f} s (py_lambert)")
    generic.write_image(os.path.join(outdir, "python_material.png"), images["py_lambert"])
    if diff > 1e-6:
        sys.exit("python_material: the Python lambert differs from the built-in one")


if __name__ == "__main__":
    main()
