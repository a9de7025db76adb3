#!/usr/bin/python3
"""The ASR-V yaw damping surface exported for a controller: a C99 header and a CSV table.

The yaw table (examples/asr-v, N(r) on the body) becomes a PCHIP surface N(r)
[N m] continued linearly beyond the runs; it is written as a self-contained
C header (float arithmetic, for a microcontroller) and as CSV, as `hydrocoef
export` writes them, into the folder given (default: beside the database).

  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/export_tables.py --db build/export.db
"""

import argparse
import pathlib

import hydrocoef

TABLES = pathlib.Path(__file__).resolve().parents[1] / "asr-v"

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--db", required=True)
parser.add_argument("--out", help="folder of the exported files (default: the database's)")
args = parser.parse_args()
out = pathlib.Path(args.out or pathlib.Path(args.db).parent)
out.mkdir(parents=True, exist_ok=True)
pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

with hydrocoef.Database(args.db, mode="create") as db:
    db.import_files(TABLES / "asr-v-yaw-damping.csv", body="asr-v",
                    settings={"sign": "on-body", "rho": 998.2, "nu": 1.004e-6})
    db.build_surface("yaw", body="asr-v", axes="r", outputs="N", method="pchip", extrapolate="linear", replace=True)
    header = db.export_surface("yaw", format="c", output=out / "yaw.h", single_precision=True)
    csv = db.export_surface("yaw", format="csv", output=out / "yaw.csv")

print(header.text(), end="")
print(csv.text(), end="")
print(f"{csv.nodes} nodes, r in [{csv.axes[0].lower}, {csv.axes[0].upper}] rad/s")
