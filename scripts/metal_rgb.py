#!/usr/bin/env python3
"""Projects measured complex refractive indices n(lambda) + i k(lambda) of metals to linear sRGB
and writes engine/materials/metal_table.h, the named metals of the conductor material.

Input: scripts/metal_ior/<Name>.txt, one file per metal: '#' comment lines (the source of the
measurement), a '# unit: nm' or '# unit: um' line, then rows 'wavelength n k'.

Projection (the one Mitsuba 0.6 and pbrt-v3 used in their RGB modes, plus a white balance):
  1. Each spectrum s(lambda) (n and k separately) is interpolated linearly between samples and
     held constant past the ends of its table.
  2. It is treated like a reflectance under the equal-energy illuminant E:
        X = sum s(l) xbar(l) / sum ybar(l),  Y, Z alike,  l = 360..830 nm in 1 nm steps,
     with the CIE 1931 2-degree colour matching functions in the analytic multi-lobe fit of
     Wyman, Sloan & Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
     Functions", JCGT 2(2), sec. 2.1 (a formula, so no table is needed).
  3. XYZ -> linear sRGB (Rec.709 primaries, D65 white) with the matrix of IEC 61966-2-1.
  4. Each channel is divided by the same projection of the constant spectrum 1 (E's colour in
     sRGB, about (1.20, 0.95, 0.91)): a von Kries scaling in linear sRGB that maps E to the sRGB
     white. So a wavelength-independent n or k stays grey, as in a renderer whose white is
     (1, 1, 1). This plays the role a D65 illuminant would, without tabulating D65.
RGB eta and k are then used by the exact conductor Fresnel per channel. That is an
approximation (the Fresnel of the projected constants is not the projection of the spectral
Fresnel); the script prints both normal-incidence reflectances so the difference can be seen.

Python 3 standard library only. Run from anywhere: python3 scripts/metal_rgb.py
"""

import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DATA = ROOT / "scripts" / "metal_ior"
OUTPUT = ROOT / "engine" / "materials" / "metal_table.h"

# Named metals in the order of the generated table, and whether pbrt-v4 has them as named
# spectra "metal-<name>-eta" / "metal-<name>-k" (pbrt-v4 file format, "Named Spectra").
METALS = [
    ("Ag", "silver", True),
    ("Al", "aluminium", True),
    ("Au", "gold", True),
    ("Cr", "chromium", False),
    ("Cu", "copper", True),
    ("CuZn", "brass", True),
    ("Fe", "iron", False),
    ("MgO", "magnesium oxide", True),
    ("Ni", "nickel", False),
    ("Pt", "platinum", False),
    ("Ti", "titanium", False),
    ("TiO2", "titanium dioxide", True),
    ("W", "tungsten", False),
]

LAMBDA_MIN, LAMBDA_MAX = 360, 830


def piecewise_gaussian(x, mu, sigma_below, sigma_above):
    """The asymmetric Gaussian lobe g(x; mu, s1, s2) of Wyman, Sloan & Shirley 2013, eq. 1."""
    t = (x - mu) / (sigma_below if x < mu else sigma_above)
    return math.exp(-0.5 * t * t)


def cie1931_xyz(wavelength):
    """CIE 1931 2-degree colour matching functions, multi-lobe fit (Wyman et al. 2013, eq. 2)."""
    x = (1.056 * piecewise_gaussian(wavelength, 599.8, 37.9, 31.0)
         + 0.362 * piecewise_gaussian(wavelength, 442.0, 16.0, 26.7)
         - 0.065 * piecewise_gaussian(wavelength, 501.1, 20.4, 26.2))
    y = (0.821 * piecewise_gaussian(wavelength, 568.8, 46.9, 40.5)
         + 0.286 * piecewise_gaussian(wavelength, 530.9, 16.3, 31.1))
    z = (1.217 * piecewise_gaussian(wavelength, 437.0, 11.8, 36.0)
         + 0.681 * piecewise_gaussian(wavelength, 459.0, 26.0, 13.8))
    return x, y, z


