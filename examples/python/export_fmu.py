#!/usr/bin/python3
"""The ASR-V yaw damping surface as an FMI 2.0 Co-Simulation FMU for a simulator.

The yaw table (examples/asr-v, N(r) on the body) becomes a PCHIP surface N(r)
[N m] continued linearly beyond the runs, exported as `hydrocoef export-fmu`
writes it: input r [rad/s], outputs N and sigma(N) [N m] (docs/fmu.md). The
FMU is written into the folder given (default: beside the database); the
script prints its identifier, GUID and variables.

  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/export_fmu.py --db build/fmu.db
"""

import argparse
import pathlib

import hydrocoef

TABLES = pathlib.Path(__file__).resolve().parents[1] / "asr-v"

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--db", required=True)
parser.add_argument("--out", help="folder of the FMU (default: the database's)")
args = parser.parse_args()
out = pathlib.Path(args.out or pathlib.Path(args.db).parent)
out.mkdir(parents=True, exist_ok=True)
pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

with hydrocoef.Database(args.db, mode="create") as db:
    db.import_files(TABLES / "asr-v-yaw-damping.csv", body="asr-v",
                    settings={"sign": "on-body", "rho": 998.2, "nu": 1.004e-6})
    db.build_surface("yaw", body="asr-v", axes="r", outputs="N", method="pchip", extrapolate="linear", replace=True)
    fmu = hydrocoef.export_fmu(db, "asr-v", surface="yaw", output=str(out / "asr-v-yaw.fmu"))

print(fmu.text(), end="")
for v in fmu.variables:
    print(f"{v.value_reference} {v.name} {v.causality} {v.unit}")
