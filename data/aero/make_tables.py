#!/usr/bin/env python3
"""make_aero_tables.py: writes the coefficient tables in data/aero/ from the formulas stated in
their headers (run from the repository root: python3 data/aero/make_tables.py).
Angle convention (include/gallop/aero.h): alpha = angle of the relative wind measured from the
section's reference direction d1, positive about the tangent; drag along the wind, lift = wind
turned +90 deg about the tangent; Den Hartog H = dC_L/dalpha + C_D < 0 is galloping-prone."""
import math

CONVENTION = [
    "convention: alpha_deg = angle of the relative wind measured from the section reference",
    "  direction d1, positive about the conductor tangent t (w = cos(a) d1 + sin(a) t x d1);",
    "  C_D along the relative wind, C_L along t x (wind direction), C_M about +t;",
    "  coefficients on the dynamic pressure 1/2 rho V^2 of the normal relative wind and the",
    "  reference diameter d (d^2 for C_M); Den Hartog H = dC_L/dalpha + C_D (per rad), < 0 gallops.",
]


def write(path, source, notes, rows):
    with open(path, "w") as f:
        for s in source:
            f.write("# source: %s\n" % s)
        for s in CONVENTION + notes:
            f.write("# %s\n" % s)
        f.write("alpha_deg,cd,cl,cm\n")
        for a, cd, cl, cm in rows:
            line = "%g,%.6f,%.6f,%.6f" % (a, cd, cl, cm)
            f.write(line.replace("-0.000000", "0.000000") + "\n")


# ---- bare conductor: circular cylinder, subcritical Reynolds number ----
write("data/aero/bare.csv",
      ["circular cylinder at subcritical Reynolds number (1e3 < Re < 2e5): C_D ~ 1.1-1.2, "
       "no mean lift or moment by symmetry (e.g. Roshko 1961; Achenbach 1968); C_D = 1.1 here"],
      ["axisymmetric section: the coefficients do not depend on alpha"],
      [(a, 1.1, 0.0, 0.0) for a in range(-180, 180, 30)])

# ---- square prism: Parkinson & Smith (1964) ----
A1, A3, A5, A7 = 2.69, 168.0, 6270.0, 59900.0
AB = 13.0  # deg: the polynomial is used up to here (its maximum is near 13 deg)


def cd_sq(a):  # a in rad; 90-degree periodic, even; 2.0 face-on, 1.5 corner-on
    return 1.75 + 0.25 * math.cos(4 * a)


def cfy(a):  # transverse force coefficient of Parkinson & Smith, on 1/2 rho U^2 h
    t = math.tan(a)
    return A1 * t - A3 * t ** 3 + A5 * t ** 5 - A7 * t ** 7


def cl_poly(a):  # C_Fy = -(C_L + C_D tan a) sec a  =>  C_L = -C_Fy cos a - C_D tan a
    return -cfy(a) * math.cos(a) - cd_sq(a) * math.tan(a)


def cl_sq(a):
    """C_L for a in [0, 45 deg]: the polynomial up to AB, then the cubic in a that matches its
    value and slope at AB and has C_L = C_L'' = 0 at 45 deg (odd about 45 deg)."""
    b = math.radians(AB)
    if a <= b:
        return cl_poly(a)
    e = math.pi / 4
    h = 1e-6
    v0 = cl_poly(b)
    s0 = (cl_poly(b + h) - cl_poly(b - h)) / (2 * h)
    # cubic p(x) = c1 x + c3 x^3 in x = a - e (odd about 45 deg: p(0) = p''(0) = 0)
    x0 = b - e
    # p(x0) = v0, p'(x0) = s0: c1 x0 + c3 x0^3 = v0, c1 + 3 c3 x0^2 = s0
    c3 = (v0 - s0 * x0) / (x0 ** 3 - 3 * x0 ** 3)
    c1 = s0 - 3 * c3 * x0 ** 2
    x = a - e
    return c1 * x + c3 * x ** 3


def cl_square(a):  # any a: 90-degree periodic, odd about 0 and about 45 deg
    q = math.pi / 2
    a = a - q * math.floor(a / q + 0.5)  # into [-45, 45) deg
    return cl_sq(a) if a >= 0 else -cl_sq(-a)


rows = []
for i in range(-360, 360):
    a = i * 0.5
    r = math.radians(a)
    rows.append((a, cd_sq(r), cl_square(r), 0.0))