# XYZ -> linear sRGB, IEC 61966-2-1:1999 (Rec. ITU-R BT.709 primaries, D65 white).
XYZ_TO_SRGB = [
    [3.2406, -1.5372, -0.4986],
    [-0.9689, 1.8758, 0.0415],
    [0.0557, -0.2040, 1.0570],
]

WAVELENGTHS = list(range(LAMBDA_MIN, LAMBDA_MAX + 1))
CMF = [cie1931_xyz(l) for l in WAVELENGTHS]
Y_INTEGRAL = sum(c[1] for c in CMF)


def read_table(path):
    """Rows (wavelength in nm, n, k) of one data file, sorted by wavelength."""
    scale = None
    rows = []
    for line in path.read_text().splitlines():
        line = line.strip()
        if line.startswith("# unit:"):
            unit = line.split(":", 1)[1].strip()
            scale = {"nm": 1.0, "um": 1000.0}[unit]
        elif line and not line.startswith("#"):
            wavelength, n, k = (float(v) for v in line.split())
            rows.append((wavelength, n, k))
    if scale is None:
        sys.exit(f"{path}: no '# unit: nm|um' line")
    rows = sorted((w * scale, n, k) for w, n, k in rows)
    if any(a[0] >= b[0] for a, b in zip(rows, rows[1:])):
        sys.exit(f"{path}: wavelengths are not increasing")
    return rows


def interpolate(rows, column, wavelength):
    """Linear interpolation of one column; the end values are held past the table's range."""
    if wavelength <= rows[0][0]:
        return rows[0][column]
    if wavelength >= rows[-1][0]:
        return rows[-1][column]
    for a, b in zip(rows, rows[1:]):
        if a[0] <= wavelength <= b[0]:
            t = (wavelength - a[0]) / (b[0] - a[0])
            return a[column] + t * (b[column] - a[column])
    raise AssertionError("unreachable")


def xyz_to_srgb(xyz):
    return [sum(m * c for m, c in zip(row, xyz)) for row in XYZ_TO_SRGB]


def project_unbalanced(values):
    """Steps 2 and 3: sampled spectrum (one value per WAVELENGTHS entry) -> linear sRGB."""
    xyz = [sum(v * c[i] for v, c in zip(values, CMF)) / Y_INTEGRAL for i in range(3)]
    return xyz_to_srgb(xyz)


ILLUMINANT_E_RGB = project_unbalanced([1.0] * len(WAVELENGTHS))


def project(values):
    """The whole projection, white balance included (step 4)."""
    rgb = project_unbalanced(values)
    return [c / w for c, w in zip(rgb, ILLUMINANT_E_RGB)]


def conductor_f0(n, k):
    """Normal-incidence reflectance of a conductor seen from vacuum: |(N - 1) / (N + 1)|^2 with
    N = n + i k, i.e. ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) (Born & Wolf, sec. 14.2)."""
    return ((n - 1) ** 2 + k * k) / ((n + 1) ** 2 + k * k)


def metal_rgb(name):
    rows = read_table(DATA / f"{name}.txt")
    n = [interpolate(rows, 1, l) for l in WAVELENGTHS]
    k = [interpolate(rows, 2, l) for l in WAVELENGTHS]
    eta_rgb = project(n)
    # A non-negative spectrum can still project slightly outside the sRGB gamut (a transparent
    # oxide's k = 0 comes out as +-1e-4); an extinction coefficient below zero would mean gain.
    k_rgb = [max(0.0, c) for c in project(k)]
    assert all(c > 0 for c in eta_rgb), (name, eta_rgb)
    f0_rgb = [conductor_f0(a, b) for a, b in zip(eta_rgb, k_rgb)]
    f0_spectral = project([conductor_f0(a, b) for a, b in zip(n, k)])
    return eta_rgb, k_rgb, f0_rgb, f0_spectral


def check_close(label, actual, expected, tolerance):
    for a, e in zip(actual, expected):
        assert abs(a - e) <= tolerance, f"{label}: {actual} is not within {tolerance} of {expected}"


