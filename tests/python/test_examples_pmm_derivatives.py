"""examples/python/pmm_derivatives.py run as a user runs it (the same interpreter,
the module of this build), its printed numbers checked against physics and
against the CLI's --json on the database it made."""

import os
import pathlib
import re
import subprocess
import sys

import hydrocoef
from conftest import SOURCE_DIR, cli_json

EXAMPLE = SOURCE_DIR / "examples" / "python" / "pmm_derivatives.py"
NUMBER = r"(-?[0-9.]+(?:e[-+]?[0-9]+)?)"


def test_pmm_derivatives_example_gives_minus_the_added_mass(tmp_path):
    db = tmp_path / "sway.db"
    environment = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(EXAMPLE), "--db", str(db)], capture_output=True, text=True,
                            env=environment)
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "pure sway at U = 0 m/s, T = 2 s, 2 runs:" in out, out
    printed = dict(re.findall(r"  (\w+) = " + NUMBER + r" \+- ", out))
    assert sorted(printed) == ["N_v", "N_vdot", "Y_v", "Y_vdot"], out
    document = cli_json(db, "derivatives", "pmm", "sphere", "--length", "0.3")
    matrix = cli_json(db, "added-mass", "sphere")
    for d in document["sets"][0]["derivatives"]:
        assert abs(float(printed[d["name"]]) - d["value"]) <= 5e-6 * abs(d["value"]), (d, out)
    y_vdot = document["sets"][0]["derivatives"][1]
    assert y_vdot["value"] == -matrix["added_mass_b"][1][1]
    assert float(printed["Y_v"]) < 0
    ratio = float(re.search(r"Y_vdot / \(rho V\) = " + NUMBER, out).group(1))
    assert -0.55 < ratio < -0.5  # potential flow's -0.5 and a few per cent of boundary layer
    prime = float(re.search(r"Y_vdot = .*prime " + NUMBER, out).group(1))
    assert abs(prime - y_vdot["prime"]) <= 5e-6 * abs(y_vdot["prime"])
