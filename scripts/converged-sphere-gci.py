#!/usr/bin/env python3
"""Celik et al. (2008, J. Fluids Eng. 130 078001) grid convergence index of the
drag of the quarter-domain sphere runs in data/openfoam-sphere/converged/.

    scripts/converged-sphere-gci.py [reference.json]

For each speed, from the three meshes' reference (iteratively converged) Fx
and cell counts N: the refinement ratios r = (N_fine / N_coarse)^(1/3), the
observed order p (fixed-point iteration of Celik's eq. 5), the extrapolated
value, the fine-grid GCI, and the drag coefficient
Cd = 4 Fx / (0.5 rho U^2 pi R^2) (x 4: the quarter surface). Also prints the
iterative error of each residualControl-1e-4 stop against its reference.
"""
import json
import math
import os
import sys

RHO, R = 998.2, 0.15
here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    here, '..', 'data', 'openfoam-sphere', 'converged', 'reference.json')
cases = json.load(open(path))['cases']


def cd(fx, u):
    return 4 * fx / (0.5 * RHO * u * u * math.pi * R * R)


print(f"{'case':12} {'cells':>7} {'it_stop':>7} {'Fx_stop':>13} {'it_ref':>6} {'Fx_ref':>13}"
      f" {'rel_diff':>10} {'Cd_ref':>7} stopped_by")
for name, c in cases.items():
    fs, fr = c['stop_1e-4']['force'][0], c['reference']['force'][0]
    print(f"{name:12} {c['cells']:7d} {c['stop_1e-4']['iteration']:7d} {fs:13.7e}"
          f" {c['reference']['iteration']:6d} {fr:13.7e} {(fs - fr) / fr:+10.3e}"
          f" {cd(fr, c['U'][0]):7.4f} {c['reference']['stopped_by']}")

for u in sorted({c['U'][0] for c in cases.values()}):
    grids = sorted((c for c in cases.values() if c['U'][0] == u), key=lambda c: -c['cells'])
    if len(grids) != 3:
        continue
    (n1, f1), (n2, f2), (n3, f3) = [(g['cells'], g['reference']['force'][0]) for g in grids]
    r21, r32 = (n1 / n2) ** (1 / 3), (n2 / n3) ** (1 / 3)
    e21, e32 = f2 - f1, f3 - f2
    ratio = e32 / e21
    s = math.copysign(1, ratio)
    p = 2.0
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        p = abs(math.log(abs(ratio)) + q) / math.log(r21)
    ext = (r21 ** p * f1 - f2) / (r21 ** p - 1)
    ea = abs((f1 - f2) / f1)
    gci = 1.25 * ea / (r21 ** p - 1)
    kind = 'monotonic' if ratio > 0 else 'oscillatory'
    if abs(ratio) < 1:  # Celik's |.| hides it: the change grows as the mesh is refined
        kind += ', DIVERGING: |e21| > |e32|, p and GCI meaningless'
    print(f"U = {u}: N = {n1}, {n2}, {n3}; r21 = {r21:.3f}, r32 = {r32:.3f}; Fx = {f1:.7e}, {f2:.7e},"
          f" {f3:.7e} ({kind}, e32/e21 = {ratio:.3f}); p = {p:.2f}; Fx_ext = {ext:.7e}"
          f" (Cd {cd(ext, u):.4f}); GCI_fine = {100 * gci:.2f} %")
