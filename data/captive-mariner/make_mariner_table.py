#!/usr/bin/env python3
"""Writes mariner-prime.csv: a synthetic captive-test table in the prime form.

The Mariner class vessel's sway force and yaw moment derivatives free of the
surge perturbation (Chislett and Strom-Tejsen 1965, Technical Report Hy-5,
Hydro- and Aerodynamics Laboratory, Lyngby; as printed, times 1e-5, in the MSS
toolbox's CRAFT/SHIP/models/mariner.m, github.com/cybergalactic/MSS, commit
6bca7942) evaluated over a captive programme at U0 = 7.7175 m/s (static drift,
rudder angle, drift and rudder, circular motion with drift; u = U0 on every
row). Each row is written at its own speed U = |(u, v)| with its forces
normalised by that speed (1/2 rho U^2 L^2, 1/2 rho U^2 L^3), the drift angle
by the MMG convention beta = atan2(-v, u).

    python3 data/captive-mariner/make_mariner_table.py > data/captive-mariner/mariner-prime.csv
"""
import math

L, U0, RHO = 160.93, 7.7175, 1025.0
SWAY = {"1": -4, "v": -1160, "r": -499, "v^3": -8078, "v^2*r": 15356, "delta": 278, "delta^3": -90,
        "v*delta^2": -4, "v^2*delta": 1190}
YAW = {"1": 3, "v": -264, "r": -166, "v^3": 1636, "v^2*r": -5483, "delta": -139, "delta^3": 45,
       "v*delta^2": 13, "v^2*delta": -489}


def term(name, v, r, d):
    return {"1": 1.0, "v": v, "r": r, "v^3": v**3, "v^2*r": v * v * r, "delta": d, "delta^3": d**3,
            "v*delta^2": v * d * d, "v^2*delta": v * v * d}[name]


def model(derivatives, v, r, d):
    return sum(value * 1e-5 * term(name, v, r, d) for name, value in derivatives.items())


def programme():
    for v in (-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3):
        yield "static-drift", v, 0.0, 0.0
    for d in (-0.5, -0.3, -0.1, 0.1, 0.3, 0.5):
        yield "rudder", 0.0, 0.0, d
    for v in (-0.2, 0.2):
        for d in (-0.4, -0.2, 0.2, 0.4):
            yield "drift-rudder", v, 0.0, d
    for r in (-0.4, -0.2, 0.2, 0.4):
        for v in (-0.2, -0.1, 0.0, 0.1, 0.2):
            yield "circular-motion", v, r, 0.0


print("# Synthetic: the Mariner's Y' and N' (Chislett and Strom-Tejsen 1965) at U0 = 7.7175 m/s;")
print("# written by make_mariner_table.py (see PROVENANCE.md)")
print("# form = prime")
print("# drift_convention = mmg")
print(f"# length = {L}")
print(f"# density = {RHO:g}")
print("test,U [m/s],beta [deg],delta [rad],r',Y',N'")
for test, vp, rp, d in programme():
    u, v, r = U0, vp * U0, rp * U0 / L
    U = math.hypot(u, v)
    Y = 0.5 * RHO * U0**2 * L**2 * model(SWAY, vp, rp, d)
    N = 0.5 * RHO * U0**2 * L**3 * model(YAW, vp, rp, d)
    beta = math.degrees(math.atan2(-v, u))
    print(f"{test},{U!r},{beta!r},{d!r},{r * L / U!r},{Y / (0.5 * RHO * U * U * L * L)!r},"
          f"{N / (0.5 * RHO * U * U * L**3)!r}")
