"""Batch evaluations per second from Python (the package generic) for the materials and models bench_batch.c
measures in C: lambert in rgb and phong in spectrum, reflection into linear sRGB, 1e6 rows, on one thread and on
every thread; and for scale, one call per row through the package (the cost of a Python-level loop).
Run with `make bench-python` (PYTHONPATH=build/python /usr/bin/python3 bench/python_batch.py). Prints figures and
never fails on time."""
import os
import sys
import tempfile
import time

import numpy as np

import generic

N = 1_000_000


def rows(n, seed=1):
    rng = np.random.default_rng(seed)
    normal = np.column_stack([rng.uniform(-0.3, 0.3, (n, 2)), np.ones(n)])
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    wi = np.column_stack([rng.uniform(-1, 1, (n, 2)), rng.uniform(0.05, 1.05, n)])
    wi /= np.linalg.norm(wi, axis=1)[:, None]
    wo = np.column_stack([rng.uniform(-1, 1, (n, 2)), rng.uniform(0.05, 1.05, n)])
    wo /= np.linalg.norm(wo, axis=1)[:, None]
    return normal, wi, wo


def best_of(runs, fn):
    best = float("inf")
    for _ in range(runs):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def bench(model, text, name):
    with tempfile.NamedTemporaryFile("w", suffix=".mat", delete=False) as f:
        f.write(text)
    try:
        mat = generic.load(f.name, colormodel=model).material(name)
    finally:
        os.unlink(f.name)
    normal, wi, wo = rows(N)
    one = best_of(3, lambda: mat.reflection(normal, wi, wo, threads=1))
    every = best_of(3, lambda: mat.reflection(normal, wi, wo))
    k = 2000
    per_call = best_of(1, lambda: [mat.reflection(normal[i], wi[i], wo[i]) for i in range(k)])
    print(f"{name:8s} {model:9s} rgb out: batch 1 thread {N / one * 1e-6:8.3f} M/s, batch all threads "
          f"{N / every * 1e-6:8.3f} M/s, one package call a row {k / per_call * 1e-3:8.1f} k/s")


class PyLambert(generic.PythonMaterial):
    keyword = "bench_py_lambert"
    params = {"reflectance": generic.Param("color", 0.8)}

    def reflection(self, sp, wi, illum, wo, result):
        c = sp.cos_in(wi, wo)
        if c <= 0.0:
            result.black()
        else:
            result.mul_scaled(self.reflectance, illum, c / 3.141592653589793)


def bench_python_material(n=100_000):
    """A lambert written in Python through the same batch call: the cost of a callback per evaluation, and of the
    interpreter's lock that the threads take in turn."""
    generic.register_material(PyLambert)
    with tempfile.NamedTemporaryFile("w", suffix=".mat", delete=False) as f:
        f.write("material m bench_py_lambert { reflectance rgb 0.7 0.5 0.2 }")
    try:
        mat = generic.load(f.name, colormodel="rgb").material("m")
    finally:
        os.unlink(f.name)
    normal, wi, wo = rows(n)
    one = best_of(2, lambda: mat.reflection(normal, wi, wo, threads=1))
    every = best_of(2, lambda: mat.reflection(normal, wi, wo))
    print(f"{'py_lambert':8s} {'rgb':9s} rgb out: batch 1 thread {n / one * 1e-6:8.3f} M/s, batch all threads "
          f"{n / every * 1e-6:8.3f} M/s ({one / n * 1e6:.2f} us a call)")


def main():
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, {os.cpu_count()} processors")
    bench("rgb", "material matte lambert { reflectance rgb 0.7 0.5 0.2 }", "matte")
    bench("spectrum", "material plastic phong { diffuse rgb 0.6 0.08 0.05 specular rgb 0.25 0.25 0.25 "
          "exponent 60 }", "plastic")
    bench_python_material()


if __name__ == "__main__":
    main()
