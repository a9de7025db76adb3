#!/usr/bin/python3
"""The sphere's drag coefficient against the Reynolds number, from Python.

Data: data/openfoam-sphere/converged (README.md there): steady RANS runs of a
sphere of radius R = 0.15 m in water (rho 998.2 kg/m^3, nu 1.004e-6 m^2/s) in a
quarter domain at 0.1 and 0.3 m/s on three meshes; reference.json gives each
case's mesh level.

What it does, as `hydrocoef import --symmetry y=0,z=0`, `hydrocoef body set`
and `hydrocoef runs --coefficients` do:
  1. imports the six case folders into a run database in body axes, the
     quarter patch's force made the whole sphere's by the two symmetry planes,
     each run with its mesh level;
  2. gives the body its reference data: L = 2R = 0.3 m, frontal area pi R^2;
  3. prints each run's Re = U L / nu and Cd = -C_X, C_X = X / (1/2 rho U^2 A)
     (body axes, the force on the body: a drag is negative).
The coefficients (0.17 to 0.28) are those of this coarse wall-function model,
falling as the mesh is refined (docs/coefficients.md).

Run from the repository after a build (scripts/build.sh):
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/drag_coefficient.py [--db build/sphere-cd.db]
"""

import argparse
import math
import pathlib

import hydrocoef
from sphere_study import RADIUS as R, ROOT, import_study


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", default=str(ROOT / "build" / "sphere-cd-python.db"))
    args = parser.parse_args()
    pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

    with hydrocoef.Database(args.db, mode="create") as db:
        import_study(db, axes="-x,y,-z", symmetry="y=0,z=0")
        hydrocoef.set_body_reference(db, "sphere", length=2 * R, areas={"frontal": math.pi * R ** 2})
        table = hydrocoef.run_coefficients(db)
    for i in range(table.id.size):
        print(f"mesh {table.disturbances['mesh'][i]:g}, U = {table.speed[i]:g} m/s: Re = {table.reynolds[i]:.6g}, "
              f"Cd = {-table.coefficients['C_X'][i]:.6g}")


if __name__ == "__main__":
    main()