write("data/aero/square_parkinson_smith.csv",
      ["Parkinson G.V. & Smith J.D. (1964) 'The square prism as an aeroelastic non-linear "
       "oscillator', Q. J. Mech. Appl. Math. 17(2):225-239: transverse force coefficient "
       "C_Fy = A1 tan(a) - A3 tan^3(a) + A5 tan^5(a) - A7 tan^7(a), A1 = 2.69, A3 = 168, "
       "A5 = 6270, A7 = 59900 (Re = 22300), a = atan(ydot/U)",
       "C_D(alpha) = 1.75 + 0.25 cos(4 alpha) is ILLUSTRATIVE (2.0 face-on as measured for "
       "square prisms, 1.5 corner-on); the blend beyond 13 deg is ILLUSTRATIVE"],
      ["C_Fy acts along the motion, on 1/2 rho U^2 h; in this table's convention a section",
       "  moving along its lift direction at ydot sees alpha = -atan(ydot/U), hence",
       "  C_Fy = -(C_L + C_D tan a) sec a and C_L(a) = -C_Fy(a) cos a - C_D(a) tan a (odd in a);",
       "  dC_Fy/da(0) = A1 = -H(0): the Den Hartog coefficient at alpha = 0 is -2.69 per rad.",
       "for |alpha| <= 13 deg: the polynomial above (it diverges beyond about 15 deg);",
       "for 13 < |alpha| <= 45 deg: the cubic in (alpha - 45 deg) that matches C_L and dC_L/dalpha",
       "  at 13 deg and has C_L = C_L'' = 0 at 45 deg; then 90-degree periodic (the square's",
       "  symmetry), C_L odd about 0 and 45 deg, C_D even; C_M = 0 (about the centre, by symmetry",
       "  of the mean flow at 0 and 45 deg; not measured by Parkinson & Smith)."],
      rows)


# ---- iced conductors: illustrative Fourier series ----
def fourier(terms, a):
    """sum of (amp, harmonic, phase_deg, kind) terms: amp cos|sin(k (a - phase))."""
    s = 0.0
    for amp, k, ph, kind in terms:
        x = k * (a - math.radians(ph))
        s += amp * (math.cos(x) if kind == "c" else math.sin(x))
    return s


def fmt(terms, name):
    parts = []
    for amp, k, ph, kind in terms:
        fn = "cos" if kind == "c" else "sin"
        if k == 0:
            parts.append("%g" % amp)
        else:
            arg = "alpha" if ph == 0 else "(alpha - %g deg)" % ph
            parts.append("%+g %s(%s%s)" % (amp, fn, "" if k == 1 else "%d " % k, arg))
    return name + " = " + " ".join(parts)


def iced(path, title, features, cd, cl, cm, notes):
    rows = []
    for a in range(-180, 180, 5):
        r = math.radians(a)
        rows.append((a, fourier(cd, r), fourier(cl, r), fourier(cm, r)))
    write(path,
          ["ILLUSTRATIVE, not measured: a smooth Fourier series (below) with the qualitative "
           "features of %s (%s); "
           "no numbers were taken from a publication. Replace it with wind-tunnel data (e.g. "
           "Chabart & Lilien 1998, J. Wind Eng. Ind. Aerodyn.) for design work" % (title, features)],
          [fmt(cd, "C_D"), fmt(cl, "C_L"), fmt(cm, "C_M"),
           "tabulated every 5 deg; the spline through these nodes is what gallop uses"] + notes,
          rows)


D_CD = [(1.15, 0, 0, "c"), (0.12, 2, 20, "c"), (-0.06, 1, 0, "c")]
D_CL = [(-0.85, 2, 20, "s"), (-0.15, 1, 0, "s")]
D_CM = [(-0.08, 2, 20, "s"), (0.03, 1, 0, "s")]
iced("data/aero/iced_d_shape.csv", "D-shaped ice accretions on single conductors",
     "C_D ~ 1-1.3, C_L of order +-1, small C_M, a negative Den Hartog range", D_CD, D_CL, D_CM,
     ["d1 points from the conductor axis away from the ice (ice on the -d1 side, facing the wind",
      "  at alpha = 0); Den Hartog H < 0 for alpha in about [-5, 45] deg (minimum near 20 deg)",
      "  and, weaker, in about [-175, -150] deg (wind on the ice-free side)."])

C_CD = [(1.05, 0, 0, "c"), (0.06, 2, 15, "c")]
C_CL = [(-0.35, 2, 15, "s"), (0.05, 1, 0, "s")]
C_CM = [(-0.04, 2, 15, "s"), (-0.01, 1, 0, "s")]
iced("data/aero/iced_crescent.csv", "thin crescent-shaped ice accretions on single conductors",
     "C_D ~ 1-1.1, weaker lift than the D-shape, small C_M, Den Hartog stable", C_CD, C_CL, C_CM,
     ["d1 points from the conductor axis away from the ice (ice on the -d1 side);",
      "  Den Hartog H > 0 everywhere (thin ice: galloping, if any, through the torsional mechanism)."])
