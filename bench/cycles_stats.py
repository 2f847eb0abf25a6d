#!/usr/bin/env python3
"""cycles_stats.py - the numbers bench/cycles.sh prints, from EXR images (read with `oiiotool --dumpdata`).

  cycles_stats.py rmse IMAGE.exr REFERENCE.exr [SCENE] -> "whole W patches P NAME V ..." (each patch's RMSE)
  cycles_stats.py means IMAGE.exr [SCENE]               -> the patches' mean luminance: "NAME M ..."
  cycles_stats.py summary RECORDS                       -> bench/cycles.sh's table of ratios (medians, min-max)

SCENE is cornell (the default), glossy or probe: which patches. RECORDS has a line a render pair: "SCENE ROUND
THREADS CONFIG N WALL CPU WALL_Q CPU_Q WHOLE PATCHES": the seconds at N samples per pixel and at N/4 (the marginal
cost of a sample is their difference over 3N/4, which leaves out each program's fixed costs), and the RMSE at N. A
configuration's time to reach an RMSE e is then cost per sample times N * RMSE^2 / e^2; the ratios of these are the
times to equal RMSE.

RMSE is over pixels and the three channels (R, G, B: the first three). "whole" leaves out the pixels that see a lamp
or the sun (where either image's luminance is above 2: gtrace's camera rays see the lamp, Cycles' area lights are
not seen) and their eight neighbours (which see part of it), "patches" is over the scene's patches together, each a
box of fractions of the image (x0, y0, x1, y1; y down): in the Cornell box the floor in front of the blocks, the back
wall right of the tall block above the short one, the red and the green wall; in the glossy box the floor in front of
the spheres, the back wall between them, the walls and the gold sphere's lit side; under the probe the ground in
front, the red sphere, the blue box's front and the sphere's shadow."""
import math
import re
import subprocess
import sys

PATCHES = {
    "cornell": {
        "floor": (0.35, 0.86, 0.65, 0.95),
        "back": (0.55, 0.25, 0.75, 0.50),
        "left": (0.10, 0.35, 0.17, 0.65),
        "right": (0.83, 0.35, 0.90, 0.65),
    },
    "glossy": {
        "floor": (0.30, 0.90, 0.55, 0.97),
        "back": (0.40, 0.25, 0.60, 0.45),
        "left": (0.10, 0.35, 0.17, 0.65),
        "right": (0.83, 0.35, 0.90, 0.65),
        "gold": (0.25, 0.62, 0.36, 0.70),
    },
    "probe": {
        "ground": (0.30, 0.82, 0.70, 0.95),
        "sphere": (0.20, 0.42, 0.34, 0.56),
        "box": (0.62, 0.45, 0.76, 0.60),
        "shadow": (0.22, 0.67, 0.45, 0.74),
    },
}
PIXEL = re.compile(r"^\s*Pixel \((\d+), (\d+)\):\s+(\S+)\s+(\S+)\s+(\S+)")


def read(path):
    """The image as (width, height, {(x, y): (r, g, b)})."""
    text = subprocess.run(["oiiotool", "--dumpdata", path], check=True, capture_output=True, text=True).stdout
    px = {}
    for line in text.splitlines():
        m = PIXEL.match(line)
        if m:
            px[(int(m.group(1)), int(m.group(2)))] = (float(m.group(3)), float(m.group(4)), float(m.group(5)))
    w = 1 + max(x for x, _ in px)
    h = 1 + max(y for _, y in px)
    if len(px) != w * h:
        raise SystemExit("%s: %d pixels read, not %d x %d" % (path, len(px), w, h))
    return w, h, px


