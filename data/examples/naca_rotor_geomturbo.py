#!/usr/bin/env python3
"""Writes naca_rotor.geomTurbo: a turbine rotor blade that is not one of CoolingGen's parametric blades,
as an aero tool would hand it over (stand-alone: imports nothing from CoolingGen, only the standard library).

Source of the section data: the NACA four-digit thickness distribution (Jacobs, Ward and Pinkerton,
"The characteristics of 78 related airfoil sections from tests in the variable-density wind tunnel",
NACA Report 460, 1933):
    y_t / c = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - 0.1015 x^4),
at t = 23 % (hub) to 21 % (tip), laid normal to a circular-arc camber line (the classical cascade mean
line) turning the flow by 80 deg at the hub to 70 deg at the tip. For a cooled blade the trailing edge is
made blunt: the half-thickness gets a linear addition reaching 0.6 mm at x = 1 and the TE is closed by a
semicircle of that radius, half on each side.

Stacking (what makes it 3D): six sections on cylinders r = const from 266 mm (below the hub) to 340 mm
(above the casing) of the flow path below, chord 38 -> 34 mm, twisted by 8 deg (stagger -10 -> -18 deg about
the mid-chord point), leaned 10 deg circumferentially and swept 1.5 mm axially. Suction sides have 71
points, pressure sides 53 (cosine-spaced in x plus 6 points on each half of the TE circle). Coordinates are
written in metres as ZRTH (z axial, r, theta in radians), with a 0.4 mm tip gap and 60 blades.

Run: python3 data/examples/naca_rotor_geomturbo.py  (writes data/examples/naca_rotor.geomTurbo)
"""
import math
import os

HUB = [(-30.0, 272.0), (0.0, 275.0), (20.0, 277.5), (40.0, 279.0), (70.0, 280.0)]
CASING = [(-30.0, 334.0), (0.0, 331.0), (20.0, 329.5), (40.0, 329.0), (70.0, 330.0)]
RADII = [266.0, 281.0, 296.0, 311.0, 326.0, 340.0]
TE_HALF = 0.6       # mm, half-thickness (radius) of the blunt trailing edge
N_SUCTION, N_PRESSURE, N_ARC = 71, 53, 6
TIP_GAP = 0.4       # mm
BLADES = 60


def naca_half_thickness(x, t):
    return 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1015 * x ** 4)


def side(chord, t, camber_deg, upper, n_side):
    """One side LE -> TE in the chord frame (s along the chord, n normal; mm), TE semicircle half included."""
    half = math.radians(camber_deg) / 2
    radius = chord / (2 * math.sin(half))
    centre_n = -radius * math.cos(half)        # arc centre at (c/2, centre_n), arc bulging towards +n
    te_add = TE_HALF / chord - naca_half_thickness(1.0, t)
    sign = 1 if upper else -1
    pts = []
    n_foil = n_side - N_ARC
    for i in range(n_foil):
        x = 0.5 * (1 - math.cos(math.pi * i / (n_foil - 1)))
        s = x * chord
        phi = math.asin((s - chord / 2) / radius)          # angle of the camber point from the arc's top
        cs, cn = chord / 2 + radius * math.sin(phi), centre_n + radius * math.cos(phi)
        nx, ny = math.sin(phi), math.cos(phi)               # unit normal of the camber line (outwards)
        h = chord * (naca_half_thickness(x, t) + x * te_add)
        pts.append((cs + sign * h * nx, cn + sign * h * ny))
    # Blunt TE: quarter of the TE circle from the side's end to the tip on the camber tangent.
    phi_te = half
    tx, ty = math.cos(phi_te), -math.sin(phi_te)            # camber tangent at the TE (downstream)
    nx, ny = math.sin(phi_te), math.cos(phi_te)
    for k in range(1, N_ARC + 1):
        a = (math.pi / 2) * k / N_ARC
        pts.append((chord + TE_HALF * (math.cos(a) * sign * nx + math.sin(a) * tx),
                    TE_HALF * (math.cos(a) * sign * ny + math.sin(a) * ty)))
    return pts


def section(r):
    f = (r - RADII[0]) / (RADII[-1] - RADII[0])
    chord = 38.0 - 4.0 * f
    t = 0.23 - 0.02 * f
    camber = 80.0 - 10.0 * f
    stagger = math.radians(-10.0 - 8.0 * f)
    lean_b = (r - RADII[0]) * math.tan(math.radians(10.0))  # circumferential shift of the stacking point
    sweep_a = 1.5 * f
    out = []
    for upper, n in ((True, N_SUCTION), (False, N_PRESSURE)):
        pts = []
        for s, n_ in side(chord, t, camber, upper, n):
            s -= chord / 2                                   # about mid-chord
            a = s * math.cos(stagger) - n_ * math.sin(stagger) + chord / 2 * math.cos(stagger) + sweep_a
            b = s * math.sin(stagger) + n_ * math.cos(stagger) + lean_b
            pts.append((a, r, b / r))                        # z = a (axial), theta = b / r
        out.append(pts)
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    m = 0.001  # file in metres
    lines = ["GEOMETRY TURBO", "VERSION 5.5", "TOLERANCE 1e-06", "UNITS Meters", "UNITS-FACTOR 1",
             "NI_BEGIN CHANNEL"]
    for name, pts in (("hub_curve", HUB), ("shroud_curve", CASING)):
        lines += ["NI_BEGIN basic_curve", "NAME " + name, "DISCRETISATION 10", "DATA_REDUCTION 0",
                  "NI_BEGIN zrcurve", "ZR", str(len(pts))]
        lines += ["%.9f %.9f" % (z * m, r * m) for z, r in pts]
        lines += ["NI_END zrcurve", "NI_END basic_curve"]
    for which in ("hub", "shroud"):
        lines += ["NI_BEGIN channel_curve " + which, "NAME " + which,
                  "VERTEX CURVE_P %s_curve 0" % which, "VERTEX CURVE_P %s_curve 1" % which,
                  "NI_END channel_curve " + which]
    lines += ["NI_END CHANNEL", "NI_BEGIN nirow", "NAME rotor", "TYPE normal", "PERIODICITY %d" % BLADES,
              "NI_BEGIN NIBlade", "NAME Main Blade", "NI_BEGIN nibladegeometry", "TYPE GEOMTURBO",
              "GEOMETRY_MODIFIED 0", "GEOMETRY TURBO VERSION 5", "units 1", "number_of_blades %d" % BLADES]
    sections = [section(r) for r in RADII]
    for k, name in ((0, "suction"), (1, "pressure")):
        lines += [name, "SECTIONAL", str(len(sections))]
        for i, sec in enumerate(sections):
            pts = sec[k]
            lines += ["# section %d" % (i + 1), "ZRTH", str(len(pts))]
            lines += ["%.9f %.9f %.12f" % (z * m, r * m, th) for z, r, th in pts]
    lines += ["NI_END nibladegeometry", "NI_BEGIN NITipGap",
              "WIDTH_AT_LEADING_EDGE %.6f" % (TIP_GAP * m), "WIDTH_AT_TRAILING_EDGE %.6f" % (TIP_GAP * m),
              "NI_END NITipGap", "NI_END NIBlade", "NI_END nirow", "NI_END GEOMTURBO"]
    with open(os.path.join(here, "naca_rotor.geomTurbo"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
