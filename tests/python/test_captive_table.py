"""Captive-test tables in prime or bis form (importers/captive_table.hpp) imported from Python: the same runs as
`hydrocoef import --format captive-table`, the reference values given as keywords standing in for the file's, and a
table without the drift convention it needs refused with the CLI's line."""

import numpy as np
import pytest

import hydrocoef
from conftest import SOURCE_DIR, cli_error, cli_json, run_cli

TABLE = SOURCE_DIR / "data" / "captive-mariner" / "mariner-prime.csv"


def runs_of(db_path):
    with hydrocoef.Database(db_path, mode="r") as db:
        return db.runs()


def test_python_imports_the_runs_the_cli_imports(tmp_path):
    with hydrocoef.Database(tmp_path / "py.db", mode="create") as db:
        summary = db.import_files(TABLE, body="mariner", format="captive-table")
        assert "41 runs" in summary.text()
    run_cli(tmp_path / "cli.db", "import", "--format", "captive-table", str(TABLE), "--body", "mariner")
    ours, theirs = runs_of(tmp_path / "py.db"), runs_of(tmp_path / "cli.db")
    assert ours["id"].size == 41
    for column in ("u", "v", "r", "X", "Y", "N"):
        if column in ours:
            np.testing.assert_array_equal(ours[column], theirs[column], err_msg=column)
    # r = r' U / L: the keyword's length stands in for the file's (line 5), and scales every rate.
    with hydrocoef.Database(tmp_path / "long.db", mode="create") as db:
        db.import_files(TABLE, body="mariner", format="captive-table", length=2 * 160.93)
    longer = runs_of(tmp_path / "long.db")
    turning = np.abs(ours["r"]) > 0
    assert turning.any()
    np.testing.assert_allclose(longer["r"][turning], ours["r"][turning] / 2, rtol=1e-15)


def test_a_table_without_its_drift_convention_is_refused_as_the_cli_refuses_it(tmp_path):
    text = "\n".join(line for line in TABLE.read_text().splitlines() if "drift_convention" not in line) + "\n"
    table = tmp_path / "no-convention.csv"
    table.write_text(text)
    message = cli_error(tmp_path / "cli.db", "import", "--format", "captive-table", str(table), "--body", "m")
    with hydrocoef.Database(tmp_path / "py.db", mode="create") as db:
        with pytest.raises(hydrocoef.InputError) as refused:
            db.import_files(table, body="m", format="captive-table")
        assert db.runs()["id"].size == 0
    assert str(refused.value) == message
