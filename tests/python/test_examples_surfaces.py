"""The surface examples (examples/python/gp_table.py, export_tables.py) run
as a user runs them, each on a database of its own, and print the numbers
the module gives."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np

import hydrocoef
from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(name, *args):
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *args], capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_gp_table_prints_the_gp_and_its_sigma_at_each_breakpoint(tmp_path):
    db = tmp_path / "gp.db"
    out = run_example("gp_table.py", "--db", str(db))
    rows = [line.split() for line in out.splitlines()[1:]]
    assert len(rows) == 9
    u, x, sigma = (np.array([float(r[i]) for r in rows]) for i in range(3))
    np.testing.assert_allclose(u, np.linspace(0.0, 0.4, 9))
    with hydrocoef.Database(db, mode="r") as database:
        surface = database.surface("surge-gp")
        answer = surface(u=u, uncertainty=True)
    np.testing.assert_allclose(x, answer["X"], atol=5e-7)
    np.testing.assert_allclose(sigma, answer["sigma_X"], atol=5e-7)
    assert np.all(sigma > 0)
    assert x[-1] < -1.0 < x[0]  # surge damping on the body: about -1.6 N at 0.38 m/s, 0 at rest
    # A second run (the same database) gives the same table.
    assert run_example("gp_table.py", "--db", str(db)) == out


def test_export_tables_writes_a_c_header_and_a_csv_of_the_yaw_surface(tmp_path):
    db = tmp_path / "export.db"
    out = run_example("export_tables.py", "--db", str(db))
    assert f"wrote {tmp_path / 'yaw.h'}" in out
    assert f"wrote {tmp_path / 'yaw.csv'}" in out
    nodes = int(re.search(r"(\d+) nodes, r in", out).group(1))
    assert nodes == 20
    lines = (tmp_path / "yaw.csv").read_text().splitlines()
    rows = [line.split(",") for line in lines if line and not line.startswith("#")]
    values = np.array([[float(v) for v in row[:2]] for row in rows[1:]])
    assert len(values) == nodes
    with hydrocoef.Database(db, mode="r") as database:
        runs = database.runs(body="asr-v")
    np.testing.assert_allclose(values[:, 1], runs["N"][np.argsort(runs["r"])], rtol=1e-12)
    assert "float" in (tmp_path / "yaw.h").read_text()
