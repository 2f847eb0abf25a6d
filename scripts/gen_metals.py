#!/usr/bin/env python3
"""Writes lib/kit/metal_table.c, the measured optical constants (n, k) of the metals and compounds that
`conductor { metal NAME }` knows, from the refractiveindex.info database (public domain, CC0 1.0:
https://github.com/polyanskiy/refractiveindex.info-database).

usage: scripts/gen_metals.py DATABASE_DIR OUT.c
  DATABASE_DIR is the database's `database/data` folder. Each entry below names one tabulated-nk file; its rows
  (wavelength in um, n, k) are interpolated linearly in wavelength onto 360..830 nm every 5 nm (held constant
  beyond the measured range, which the table records). Only data is taken from the database."""
import re
import sys

GRID_MIN, GRID_STEP, GRID_N = 360, 5, 95

# name, what it is, file under database/data (tabulated nk)
METALS = [  # sorted by name below, as strcmp orders them
    ("Ag", "silver", "main/Ag/nk/Johnson.yml"),
    ("Al", "aluminium", "main/Al/nk/McPeak.yml"),
    ("Au", "gold", "main/Au/nk/Johnson.yml"),
    ("Be", "beryllium", "main/Be/nk/Rakic-LD.yml"),
    ("Bi", "bismuth", "main/Bi/nk/Werner.yml"),
    ("Ca", "calcium", "main/Ca/nk/Mathewson.yml"),
    ("Co", "cobalt", "main/Co/nk/Johnson.yml"),
    ("Cr", "chromium", "main/Cr/nk/Johnson.yml"),
    ("Cu", "copper", "main/Cu/nk/Johnson.yml"),
    ("CuZn", "brass, 70% Cu 30% Zn", "other/alloys/Cu-Zn/nk/Querry-Cu70Zn30.yml"),
    ("CuZn10", "brass (gilding metal), 90% Cu 10% Zn", "other/alloys/Cu-Zn/nk/Querry-Cu90Zn10.yml"),
    ("Fe", "iron", "main/Fe/nk/Johnson.yml"),
    ("Fe3O4", "magnetite", "main/Fe3O4/nk/Querry.yml"),
    ("Hg", "mercury", "main/Hg/nk/Inagaki.yml"),
    ("In", "indium", "main/In/nk/Mathewson-298K.yml"),
    ("Ir", "iridium", "main/Ir/nk/Schmitt-MS.yml"),
    ("K", "potassium", "main/K/nk/Smith.yml"),
    ("Li", "lithium", "main/Li/nk/Mathewson-298K.yml"),
    ("Mg", "magnesium", "main/Mg/nk/Palm.yml"),
    ("Mn", "manganese", "main/Mn/nk/Johnson.yml"),
    ("Mo", "molybdenum", "main/Mo/nk/Querry.yml"),
    ("Na", "sodium", "main/Na/nk/Inagaki.yml"),
    ("Nb", "niobium", "main/Nb/nk/Weaver.yml"),
    ("Ni", "nickel", "main/Ni/nk/Johnson.yml"),
    ("Pb", "lead", "main/Pb/nk/Mathewson-298K.yml"),
    ("Pd", "palladium", "main/Pd/nk/Johnson.yml"),
    ("Pt", "platinum", "main/Pt/nk/Tselin.yml"),
    ("Rh", "rhodium", "main/Rh/nk/Weaver.yml"),
    ("Si", "silicon, crystalline", "main/Si/nk/Schinke.yml"),
    ("Ta", "tantalum", "main/Ta/nk/Werner.yml"),
    ("Ti", "titanium", "main/Ti/nk/Johnson.yml"),
    ("TiN", "titanium nitride, sputtered film", "main/TiN/nk/Beliaev-sputtering.yml"),
    ("V", "vanadium", "main/V/nk/Johnson.yml"),
    ("W", "tungsten", "main/W/nk/Weaver.yml"),
    ("Zn", "zinc", "main/Zn/nk/Querry.yml"),
    ("Zr", "zirconium", "main/Zr/nk/Querry.yml"),
    ("steel", "stainless steel, austenitic (about SS316)",
     "other/alloys/stainless steel/nk/Karlsson-austenitic.yml"),
]


def read_nk(path):
    text = open(path, encoding="utf-8").read()
    m = re.search(r"type: tabulated nk\s*\n\s*data: \|\n((?:[ \t]+\S+[ \t]+\S+[ \t]+\S+[ \t]*\n?)+)", text)
    if not m:
        sys.exit(f"gen_metals: {path}: no tabulated nk data")
    rows = sorted(tuple(float(x) for x in line.split()) for line in m.group(1).strip().splitlines())
    ref = re.search(r"REFERENCES: \|\n((?:    .*\n)+)", text)
    first = re.sub(r"<[^>]*>", "", ref.group(1).strip().splitlines()[0]) if ref else "?"
    first = re.sub(r"^\d+\)\s*", "", first.strip())
    names = re.match(r"^(.*?\w\w\w)\.(\s|$)", first)
    names = re.split(r",\s*| and ", names.group(1) if names else first)
    authors = names[0] + (" et al." if len(names) > 1 else "")
    year = re.search(r"\((\d{4})\)", ref.group(1)) if ref else None
    return [(r[0] * 1000.0, r[1], r[2]) for r in rows], authors, year.group(1) if year else "?"


def interp(rows, nm, col):
    if nm <= rows[0][0]:
        return rows[0][col]
    if nm >= rows[-1][0]:
        return rows[-1][col]
    for a, b in zip(rows, rows[1:]):
        if a[0] <= nm <= b[0]:
            t = (nm - a[0]) / (b[0] - a[0]) if b[0] > a[0] else 0.0
            return a[col] + t * (b[col] - a[col])
    raise AssertionError


def c_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    root, out = sys.argv[1], sys.argv[2]
    lines = [
        "/* metal_table.c - measured optical constants of metals and compounds (lib/kit/metal_table.h), written by",
        " * scripts/gen_metals.py from the refractiveindex.info database (public domain, CC0 1.0); regenerate, do not",
        " * edit. n and k every 5 nm from 360 to 830 nm, interpolated linearly between the published rows and held",
        " * constant beyond the measured range (min_nm..max_nm). */",
        '#include "metal_table.h"',
        "",
        "const GMetalData gmetal_data[] = {",
    ]
    for name, what, rel in sorted(METALS):
        rows, authors, year = read_nk(f"{root}/{rel}")
        lo, hi = rows[0][0], rows[-1][0]
        if lo > 380.0 or hi < 780.0:
            sys.exit(f"gen_metals: {rel}: measured {lo:.0f}..{hi:.0f} nm does not cover 380..780 nm")
        nm = [GRID_MIN + i * GRID_STEP for i in range(GRID_N)]
        source = f"refractiveindex.info: {rel.split('/nk/')[0].split('/', 1)[1]}, {authors} ({year})"
        lines.append(f"    {{{c_string(name)}, {c_string(what)},")
        lines.append(f"     {c_string(source)},")
        lines.append(f"     {lo:.1f}, {hi:.1f},")
        for col, label in ((1, "eta"), (2, "k")):
            vals = [f"{interp(rows, x, col):.6g}" for x in nm]
            lines.append("     {" + ", ".join(vals[:10]) + ",")
            for i in range(10, GRID_N, 10):
                tail = "}," if i + 10 >= GRID_N else ","
                lines.append("      " + ", ".join(vals[i:i + 10]) + tail)
        lines.append("    },")
    lines.append("};")
    lines.append("")
    lines.append("const int gmetal_data_count = (int)(sizeof gmetal_data / sizeof gmetal_data[0]);")
    with open(out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
