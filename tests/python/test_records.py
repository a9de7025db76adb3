"""The records' operations from Python give what the CLI prints with --json on the same database: an
import, one run, fits (weighted or not, per level, refit, list, evaluated), delete, merge, copy and report."""

import json
import math
import shutil

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, cli_error, cli_json, run_cli, write_grid_table

SURGE = ASR_V / "asr-v-surge-damping.csv"
SURGE_SETTINGS = {"sign": "opposing", "rho": 998.2, "nu": 1.004e-6, "uncertainty": "X=2%"}


@pytest.fixture
def records_db(tmp_path):
    """The surge table (2 % uncertainty on X) and a 2-D grid table, imported from Python."""
    path = tmp_path / "records.db"
    with hydrocoef.Database(path) as db:
        db.import_files(SURGE, body="asr-v", settings=SURGE_SETTINGS)
        table = tmp_path / "grid.csv"
        write_grid_table(table)
        db.import_files(table, body="grid")
    return path


def test_import_gives_the_cli_json(tmp_path):
    with hydrocoef.Database(tmp_path / "py.db") as db:
        summary = db.import_files(SURGE, body="asr-v", settings={"sign": "opposing", "rho": 998.2})
    ours = json.loads(summary.json())
    theirs = cli_json(tmp_path / "cli.db", "import", str(SURGE), "--body", "asr-v", "--sign", "opposing",
                      "--rho", "998.2")
    assert ours["summary"] == theirs["summary"]
    assert ours["summary"]["runs_created"] == summary.runs_created == 20
    assert [f["sha256"] for f in ours["files"]] == [f["sha256"] for f in theirs["files"]]
    assert ours["files"][0]["runs_in_file"] == 20
    assert summary.text(quiet=True) == f"imported 1 input into {tmp_path / 'py.db'}: 20 new runs, 0 extended, " \
                                       "0 already imported, 0 notes\n"


def test_runs_and_one_run_give_the_cli_json(records_db):
    with hydrocoef.Database(records_db, mode="r") as db:
        runs = db.runs(body="asr-v")
        details = db.show_run(int(runs["id"][5]))
        shown = json.loads(details.json())
    listed = cli_json(records_db, "runs", "--body", "asr-v")
    assert list(runs["id"]) == [r["id"] for r in listed]
    # Forces on the body: the magnitudes as tabulated negated.
    assert list(runs["X"]) == [-r["forces"]["X"]["total"] for r in listed]
    assert shown == cli_json(records_db, "runs", "show", str(runs["id"][5]))
    assert details.force[0] == 0.11278 and details.sign_convention[0] == "opposing"
    assert details.imports[0]["importer"] == "force-table"


def test_fits_give_the_cli_json_weighted_or_not(records_db):
    args = ["fit", "--body", "asr-v", "--dof", "X", "--terms", "1,u,u|u|", "--no-store"]
    with hydrocoef.Database(records_db) as db:
        weighted = db.fit(body="asr-v", output="X", terms="1,u,u|u|", store=False)
        plain = db.fit(body="asr-v", output="X", terms="1,u,u|u|", store=False, weighted=False)
    assert json.loads(weighted.json()) == cli_json(records_db, *args)
    assert json.loads(plain.json()) == cli_json(records_db, *args, "--unweighted")
    assert weighted.weighting == "uncertainty" and plain.weighting == "none"
    assert math.isnan(plain.chi2_reduced) and weighted.chi2_reduced > 0
    assert weighted.covariance.shape == (3, 3)
    assert np.allclose(np.sqrt(np.diag(weighted.covariance)), list(weighted.std_errors.values()), rtol=1e-12)
    assert plain.coefficients["u|u|"] == pytest.approx(11.0364, abs=1e-4)  # README, paper eq. 5


