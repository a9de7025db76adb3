"""A body's reference data and the runs' coefficients from Python give what the CLI prints with --json on the
same database (the OpenFOAM sphere runs of data/openfoam-sphere/cases): set_body_reference (body set),
body_references (body show) and run_coefficients (runs --coefficients), whose numpy columns hold the
coefficients worked from each run's force by C_X = X / (1/2 rho U^2 A)."""

import json
import math

import numpy as np
import pytest

import hydrocoef
from conftest import SOURCE_DIR, cli_error, cli_json, run_cli

CASES = sorted((SOURCE_DIR / "data" / "openfoam-sphere" / "cases").iterdir())
FRONTAL = math.pi * 0.15 ** 2


@pytest.fixture
def sphere_db(tmp_path):
    path = tmp_path / "sphere.db"
    with hydrocoef.Database(path, mode="create") as db:
        db.import_files(CASES, body="sphere", settings={"axes": "-x,y,-z"})
    return path


def test_set_and_show_give_the_cli_json(sphere_db):
    with hydrocoef.Database(sphere_db) as db:
        stored = hydrocoef.set_body_reference(db, "sphere", length=0.3, areas={"frontal": FRONTAL, "L*d": 0.09},
                                              default_area="frontal", volume=0.014137166941154069,
                                              moment_point=(0.1, 0.0, 0.0))
        shown = hydrocoef.body_references(db, "sphere")
    assert stored.length == 0.3 and stored.areas["frontal"] == FRONTAL and stored.default_area == "frontal"
    assert math.isnan(stored.draft)
    assert json.loads(stored.json()) == cli_json(sphere_db, "body", "show", "sphere")["bodies"][0]
    assert json.loads(shown.json()) == cli_json(sphere_db, "body", "show", "sphere")
    assert shown.text() == run_cli(sphere_db, "body", "show", "sphere")[1]
    assert [b.body for b in shown.bodies] == ["sphere"]


def test_coefficients_give_the_cli_json_and_the_formula(sphere_db):
    with hydrocoef.Database(sphere_db) as db:
        hydrocoef.set_body_reference(db, "sphere", length=0.3, areas={"frontal": FRONTAL})
        table = hydrocoef.run_coefficients(db, where=["u>0.05"])
        runs = db.runs()
    theirs = cli_json(sphere_db, "runs", "--coefficients", "--where", "u>0.05")
    assert json.loads(table.json()) == theirs
    assert table.csv() == run_cli(sphere_db, "runs", "--coefficients", "--where", "u>0.05", "--csv")[1]
    assert list(table.id) == [r["id"] for r in theirs["runs"]]
    assert list(table.coefficients["C_X"]) == [r["coefficients"]["C_X"] for r in theirs["runs"]]
    assert list(table.reynolds) == [r["reynolds"] for r in theirs["runs"]]
    assert table.references[0]["area_name"] == "frontal"  # the only area: the default
    # By hand from the runs' own forces, speeds and density.
    speed = np.sqrt(runs["u"] ** 2 + runs["v"] ** 2 + runs["w"] ** 2)
    expected = runs["X"] / (0.5 * 998.2 * speed ** 2 * FRONTAL)
    np.testing.assert_allclose(table.coefficients["C_X"], expected, rtol=1e-14)
    np.testing.assert_allclose(table.reynolds, speed * 0.3 / 1.004e-6, rtol=1e-15)
    assert np.all(table.coefficients["C_X"] < 0)  # a drag on the body, along -x
    assert table.gravity == 9.80665


def test_refusals_are_the_cli_messages(sphere_db):
    with hydrocoef.Database(sphere_db) as db:
        with pytest.raises(hydrocoef.InputError) as error:
            hydrocoef.run_coefficients(db)
        assert str(error.value) == cli_error(sphere_db, "runs", "--coefficients")
        with pytest.raises(hydrocoef.InputError) as error:
            hydrocoef.set_body_reference(db, "sphere", length=-0.3)
        assert str(error.value) == cli_error(sphere_db, "body", "set", "sphere", "--length", "-0.3")
    with hydrocoef.Database(sphere_db, mode="r") as db:
        with pytest.raises(hydrocoef.InputError, match="read-only"):
            hydrocoef.set_body_reference(db, "sphere", length=0.3)


def test_plot_coefficient_draws_the_numbers_of_run_coefficients(sphere_db, tmp_path):
    with hydrocoef.Database(sphere_db) as db:
        hydrocoef.set_body_reference(db, "sphere", length=0.3, areas={"frontal": FRONTAL})
        table = hydrocoef.run_coefficients(db)
        files = hydrocoef.plot_coefficient(db, coefficient="C_X", against="Re", image=tmp_path / "cx.svg")
    assert files.format == "svg" and files.series[0]["points"] == 4
    rows = [line.split() for line in open(files.data) if line.strip() and not line.startswith("#")]
    assert [float(r[0]) for r in rows] == list(table.reynolds)
    assert [float(r[1]) for r in rows] == list(table.coefficients["C_X"])