def self_check(results):
    # The CMF fit integrates to about the tabulated CIE 1931 ybar (106.857 at 1 nm steps,
    # 360-830 nm); Wyman et al. report errors of a few percent at most.
    assert abs(Y_INTEGRAL - 106.857) < 0.02 * 106.857, Y_INTEGRAL
    # A constant spectrum projects to exactly that grey (the white balance of step 4).
    grey = project([1.5] * len(WAVELENGTHS))
    check_close("constant spectrum", grey, [1.5] * 3, 1e-9)
    # Well-known normal-incidence colours of polished metals, linear sRGB (e.g. Hoffman,
    # "Physics and Math of Shading", SIGGRAPH 2015 course, and the same values in Unity's metal
    # reflectance node): gold (1.000, 0.766, 0.336), silver (0.972, 0.960, 0.915), aluminium
    # (0.913, 0.921, 0.925), copper (0.955, 0.637, 0.538). Different measurements and
    # projections scatter by a few hundredths, hence the tolerances.
    f0 = {name: r[2] for name, r in results.items()}
    check_close("Au F0", f0["Au"], [1.0, 0.766, 0.336], 0.06)
    check_close("Ag F0", f0["Ag"], [0.972, 0.960, 0.915], 0.05)
    check_close("Al F0", f0["Al"], [0.913, 0.921, 0.925], 0.03)
    check_close("Cu F0", f0["Cu"], [0.955, 0.637, 0.538], 0.08)
    for name, (_, _, f0_rgb, f0_spectral) in results.items():
        assert all(0 <= c <= 1 for c in f0_rgb), (name, f0_rgb)
        # The Fresnel of projected constants stays close to the projected spectral Fresnel.
        check_close(f"{name} F0 (RGB constants vs spectral)", f0_rgb, f0_spectral, 0.06)


def format_color(values):
    return "Color(" + ", ".join(f"{v:.6f}f" for v in values) + ")"


def write_header(results):
    lines = [
        "// generated by scripts/metal_rgb.py; do not edit",
        "// Complex refractive indices eta + i k of named metals in linear sRGB (Rec.709 primaries),",
        "// projected from measured spectra (scripts/metal_ior/, one file per metal naming its",
        "// source): each spectrum is weighted by the CIE 1931 colour matching functions (analytic",
        "// fit of Wyman, Sloan & Shirley 2013) under the equal-energy illuminant, taken to linear",
        "// sRGB (IEC 61966-2-1) and white-balanced so that a constant spectrum stays grey.",
        "// F0 is the normal-incidence reflectance of these constants, for reference.",
        "#pragma once",
        "#include <array>",
        "#include <string_view>",
        "#include <photon/vec.h>",
        "",
        "namespace photon {",
        "",
        "struct MetalIor {",
        "    std::string_view name;      // chemical symbol, the scene file's \"metal\" value",
        "    bool pbrtNamed;             // pbrt-v4 names its spectra metal-<name>-eta and metal-<name>-k",
        "    Color eta;",
        "    Color k;",
        "};",
        "",
        f"inline constexpr std::array<MetalIor, {len(results)}> kMetalIors = {{{{",
    ]
    for (name, common, pbrt), (eta, k, f0, _) in zip(METALS, results.values()):
        f0_text = ", ".join(f"{v:.3f}" for v in f0)
        lines.append(f"    // {common}: F0 = ({f0_text})")
        pbrt_named = "true" if pbrt else "false"
        lines.append(f"    {{\"{name}\", {pbrt_named}, {format_color(eta)}, {format_color(k)}}},")
    lines += ["}};", "", "}  // namespace photon", ""]
    OUTPUT.write_text("\n".join(lines))


def main():
    results = {name: metal_rgb(name) for name, _, _ in METALS}
    print(f"{'metal':6} {'eta (r, g, b)':26} {'k (r, g, b)':26} {'F0 of RGB eta/k':22} F0 spectral")
    for name, (eta, k, f0, f0_spectral) in results.items():
        fmt = lambda v: "(" + ", ".join(f"{c:.3f}" for c in v) + ")"
        print(f"{name:6} {fmt(eta):26} {fmt(k):26} {fmt(f0):22} {fmt(f0_spectral)}")
    self_check(results)
    write_header(results)
    print(f"self-check passed; wrote {OUTPUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
