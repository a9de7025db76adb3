#!/usr/bin/python3
"""A GP surface of the ASR-V surge runs, tabulated with its standard deviation for a controller.

The surge damping table (examples/asr-v, X(u) as printed: positive opposes
motion, stored on the body) becomes a Gaussian-process surface X(u) [N]; the
surface is tabulated on 9 breakpoints u = 0 .. 0.4 m/s with X and its one-sigma
standard deviation at each, the lookup table a controller (or a robust
controller's uncertainty model) takes. Beyond the runs (u > 0.38) the GP is
clamped, as built.

  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/gp_table.py --db build/gp-table.db
"""

import argparse
import pathlib

import numpy as np

import hydrocoef

TABLES = pathlib.Path(__file__).resolve().parents[1] / "asr-v"

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--db", required=True)
args = parser.parse_args()
pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

with hydrocoef.Database(args.db, mode="create") as db:
    db.import_files(TABLES / "asr-v-surge-damping.csv", body="asr-v",
                    settings={"sign": "opposing", "rho": 998.2, "nu": 1.004e-6})
    db.build_surface("surge-gp", body="asr-v", axes="u", outputs="X", method="gp", gp_starts=2,
                     extrapolate="clamp", replace=True)
    table = db.surface("surge-gp").tabulate(u=np.linspace(0.0, 0.4, 9))

print("u [m/s]      X [N]   sigma_X [N]")
for u, x, sigma in zip(table["u"], table["X"], table["sigma_X"]):
    print(f"{u:7.3f} {x:10.6f} {sigma:13.6f}")
