"""Fixtures of the Python module's tests: a database of the ASR-V tables and a
2-D force table, imported through the module, with surfaces built by the CLI of
the same build (HYDROCOEF_CLI), as ctest runs them (python/CMakeLists.txt)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import hydrocoef

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
ASR_V = SOURCE_DIR / "examples" / "asr-v"


def cli_path():
    path = os.environ.get("HYDROCOEF_CLI")
    if not path:
        pytest.skip("HYDROCOEF_CLI is not set (ctest sets it to the build's hydrocoef binary)")
    return path


def run_cli(db, *args, check=True):
    """The CLI on `db`: (exit code, stdout, stderr)."""
    result = subprocess.run([cli_path(), "--db", str(db), *args], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"hydrocoef {' '.join(args)}: {result.stderr}")
    return result.returncode, result.stdout, result.stderr


def cli_error(db, *args):
    """The message the CLI prints for a refused command (after 'hydrocoef: error: ')."""
    code, _, err = run_cli(db, *args, check=False)
    assert code == 2, err
    assert err.startswith("hydrocoef: error: "), err
    return err[len("hydrocoef: error: "):].rstrip("\n")


def cli_json(db, *args):
    return json.loads(run_cli(db, *args, "--json")[1])


def grid_function(u, v):
    """The 2-D table's forces: X = -10 u|u| - 2 v, Y = u - 5 v|v| + 0.3 u v."""
    return -10 * u * np.abs(u) - 2 * v, u - 5 * v * np.abs(v) + 0.3 * u * v


GRID_U = np.linspace(0.0, 0.38, 20)
GRID_V = np.linspace(-0.2, 0.2, 20)


def write_grid_table(path):
    uu, vv = np.meshgrid(GRID_U, GRID_V, indexing="ij")
    x, y = grid_function(uu, vv)
    with open(path, "w") as out:
        out.write("u [m s^-1],v [m s^-1],X [N],Y [N]\n")
        for row in zip(uu.ravel(), vv.ravel(), x.ravel(), y.ravel()):
            out.write(",".join(repr(float(value)) for value in row) + "\n")


@pytest.fixture(scope="session")
def db_path(tmp_path_factory):
    path = tmp_path_factory.mktemp("hydrocoef") / "test.db"
    with hydrocoef.Database(path, mode="create") as db:
        db.import_files(ASR_V / "asr-v-surge-damping.csv", body="asr-v",
                        settings={"sign": "opposing", "rho": 998.2, "nu": 1.004e-6})
        db.import_files([ASR_V / "asr-v-yaw-damping.csv"], body="asr-v",
                        settings={"sign": "on-body", "rho": 998.2, "nu": 1.004e-6})
        table = path.parent / "grid.csv"
        write_grid_table(table)
        db.import_files(table, body="grid")
    for name, body, outputs, axes, method, extrapolate in [
            ("asr-v-surge", "asr-v", "X", "u", "pchip", "linear"),
            ("asr-v-yaw", "asr-v", "N", "r", "pchip", "linear"),
            ("grid-linear", "grid", "X,Y", "u,v", "linear", "error"),
            ("grid-pchip", "grid", "X,Y", "u,v", "pchip", "error")]:
        run_cli(path, "surface", "build", name, "--body", body, "--outputs", outputs, "--axes", axes,
                "--method", method, "--extrapolate", extrapolate)
    return path


@pytest.fixture
def db(db_path):
    with hydrocoef.Database(db_path, mode="r") as database:
        yield database
