"""The Python examples of the records' operations run as a user runs them (examples/python/fit_law.py,
fit_and_plot.py), their printed numbers checked against the CLI and the ASR-V paper's law."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np

import hydrocoef
from conftest import SOURCE_DIR, cli_json

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(name, *args):
    """The example under this interpreter with the module this test imports; its standard output."""
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]),
               MPLBACKEND="Agg")
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *args], capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_fit_law_prints_the_law_and_its_band(tmp_path):
    db = tmp_path / "fit-law.db"
    out = run_example("fit_law.py", "--db", str(db))
    rows = [line.split() for line in out.splitlines() if re.match(r"^\s+\d\.\d\d\s", line)]
    assert len(rows) == 11
    at = np.array([float(r[0]) for r in rows])
    value = np.array([float(r[1]) for r in rows])
    sigma = np.array([float(r[2]) for r in rows])
    assert np.allclose(at, np.linspace(0.0, 0.5, 11))
    # The stored law evaluated by the CLI on the example's database: the same numbers, as printed.
    name = cli_json(db, "fits")[0]["name"]
    theirs = cli_json(db, "fits", "evaluate", name, "--at", ",".join(f"{x:g}" for x in at))
    assert np.allclose(value, theirs["value"], rtol=0, atol=6e-6)
    assert np.allclose(sigma, theirs["std_error"], rtol=5e-3)
    # The runs: X(0.2) = 0.44516 N, X(0.3) = 0.99881 N as tabulated (positive opposes motion).
    assert abs(value[4] - 0.44516) < 3 * sigma[4] + 0.005
    assert abs(value[6] - 0.99881) < 3 * sigma[6] + 0.01
    assert np.all(sigma > 0)
    assert sigma[10] > sigma[8]  # beyond the runs (0.38 m/s) the band widens
    assert "fitted over u = 0 to 0.38 m/s" in out
    assert "weighted by each run's uncertainty" in out


def test_fit_and_plot_prints_the_papers_laws(tmp_path):
    out = run_example("fit_and_plot.py", "--db", str(tmp_path / "asr-v.db"), "--png", str(tmp_path / "asr-v.png"))
    assert "X(u) = 0.000618201 + 0.0155077 u + 11.0364 u|u|" in out
    assert "N(r) = 1.89812e-05 - 0.00607516 r - 0.0771371 r|r|" in out
    assert "20 new runs" in out and "39 runs of body asr-v" in out
    surge = [line for line in out.splitlines() if line.strip().startswith("u = 0.228")]
    assert surge, out
    # On the body at u = 0.228 m/s: between the runs at 0.22 (-0.53802 N) and 0.24 (-0.63986 N).
    x = float(surge[0].split("X =")[1].split()[0])
    assert -0.63986 < x < -0.53802
