#!/usr/bin/python3
"""Sway derivatives of a sphere from two forced-oscillation runs, from Python.

Data: examples/openfoam-sphere/pmm (PROVENANCE.md there): OpenFOAM v1912, the
whole mesh of a sphere of radius 0.15 m moved along the case's x axis as
x = A sin(pi t) (period 2 s) at A = 0.015 and 0.045 m, the water at rest. Read
with body y = case x (axes "y,x,-z"), each run is a pure sway run at U = 0.

What it does, as `hydrocoef pmm` and `hydrocoef derivatives pmm` do:
  1. analyses and stores both runs as sway runs;
  2. gives the sway derivatives: Y_v from the part of Y in phase with v,
     Y_vdot from the part in phase with vdot (SNAME body axes, forces on the
     body), the two amplitudes combined, and the prime form of Y_vdot with
     L = 0.3 m (the diameter): Y_vdot' = Y_vdot / (1/2 rho L^3).

Expected: Y_vdot = -M_A[sway][sway], about -0.514 rho V (potential flow's
-0.5 and the Stokes boundary layer); Y_v < 0 (the boundary layer dissipates).

Run from the repository after a build (scripts/build.sh):
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/pmm_derivatives.py [--db build/sway.db]
"""

import argparse
import pathlib

import hydrocoef
from sphere_pmm import RADIUS, RHO, ROOT, VOLUME, analyse_runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", default=str(ROOT / "build" / "sphere-sway-python.db"))
    args = parser.parse_args()
    pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

    analysis = analyse_runs("y,x,-z")
    with hydrocoef.Database(args.db, mode="create") as db:
        hydrocoef.store_pmm(db, analysis)
        result = hydrocoef.pmm_derivatives(db, "sphere", length=2 * RADIUS)
    for group in result.sets:
        print(f"{group.motion} at U = {group.speed:g} m/s, T = {group.period:g} s, {group.runs} runs:")
        for d in group.derivatives:
            prime = f", prime {d.prime:.6g}" if d.prime is not None else ""
            print(f"  {d.name} = {d.value:.6g} +- {d.std_error:.2g} {d.unit} ({d.source}){prime}")
    y_vdot = result.sets[0].derivatives[1]
    print(f"Y_vdot / (rho V) = {y_vdot.value / (RHO * VOLUME):.6g} (potential flow: -0.5)")


if __name__ == "__main__":
    main()
