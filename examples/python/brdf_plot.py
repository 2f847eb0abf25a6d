"""brdf_plot.py [OUTDIR] - the reflection of every built-in material type, with its default parameters, in the
plane of incidence: light from 45 degrees, the viewer swept over the hemisphere, one batch call per material
(1801 directions), in the spectrum model, plotted as luminance Y. Writes OUTDIR/brdf.png with matplotlib when it
is installed (python3-matplotlib), and OUTDIR/brdf.csv always (default OUTDIR: the current directory).
    PYTHONPATH=build/python /usr/bin/python3 examples/python/brdf_plot.py /tmp
"""
import os
import sys
import tempfile

import numpy as np

import generic


def curves(n=1801):
    """theta_out in degrees and, per material type, the luminance reflected towards each direction."""
    # Types with a required parameter are shown with one; the rest with their defaults.
    required = {"layer": "layer { top dielectric { index 1.5 } bottom lambert { } }"}
    theta = np.linspace(-89.0, 89.0, n)
    t = np.radians(theta)
    wo = np.stack([np.sin(t), np.zeros(n), np.cos(t)], axis=1)
    wi = np.tile([-np.sin(np.radians(45.0)), 0.0, np.cos(np.radians(45.0))], (n, 1))
    normal = [0.0, 0.0, 1.0]
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        for kind in generic.types("material"):
            path = os.path.join(tmp, f"{kind}.mat")
            with open(path, "w") as f:
                f.write(f"material sample {required.get(kind, kind)}\n")
            mat = generic.load(path, colormodel="spectrum").material("sample")
            out[kind] = mat.reflection(normal, wi, wo, output="xyz")[:, 1]
    return theta, out


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "."
    theta, ys = curves()
    table = np.column_stack([theta] + list(ys.values()))
    np.savetxt(os.path.join(outdir, "brdf.csv"), table, delimiter=",", fmt="%.6g",
               header="theta_out," + ",".join(ys), comments="")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("brdf_plot: matplotlib is not installed (python3-matplotlib): wrote brdf.csv only")
        return
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for kind, y in ys.items():
        ax.plot(theta, y, label=kind)
    ax.set_xlabel("viewing angle (degrees; light at -45)")
    ax.set_ylabel("reflected luminance Y (f_r cos theta_in)")
    ax.set_yscale("symlog", linthresh=1e-2)
    ax.set_title("built-in materials, default parameters, spectrum model")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "brdf.png"), dpi=100)
    print(f"brdf_plot: wrote {os.path.join(outdir, 'brdf.png')} and brdf.csv ({len(ys)} materials)")


if __name__ == "__main__":
    main()
