#!/usr/bin/python3
"""A mesh study's numerical uncertainty (Celik et al. 2008), from Python.

Data: data/openfoam-sphere/converged (README.md there): steady RANS runs of a
sphere of radius 0.15 m in a quarter domain at 0.1 and 0.3 m/s on three
systematically refined meshes; reference.json gives each case's mesh level
and cell count.

What it does, as `hydrocoef import --set mesh=L --set cells=N` and
`hydrocoef gci` do:
  1. imports the six case folders into a run database, each with its mesh
     level and cell count as disturbance parameters;
  2. runs the grid-convergence study of each speed: the observed order p,
     the Richardson extrapolation and the GCI of the drag X on the finest mesh,
     stored as the runs' numerical uncertainty u_num = GCI_fine |phi1| / 2.
The runs stopped on residualControl 1e-4, whose iterative error is not below
a tenth of the mesh changes: Celik et al. would refuse them, so the study is
run with allow_unconverged=True (each component says so in its note).

Run from the repository after a build (scripts/build.sh):
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/gci_study.py [--db build/sphere-gci.db]
"""

import argparse
import pathlib

import hydrocoef
from sphere_study import ROOT, import_study


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", default=str(ROOT / "build" / "sphere-gci-python.db"))
    args = parser.parse_args()
    pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

    with hydrocoef.Database(args.db, mode="create") as db:
        import_study(db)
        study = hydrocoef.grid_convergence(db, body="sphere", allow_unconverged=True)
    for key in study.keys:
        x = key.components[0]  # X, the drag of the quarter sphere (on the body)
        levels = ",".join(f"{level:g}" for level in key.levels)
        print(f"u = {key.velocity[0]:g} m/s, mesh levels {levels}: X fine to coarse {x.phi[0]:.6g} {x.phi[1]:.6g} "
              f"{x.phi[2]:.6g} N, {x.convergence}, p = {x.apparent_order:.6g}, X_ext = {x.extrapolated:.6g} N, "
              f"GCI_fine = {x.gci_fine:.6g}, u_num = {x.numerical_uncertainty:.6g} N")


if __name__ == "__main__":
    main()
