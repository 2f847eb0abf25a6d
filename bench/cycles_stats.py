#!/usr/bin/env python3
"""cycles_stats.py - the numbers bench/cycles.sh prints, from EXR images (read with `oiiotool --dumpdata`).

  cycles_stats.py rmse IMAGE.exr REFERENCE.exr  -> "whole W patches P floor F back B left L right R"
  cycles_stats.py means IMAGE.exr               -> the patches' mean luminance: "floor F back B left L right R"
  cycles_stats.py summary RECORDS                -> bench/cycles.sh's table of ratios (medians, min-max over rounds)

RECORDS has a line a render pair: "ROUND THREADS CONFIG N WALL CPU WALL_Q CPU_Q WHOLE PATCHES": the seconds at N
samples per pixel and at N/4 (the marginal cost of a sample is their difference over 3N/4, which leaves out each
program's fixed costs), and the RMSE at N. A configuration's time to reach an RMSE e is then cost per sample times
N * RMSE^2 / e^2; the ratios of these are the times to equal RMSE.

RMSE is over pixels and the three channels (R, G, B: the first three). "whole" leaves out the pixels that see the
lamp (where either image's luminance is above 2: gtrace's camera rays see the lamp, Cycles' area lights are not
seen), "patches" is over the four patches together: the floor in front of the blocks, the back wall right of the tall
block above the short one, the red and the green wall, each a box of fractions of the image (x0, y0, x1, y1; y down)."""
import math
import re
import subprocess
import sys

PATCHES = {
    "floor": (0.35, 0.86, 0.65, 0.95),
    "back": (0.55, 0.25, 0.75, 0.50),
    "left": (0.10, 0.35, 0.17, 0.65),
    "right": (0.83, 0.35, 0.90, 0.65),
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


def box(w, h, name):
    x0, y0, x1, y1 = PATCHES[name]
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
        if len(f) != 10:
            continue
        r, t, cfg, n = int(f[0]), int(f[1]), f[2], int(f[3])
        wall, cpu, wall_q, cpu_q, whole, patches = (float(v) for v in f[4:])
        per = 0.75 * n
        rec[(r, t, cfg)] = {"wall": (wall - wall_q) / per, "cpu": (cpu - cpu_q) / per,
                            "whole": n * whole * whole, "patches": n * patches * patches}
    rounds = sorted({k[0] for k in rec})
    threads = sorted({k[1] for k in rec})
    rows = [("gtrace sobol / Cycles", "sobol", "cycles"), ("gtrace independent / Cycles", "independent", "cycles"),
            ("gtrace sobol / independent", "sobol", "independent")]
    print("%-28s %3s %-5s %18s %18s %18s %18s" % ("time to equal RMSE", "thr", "time", "whole image",
                                                  "patches", "cost per sample", "variance per spp"))
    for name, a, b in rows:
        for t in threads:
            for clock in ("wall", "cpu"):
                cols = []
                for what in ("whole", "patches", "cost", "var"):
                    v = []
                    for r in rounds:
                        x, y = rec.get((r, t, a)), rec.get((r, t, b))
                        if not x or not y or x[clock] <= 0 or y[clock] <= 0:
                            continue
                        if what == "cost":
                            v.append(x[clock] / y[clock])
                        elif what == "var":
                            v.append(x["patches"] / y["patches"])
                        else:
                            v.append(x[clock] * x[what] / (y[clock] * y[what]))
                    cols.append("%.2f (%.2f-%.2f)" % (median(v), min(v), max(v)) if v else "-")
                print("%-28s %3d %-5s %18s %18s %18s %18s" % (name, t, clock, *cols))
    print("medians (min-max) of the per-round ratios over %d rounds; variance per spp: the patches'" % len(rounds))


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "rmse":
        w, h, img = read(sys.argv[2])
        w2, h2, ref = read(sys.argv[3])
        if (w, h) != (w2, h2):
            raise SystemExit("the images differ in size")
        keep = [k for k in img if luminance(img[k]) <= 2.0 and luminance(ref[k]) <= 2.0]
        s, n = sq_err(img, ref, keep)
        out = ["whole %.6g" % math.sqrt(s / n)]
        parts = [sq_err(img, ref, box(w, h, name)) for name in PATCHES]
        out.append("patches %.6g" % math.sqrt(sum(p[0] for p in parts) / sum(p[1] for p in parts)))
        out += ["%s %.6g" % (name, math.sqrt(p[0] / p[1])) for name, p in zip(PATCHES, parts)]
        print(" ".join(out))
    elif len(sys.argv) == 3 and sys.argv[1] == "means":
        w, h, img = read(sys.argv[2])
        out = []
        for name in PATCHES:
            keys = box(w, h, name)
            out.append("%s %.6g" % (name, sum(luminance(img[k]) for k in keys) / len(keys)))
        print(" ".join(out))
    elif len(sys.argv) == 3 and sys.argv[1] == "summary":
        summary(sys.argv[2])
    else:
        raise SystemExit(__doc__)


main()
