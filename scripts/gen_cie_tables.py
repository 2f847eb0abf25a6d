#!/usr/bin/python3
"""Generates lib/color/cie_tables.c from Debian's colord-data CIE tables and computes the spectral primary
basis used for RGB -> spectrum (three smooth reflectances in [0,1] that sum to 1 at every wavelength and
whose sRGB colours under D65 are the primaries). Run: python3 scripts/gen_cie_tables.py > lib/color/cie_tables.c
Needs colord-data, python3-numpy and python3-scipy (development time only; the output is committed)."""
import sys
import numpy as np
from scipy.optimize import minimize

COLORD = "/usr/share/colord"


def read_cd(path):
    start = end = None
    sets = []
    data = False
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "SPECTRAL_START_NM":
            start = float(f[1])
        elif f[0] == "SPECTRAL_END_NM":
            end = float(f[1])
        elif f[0] == "BEGIN_DATA":
            data = True
        elif f[0] == "END_DATA":
            data = False
        elif data:
            sets.append([float(x) for x in f])
    n = len(sets[0])
    nm = np.linspace(start, end, n)
    return nm, [np.array(s) for s in sets]


# Sprague (1880) quintic interpolation, the method CIE 15 recommends for 5 nm -> 1 nm.
SPRAGUE = np.array([[0, 0, 24, 0, 0, 0], [2, -16, 0, 16, -2, 0], [-1, 16, -30, 16, -1, 0],
                    [-9, 39, -70, 66, -33, 7], [13, -64, 126, -124, 61, -12], [-5, 25, -50, 50, -25, 5]]) / 24.0
SPRAGUE_END0 = np.array([884, -1960, 3033, -2648, 1080, -180]) / 209.0
SPRAGUE_END1 = np.array([508, -540, 488, -367, 144, -24]) / 209.0


def interp_1nm(x, y, xq):
    """Values at xq from a table on a uniform grid x: Sprague for 5 nm tables, exact for 1 nm tables."""
    step = x[1] - x[0]
    if abs(step - 1.0) < 1e-9:
        return np.interp(xq, x, y)
    y = np.asarray(y, float)
    pad = np.concatenate([[SPRAGUE_END0 @ y[:6], SPRAGUE_END1 @ y[:6]], y,
                          [SPRAGUE_END1 @ y[-6:][::-1], SPRAGUE_END0 @ y[-6:][::-1]]])
    out = []
    for q in xq:
        i = min(int((q - x[0]) // step), len(x) - 2)
        t = (q - x[i]) / step
        c = SPRAGUE @ pad[i:i + 6]
        out.append(sum(c[k] * t ** k for k in range(6)))
    return np.array(out)


NM = np.arange(380, 781)
cmf_nm, (xb, yb, zb) = read_cd(f"{COLORD}/cmf/CIE1931-2deg-XYZ.cmf")
cmf = np.stack([interp_1nm(cmf_nm, c, NM) for c in (xb, yb, zb)], axis=1)
d65_nm, (d65,) = read_cd(f"{COLORD}/illuminant/CIE-D65.sp")
a_nm, (ia,) = read_cd(f"{COLORD}/illuminant/CIE-A.sp")
D65 = interp_1nm(d65_nm, d65, NM)
A = interp_1nm(a_nm, ia, NM)

XYZ2RGB = np.array([[3.2404542, -1.5371385, -0.4985314],
                    [-0.9692660, 1.8760108, 0.0415560],
                    [0.0556434, -0.2040259, 1.0572252]])

# basis on a 5 nm grid, linearly interpolated to 1 nm (the run-time representation)
G = np.arange(380, 781, 5)
ng = len(G)
W = np.zeros((len(NM), ng))  # 1 nm <- 5 nm linear interpolation weights
for i, x in enumerate(NM):
    k = min(int((x - 380) // 5), ng - 2)
    t = (x - G[k]) / 5.0
    W[i, k] += 1 - t
    W[i, k + 1] += t
kD = (D65 * cmf[:, 1]).sum()
proj = XYZ2RGB @ ((cmf * D65[:, None]).T / kD) @ W  # 3 x ng: rgb of a 5 nm reflectance under D65


# Unknowns: the red and green basis (blue = 1 - red - green keeps the sum at 1 exactly).
ONE = np.ones(ng)


def full(x):
    r, g = x[:ng], x[ng:]
    return np.stack([r, g, ONE - r - g])


def smooth(x):
    d = np.diff(full(x), 2, axis=1)
    return (d * d).sum()


def smooth_grad(x):
    d = np.diff(full(x), 2, axis=1)
    g = np.zeros((3, ng))
    g[:, :-2] += 2 * d
    g[:, 1:-1] -= 4 * d
    g[:, 2:] += 2 * d
    return np.concatenate([g[0] - g[2], g[1] - g[2]])


E3 = np.eye(3)
JP = np.zeros((6, 2 * ng))
for r in range(3):
    JP[r, :ng] = proj[r]
    JP[3 + r, ng:] = proj[r]
cons = [
    {"type": "eq", "fun": lambda x: np.concatenate([proj @ x[:ng] - E3[0], proj @ x[ng:] - E3[1]]),
     "jac": lambda x: JP},
    {"type": "ineq", "fun": lambda x: 1.0 - x[:ng] - x[ng:],
     "jac": lambda x: -np.hstack([np.eye(ng), np.eye(ng)])},
]
x0 = np.full(2 * ng, 1.0 / 3.0)
res = minimize(smooth, x0, jac=smooth_grad, constraints=cons, bounds=[(0.0, 1.0)] * (2 * ng),
               method="SLSQP", options={"maxiter": 3000, "ftol": 1e-15})
if not res.success:
    sys.exit("basis optimisation failed: " + res.message)
B = np.clip(full(res.x), 0.0, 1.0)
err = np.abs(proj @ B.T - np.eye(3)).max()
sys.stderr.write(f"basis: smoothness {res.fun:.3e}, projection error {err:.2e}, range [{B.min():.4f}, {B.max():.4f}]\n")


def flt(v):
    t = "{:.9g}".format(0.0 if abs(v) < 1e-12 else v)
    if "." not in t and "e" not in t:
        t += ".0"
    return t + "f"


def pack(tokens, limit=120):
    """The tokens, each followed by a comma, on lines of at most limit columns indented by four spaces."""
    out, cur = [], ""
    for tok in (t + "," for t in tokens):
        if cur and 4 + len(cur) + 1 + len(tok) > limit:
            out.append("    " + cur)
            cur = ""
        cur = cur + " " + tok if cur else tok
    if cur:
        out.append("    " + cur)
    return out


def arr(name, vals):
    return "\n".join([f"const float {name}[{len(vals)}] = {{"] + pack(flt(v) for v in vals) + ["};"])


print("/* cie_tables.c - generated by scripts/gen_cie_tables.py from Debian's colord-data; do not edit.")
print(" * CIE 1931 2-degree colour matching functions and the D65 and A illuminants (relative, as in the")
print(" * CIE tables), interpolated to 1 nm over 380..780 nm (Sprague, as CIE 15 recommends), and the spectral primary basis")
print(" * on a 5 nm grid (380..780 nm). */")
print('#include "cie_tables.h"\n')
print(arr("gcie_xbar", cmf[:, 0]))
print(arr("gcie_ybar", cmf[:, 1]))
print(arr("gcie_zbar", cmf[:, 2]))
print(arr("gcie_d65", D65))
print(arr("gcie_a", A))
print(arr("gcie_basis_r", B[0]))
print(arr("gcie_basis_g", B[1]))
print(arr("gcie_basis_b", B[2]))
