#!/usr/bin/python3
"""Added mass of a sphere from two forced-oscillation runs, from Python.

Data: examples/openfoam-sphere/pmm (PROVENANCE.md there): OpenFOAM v1912, the
whole mesh of a sphere of radius 0.15 m moved in surge as x = A sin(pi t)
(period 2 s) at A = 0.015 and 0.045 m; the motion is read from each case's
constant/dynamicMeshDict. The case's x axis points aft: --axes -x,y,-z.

What it does, as `hydrocoef pmm` and `hydrocoef added-mass` do:
  1. analyses both runs: the surge force fitted over whole periods after the
     start-up transient, the part in phase with the acceleration giving the
     added mass M_A, the part with the velocity the damping D;
  2. stores them in a run database and assembles the 6x6 added-mass matrix of
     a sphere (sway and heave as surge, no rotational added mass), with the
     quadratic damping from the two amplitudes.

Expected: M_A close to rho V / 2 (potential flow), the Stokes boundary layer
adding a few per cent: C_A = M_A / (rho V) about 0.51.

Run from the repository after a build (scripts/build.sh):
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/pmm_analysis.py [--db build/sphere-pmm.db]
"""

import argparse
import pathlib

import hydrocoef
from sphere_pmm import RADIUS, RHO, ROOT, VOLUME, analyse_runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", default=str(ROOT / "build" / "sphere-pmm-python.db"))
    args = parser.parse_args()
    pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

    analysis = analyse_runs("-x,y,-z", nu=1.004e-6, volume=VOLUME, size=2 * RADIUS)
    for run in analysis.runs:
        x = run.components[0]  # X: the surge force of a surge run
        print(f"run {pathlib.Path(run.path).name}: A = {run.amplitude:g} m, T = {run.period:g} s, "
              f"KC = {run.keulegan_carpenter:.4g}: M_A = {x.added_mass:.6g} kg (C_A = {x.added_mass_coefficient:.6g}), "
              f"D = {x.damping:.6g} N s/m")

    with hydrocoef.Database(args.db, mode="create") as db:
        hydrocoef.store_pmm(db, analysis)
        matrix = hydrocoef.added_mass_matrix(db, "sphere", same={"sway": "surge", "heave": "surge"},
                                             zero=["roll", "pitch", "yaw"])
    print("M_A diagonal [kg, kg m^2]: " + " ".join(f"{matrix.added_mass[i, i]:.6g}" for i in range(6)))
    print(f"C_A = M_A / (rho V) = {matrix.added_mass[0, 0] / (RHO * VOLUME):.6g} (potential flow: 0.5)")
    for q in matrix.quadratic_damping:
        print(f"quadratic damping of {q.dof}: b1 = {q.linear:.6g} N s/m, b2 = {q.quadratic:.6g} N s^2/m^2")


if __name__ == "__main__":
    main()
