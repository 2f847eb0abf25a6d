"""Shared fixtures of the Python package's tests: the source and build trees (GENERIC_SOURCE_DIR and
GENERIC_BUILD_DIR, as scripts/run_tests.sh sets them; else this tree and its build/), and the rows of inputs that
bench/bench_batch.c draws for its reference results, drawn the same way."""
import os
import subprocess

import numpy as np
import pytest

SOURCE = os.environ.get("GENERIC_SOURCE_DIR") or os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("GENERIC_BUILD_DIR") or os.path.join(SOURCE, "build")


@pytest.fixture
def source():
    return SOURCE


@pytest.fixture
def build():
    return BUILD


def uniform(seed, n):
    """The n-th uniform numbers of bench_batch.c's uniform(): splitmix64 of seed + n times the golden gamma."""
    with np.errstate(over="ignore"):
        z = np.uint64(seed) + np.asarray(n, dtype=np.uint64) * np.uint64(0x9E3779B97F4A7C15)
        z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        z ^= z >> np.uint64(31)
    return (z >> np.uint64(11)).astype(np.float64) * 2.0 ** -53


def _unit(x, y, z):
    length = np.sqrt(x * x + y * y + z * z)
    return np.stack([x / length, y / length, z / length], axis=1)


def rows(seed, n):
    """bench_batch.c's rows(): (normal, wi, wo), each (n, 3)."""
    k = np.arange(n, dtype=np.uint64) * np.uint64(8)
    u = [uniform(seed, k + np.uint64(j)) for j in range(8)]
    normal = _unit(0.3 * (2 * u[0] - 1), 0.3 * (2 * u[1] - 1), np.ones(n))
    wi = _unit(2 * u[2] - 1, 2 * u[3] - 1, u[4] + 0.05)
    wo = _unit(2 * u[5] - 1, 2 * u[6] - 1, u[7] + 0.05)
    return normal, wi, wo


def c_reference(tmp_path, path, material, model, output, n, seed):
    """bench_batch --reference: the C API's results, one call a row, as float64 (n, width)."""
    out = tmp_path / f"ref_{material}_{model}_{output}.bin"
    prog = os.path.join(BUILD, "bench", "bench_batch")
    subprocess.run([prog, "--reference", path, material, model, output, str(n), str(seed), str(out)], check=True)
    data = np.fromfile(out, dtype=np.float64)
    out.unlink()
    return data.reshape(n, -1)