def test_per_level_fits_give_the_cli_json(records_db):
    with hydrocoef.Database(records_db) as db:
        levels = db.fit_by_level(body="grid", output="X", terms="1,u|u|", by="v", curve="polynomial:1", store=False)
    theirs = cli_json(records_db, "fit", "--body", "grid", "--dof", "X", "--terms", "1,u|u|", "--by", "v",
                      "--curve", "polynomial:1", "--no-store")
    assert json.loads(levels.json()) == theirs
    assert len(levels.levels) == 20
    # X = -10 u|u| - 2 v: the constant is -2 v at each level, u|u|'s coefficient -10.
    assert levels.curves["1"]["polynomial"][1] == pytest.approx(-2.0, abs=1e-9)
    assert levels.levels[0].coefficients["u|u|"] == pytest.approx(-10.0, abs=1e-9)


def test_stored_fit_evaluated_with_its_standard_error(records_db):
    with hydrocoef.Database(records_db) as db:
        fit = db.fit(body="asr-v", output="X", terms="1,u,u|u|")
        at = np.array([0.0, 0.1, 0.38, 0.5])
        law = db.evaluate_fit(fit.name, at)
        listed = [json.loads(f.json()) for f in db.fits()]
    assert json.loads(law.json()) == cli_json(records_db, "fits", "evaluate", fit.name, "--at", "0,0.1,0.38,0.5")
    assert listed == cli_json(records_db, "fits")
    c = np.array(list(fit.coefficients.values()))
    basis = np.stack([np.ones_like(at), at, at * np.abs(at)], axis=1)
    assert np.allclose(law.value, basis @ c, rtol=0, atol=1e-13)
    assert np.allclose(law.std_error, np.sqrt(np.einsum("ik,kl,il->i", basis, fit.covariance, basis)), rtol=1e-12)
    assert law.std_error[0] == pytest.approx(fit.std_errors["1"], rel=1e-12)
    assert law.fitted_range == (0.0, 0.38)
    assert law.std_error[3] > law.std_error[2]  # beyond the runs the band widens
    with hydrocoef.Database(records_db, mode="r") as db:
        with pytest.raises(hydrocoef.InputError) as error:
            db.evaluate_fit("nope", 0.1)
    assert str(error.value) == cli_error(records_db, "fits", "evaluate", "nope", "--at", "0.1")


def test_delete_and_refit_give_the_cli_json(records_db, tmp_path):
    cli_db = tmp_path / "cli.db"
    with hydrocoef.Database(records_db) as db:
        db.fit(body="asr-v", output="X", terms="1,u,u|u|", weighted=False)
    shutil.copy(records_db, cli_db)
    with hydrocoef.Database(records_db) as db:
        run = int(db.runs(where=["u=0.38"], body="asr-v")["id"][0])
        deleted = db.delete_runs([run])
        assert json.loads(deleted.json()) == cli_json(cli_db, "runs", "delete", str(run))
        assert deleted.runs == 1 and deleted.fits_made_stale == 1
        refits = db.refit()
        assert json.loads(refits.json()) == cli_json(cli_db, "fit", "--refit")
        assert len(refits.made[0].runs) == 19 and len(refits.previous[0].runs) == 20
        with pytest.raises(hydrocoef.InputError) as error:
            db.delete_runs()
    assert str(error.value) == cli_error(cli_db, "runs", "delete")


def test_merge_copy_and_report_as_the_cli(records_db, tmp_path):
    with hydrocoef.Database(tmp_path / "merged.db") as db:
        merged = db.merge([records_db])
    theirs = cli_json(tmp_path / "merged-cli.db", "merge", str(records_db))
    assert json.loads(merged.json())["shards"] == theirs["shards"]
    assert merged.shards[0]["runs_created"] == 20 + 400
    with hydrocoef.Database(records_db, mode="r") as source, hydrocoef.Database(tmp_path / "copy.db") as target:
        copied = source.copy_to(target)
        assert copied.rows == cli_json(records_db, "copy", "--from", str(records_db), "--to",
                                       str(tmp_path / "copy-cli.db"))["rows"]
        report = source.report(tmp_path / "report", body="asr-v")
    theirs = cli_json(records_db, "report", "-o", str(tmp_path / "report-cli"), "--body", "asr-v")
    ours = json.loads(report.json())
    for key in ("runs", "fits", "surfaces", "histories", "mesh_study_rows", "pmm_fits"):
        assert ours[key] == theirs[key], key
    assert report.runs == 20 and (tmp_path / "report" / "index.html").exists()
