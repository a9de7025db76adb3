"""Derivative models of several variables from Python give what `hydrocoef derivatives ... --json` prints on
the same database: a model fitted, listed, shown in the SI and prime forms, evaluated with its standard error,
and deleted; a refusal is the CLI's message."""
import json

import numpy as np
import pytest

import hydrocoef
from conftest import cli_error, cli_json, run_cli, write_grid_table

TERMS = "u, v, v*|v|, u*v"


@pytest.fixture
def grid_db(tmp_path):
    """The 2-D grid table (Y = u - 5 v|v| + 0.3 u v) with a sway model fitted by the CLI."""
    path = tmp_path / "d.db"
    table = tmp_path / "grid.csv"
    write_grid_table(table)
    run_cli(path, "import", str(table), "--body", "grid")
    run_cli(path, "derivatives", "fit", "--body", "grid", "--output", "Y", "--terms", TERMS, "--name", "sway")
    return path


def test_fit_gives_the_cli_numbers(grid_db, tmp_path):
    with hydrocoef.Database(grid_db) as db:
        ours = hydrocoef.fit_derivative_model(db, body="grid", output="Y", terms=TERMS, store=False)
    theirs = cli_json(grid_db, "derivatives", "show", "sway")
    assert [c.value for c in ours.coefficients] == [c["value"] for c in theirs["coefficients"]]
    assert [c.std_error for c in ours.coefficients] == [c["std_error"] for c in theirs["coefficients"]]
    assert ours.covariance == theirs["covariance"]
    assert ours.id == 0
    # The grid's own model: u - 5 v|v| + 0.3 u v, and no v.
    values = {c.term: c.value for c in ours.coefficients}
    assert values["u"] == pytest.approx(1.0, abs=1e-9)
    assert values["v*|v|"] == pytest.approx(-5.0, abs=1e-9)
    assert values["u*v"] == pytest.approx(0.3, abs=1e-9)
    assert values["v"] == pytest.approx(0.0, abs=1e-9)


def test_list_show_evaluate_and_delete_give_the_cli_json(grid_db):
    with hydrocoef.Database(grid_db) as db:
        listed = hydrocoef.list_derivative_models(db)
        assert json.loads(listed.json()) == cli_json(grid_db, "derivatives", "list")
        prime = hydrocoef.show_derivative_model(db, "sway", form="prime", length=2.0, speed=1.5, density=1025.0)
        theirs = cli_json(grid_db, "derivatives", "show", "sway", "--form", "prime", "--length", "2",
                          "--speed", "1.5", "--density", "1025")
        assert json.loads(prime.json()) == theirs
        assert prime.form == "prime"
        assert all(c.normalisation.startswith("prime (SNAME 1950)") for c in prime.coefficients)
        value = hydrocoef.evaluate_derivative_model(db, "sway", {"u": 0.2, "v": -0.1})
        at = cli_json(grid_db, "derivatives", "evaluate", "sway", "--at", "u=0.2", "--at", "v=-0.1")
        assert value.value == at["value"]
        assert value.std_error == at["std_error"]
        assert value.value == pytest.approx(0.2 - 5 * -0.1 * 0.1 + 0.3 * 0.2 * -0.1, abs=1e-9)
        message = cli_error(grid_db, "derivatives", "show", "sway", "--form", "bis", "--length", "2")
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.show_derivative_model(db, "sway", form="bis", length=2.0)
        assert str(refused.value) == message
        deleted = hydrocoef.delete_derivative_model(db, "sway")
        assert deleted.name == "sway"
        assert hydrocoef.list_derivative_models(db).models == []