def luminance(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def box(w, h, scene, name):
    x0, y0, x1, y1 = PATCHES[scene][name]
    return [(x, y) for y in range(int(y0 * h), int(y1 * h)) for x in range(int(x0 * w), int(x1 * w))]


def sq_err(a, b, keys):
    return sum((a[k][c] - b[k][c]) ** 2 for k in keys for c in range(3)), 3 * len(keys)


def median(v):
    v = sorted(v)
    n = len(v)
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def summary(path):
    rec = {}
    for line in open(path):
        f = line.split()
        if len(f) != 11:
            continue
        sc, r, t, cfg, n = f[0], int(f[1]), int(f[2]), f[3], int(f[4])
        wall, cpu, wall_q, cpu_q, whole, patches = (float(v) for v in f[5:])
        per = 0.75 * n
        rec[(sc, r, t, cfg)] = {"wall": (wall - wall_q) / per, "cpu": (cpu - cpu_q) / per,
                                "whole": n * whole * whole, "patches": n * patches * patches}
    scenes = sorted({k[0] for k in rec}, key=list(PATCHES).index)
    rounds = sorted({k[1] for k in rec})
    threads = sorted({k[2] for k in rec})
    rows = [("gtrace sobol / Cycles", "sobol", "cycles"), ("gtrace independent / Cycles", "independent", "cycles"),
            ("gtrace sobol / independent", "sobol", "independent")]
    print("%-8s %-28s %3s %-5s %18s %18s %18s %18s" % ("scene", "time to equal RMSE", "thr", "time", "whole image",
                                                       "patches", "cost per sample", "variance per spp"))
    for sc, (name, a, b), t, clock in ((sc, row, t, clock) for sc in scenes for row in rows for t in threads
                                       for clock in ("wall", "cpu")):
        if not any((sc, r, t, a) in rec and (sc, r, t, b) in rec for r in rounds):
            continue
        cols = []
        for what in ("whole", "patches", "cost", "var"):
            v = []
            for r in rounds:
                x, y = rec.get((sc, r, t, a)), rec.get((sc, r, t, b))
                if not x or not y or x[clock] <= 0 or y[clock] <= 0:
                    continue
                if what == "cost":
                    v.append(x[clock] / y[clock])
                elif what == "var":
                    v.append(x["patches"] / y["patches"])
                else:
                    v.append(x[clock] * x[what] / (y[clock] * y[what]))
            cols.append("%.2f (%.2f-%.2f)" % (median(v), min(v), max(v)) if v else "-")
        print("%-8s %-28s %3d %-5s %18s %18s %18s %18s" % (sc, name, t, clock, *cols))
    print("medians (min-max) of the per-round ratios over %d rounds; variance per spp: the patches'" % len(rounds))


def main():
    scene = sys.argv[-1] if len(sys.argv) > 2 and sys.argv[-1] in PATCHES else None
    argv = sys.argv[:-1] if scene else sys.argv
    scene = scene or "cornell"
    if len(argv) == 4 and argv[1] == "rmse":
        w, h, img = read(argv[2])
        w2, h2, ref = read(argv[3])
        if (w, h) != (w2, h2):
            raise SystemExit("the images differ in size")
        lamp = {k for k in img if luminance(img[k]) > 2.0 or luminance(ref[k]) > 2.0}
        near = {(x + dx, y + dy) for x, y in lamp for dx in (-1, 0, 1) for dy in (-1, 0, 1)}
        s, n = sq_err(img, ref, [k for k in img if k not in near])
        out = ["whole %.6g" % math.sqrt(s / n)]
        parts = [sq_err(img, ref, box(w, h, scene, name)) for name in PATCHES[scene]]
        out.append("patches %.6g" % math.sqrt(sum(p[0] for p in parts) / sum(p[1] for p in parts)))
        out += ["%s %.6g" % (name, math.sqrt(p[0] / p[1])) for name, p in zip(PATCHES[scene], parts)]
        print(" ".join(out))
    elif len(argv) == 3 and argv[1] == "means":
        w, h, img = read(argv[2])
        out = []
        for name in PATCHES[scene]:
            keys = box(w, h, scene, name)
            out.append("%s %.6g" % (name, sum(luminance(img[k]) for k in keys) / len(keys)))
        print(" ".join(out))
    elif len(argv) == 3 and argv[1] == "summary":
        summary(argv[2])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()
