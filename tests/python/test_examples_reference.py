"""examples/python/drag_coefficient.py runs as a user runs it (the same interpreter, the module of this build):
its printed Re and Cd are the formulas' from the runs' own forces, and the CLI's on the database it made."""

import math
import os
import pathlib
import re
import subprocess
import sys

import hydrocoef
from conftest import SOURCE_DIR, cli_json

EXAMPLE = SOURCE_DIR / "examples" / "python" / "drag_coefficient.py"


def test_drag_coefficient_example_prints_the_formulas_numbers(tmp_path):
    db = tmp_path / "cd.db"
    environment = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(EXAMPLE), "--db", str(db)], capture_output=True, text=True,
                            env=environment)
    assert result.returncode == 0, result.stderr
    printed = re.findall(r"mesh (\d), U = ([0-9.]+) m/s: Re = ([0-9.e+]+), Cd = ([0-9.]+)", result.stdout)
    assert len(printed) == 6, result.stdout
    runs = {(r["disturbances"]["mesh"], r["u"]): r for r in cli_json(db, "runs")}
    area = math.pi * 0.15 ** 2
    for mesh, speed, reynolds, cd in printed:
        run = runs[(float(mesh), float(speed))]
        drag = -run["forces"]["X"]["total"]  # the whole sphere's (symmetry y=0,z=0), on the body
        assert abs(float(cd) - drag / (0.5 * 998.2 * float(speed) ** 2 * area)) <= 5e-6 * float(cd)
        assert abs(float(reynolds) - float(speed) * 0.3 / 1.004e-6) <= 5e-6 * float(reynolds)
        assert 0.15 < float(cd) < 0.3
    theirs = [-r["coefficients"]["C_X"] for r in cli_json(db, "runs", "--coefficients")["runs"]]
    for *_, cd in printed:
        assert any(abs(float(cd) - exact) <= 5e-6 * exact for exact in theirs)
