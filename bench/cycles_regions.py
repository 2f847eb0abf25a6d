#!/usr/bin/env python3
"""cycles_regions.py - where the noise of bench/cycles.sh's Cornell box renders lies, region by region.

  cycles_regions.py DIRECT.exr GT.exr GT_REF.exr CY.exr CY_REF.exr [COST_RATIO]

DIRECT.exr is a long render of the direct light alone (gtrace `--depth 0`), GT.exr and CY.exr are renders of gtrace
and Cycles at the same samples per pixel, GT_REF.exr and CY_REF.exr each renderer's own long reference (another
random sequence). The pixels are split into regions, each pixel in the first that takes it:
  lamp         the lamp's pixels (the gtrace reference's luminance above 2; left out of "whole", as cycles_stats.py)
  lamp border  within 2 pixels of the lamp (gtrace's camera rays see the lamp's edge, Cycles' do not)
  edges        a geometric edge or corner: the Cycles reference's luminance differs from an 8-neighbour's by more
               than a quarter of the larger (where the pixel filter and the antialiasing decide the noise)
  ceiling      the ceiling (its rays meet y = 2 before the side walls; lit only by the bounces)
  shadowed     the direct light is under a tenth of the light (indirect light alone, mostly)
  lit          the rest (floor, walls and blocks in the direct light)
For each: its pixels, its share of each renderer's squared error over the image (lamp left out), and gtrace's
variance per sample over Cycles' (the ratio of the mean squared errors at equal samples per pixel); with COST_RATIO
(gtrace's cost per sample over Cycles') also the time to equal RMSE on that region (their product)."""
import math
import sys

from cycles_stats import luminance, read

TAN_HALF_FOV = math.tan(math.radians(19.0))  # the camera's vertical field of view is 38 degrees


def on_ceiling(x, y, w, h):
    """Whether the camera ray through pixel (x, y) meets the ceiling (y = 2) before the side walls or the back."""
    a = ((x + 0.5) / w - 0.5) * 2.0 * TAN_HALF_FOV
    b = (0.5 - (y + 0.5) / h) * 2.0 * TAN_HALF_FOV
    return b > 1.0 / 4.9 and abs(a / b) < 1.0  # from <0, 1, 3.9>: the back wall at z = -1 is 4.9 away


def regions(direct, gref, cref, w, h):
    lamp = {k for k in gref if luminance(gref[k]) > 2.0}
    border = {(x + dx, y + dy) for x, y in lamp for dx in range(-2, 3) for dy in range(-2, 3)} - lamp
    out = {}
    for y in range(h):
        for x in range(w):
            k = (x, y)
            lc = luminance(cref[k])
            nb = [luminance(cref[(x + dx, y + dy)]) for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                  if (dx or dy) and 0 <= x + dx < w and 0 <= y + dy < h]
            if k in lamp:
                out[k] = "lamp"
            elif k in border:
                out[k] = "lamp border"
            elif any(abs(lc - v) > 0.25 * max(lc, v) for v in nb):
                out[k] = "edges"
            elif on_ceiling(x, y, w, h):
                out[k] = "ceiling"
            elif luminance(direct[k]) < 0.1 * lc:
                out[k] = "shadowed"
            else:
                out[k] = "lit"
    return out


def main():
    if len(sys.argv) not in (6, 7):
        raise SystemExit(__doc__)
    w, h, direct = read(sys.argv[1])
    _, _, g = read(sys.argv[2])
    _, _, gref = read(sys.argv[3])
    _, _, c = read(sys.argv[4])
    _, _, cref = read(sys.argv[5])
    cost = float(sys.argv[6]) if len(sys.argv) == 7 else None
    reg = regions(direct, gref, cref, w, h)
    names = ["lamp border", "edges", "ceiling", "shadowed", "lit"]
    sq = {n: [0.0, 0.0, 0] for n in names}
    for k, n in reg.items():
        if n == "lamp":
            continue
        sq[n][0] += sum((g[k][i] - gref[k][i]) ** 2 for i in range(3))
        sq[n][1] += sum((c[k][i] - cref[k][i]) ** 2 for i in range(3))
        sq[n][2] += 1
    tg = sum(v[0] for v in sq.values())
    tc = sum(v[1] for v in sq.values())
    head = "| region | pixels | share of gtrace's squared error | share of Cycles' | variance per sample, gtrace/Cycles"
    head += " |"
    print(head + (" time to equal RMSE |" if cost else ""))
    print("| --- " * (5 + (cost is not None)) + "|")
    for n in names + ["whole"]:
        eg, ec, m = (tg, tc, sum(v[2] for v in sq.values())) if n == "whole" else sq[n]
        if not m:
            continue
        var = eg / ec if ec > 0 else float("inf")
        row = "| %s | %d | %.3f | %.3f | %.2f |" % (n, m, eg / tg, ec / tc, var)
        print(row + (" %.2f |" % (var * cost) if cost else ""))


if __name__ == "__main__":
    main()
