"""colormodels.py [OUTDIR] - the same colours through every built-in colour model: random reflectances from sRGB
into each model and back (the round trip's error), and a phong material evaluated in each (the reflected colour's
difference from the spectral reference). Prints a table; writes OUTDIR/colormodels.png with matplotlib when it is
installed.
    PYTHONPATH=build/python /usr/bin/python3 examples/python/colormodels.py /tmp
"""
import os
import sys
import tempfile

import numpy as np

import generic

PLASTIC = "material glossy phong { diffuse rgb 0.6 0.08 0.05 specular rgb 0.25 0.25 0.25 exponent 60 }\n"


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "."
    rng = np.random.default_rng(7)
    rgb = rng.uniform(0.02, 0.98, (10000, 3))
    n = 2000
    wi = rng.normal(size=(n, 3))
    wi[:, 2] = np.abs(wi[:, 2])
    wi /= np.linalg.norm(wi, axis=1)[:, None]
    wo = wi * [-1.0, -1.0, 1.0] + rng.normal(scale=0.05, size=(n, 3))
    wo[:, 2] = np.abs(wo[:, 2])
    wo /= np.linalg.norm(wo, axis=1)[:, None]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "glossy.mat")
        with open(path, "w") as f:
            f.write(PLASTIC)
        results = {m: generic.load(path, colormodel=m).material("glossy").reflection([0, 0, 1], wi, wo)
                   for m in generic.colormodels()}
    reference = results["spectrum"]
    print(f"{'model':12s} {'values':>6s} {'round trip max |drgb|':>22s} {'phong vs spectrum max |drgb|':>30s}")
    rows = []
    for name in generic.colormodels():
        model = generic.ColorModel(name)
        back = model.to_rgb(model.from_rgb(rgb))
        trip = np.abs(back - rgb).max()
        diff = np.abs(results[name] - reference).max()
        rows.append((name, model.nvalues, trip, diff))
        print(f"{name:12s} {model.nvalues:6d} {trip:22.3g} {diff:30.3g}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("colormodels: matplotlib is not installed (python3-matplotlib): no plot")
        return
    fig, ax = plt.subplots(figsize=(6, 3.5))
    names = [r[0] for r in rows]
    ax.bar(np.arange(len(rows)) - 0.2, [max(r[2], 1e-9) for r in rows], 0.4, label="sRGB round trip")
    ax.bar(np.arange(len(rows)) + 0.2, [max(r[3], 1e-9) for r in rows], 0.4, label="phong vs spectrum")
    ax.set_xticks(np.arange(len(rows)), names)
    ax.set_yscale("log")
    ax.set_ylabel("largest |difference| in linear sRGB")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "colormodels.png"), dpi=100)
    print(f"colormodels: wrote {os.path.join(outdir, 'colormodels.png')}")


if __name__ == "__main__":
    main()
