"""Database: runs as numpy columns, imports, fits, as the CLI gives them."""

import json
import os
import subprocess

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, cli_json, run_cli


def test_runs_are_numpy_columns_of_forces_on_the_body(db):
    runs = db.runs(body="asr-v")
    assert isinstance(runs, hydrocoef.Table)
    assert list(runs)[:8] == ["id", "body", "u", "v", "w", "p", "q", "r"]
    assert runs["id"].dtype == np.int64 and runs["u"].dtype == np.float64
    assert len(runs["id"]) == 39 and set(runs["body"]) == {"asr-v"}
    at = np.flatnonzero(np.isclose(runs["u"], 0.10))[0]
    assert runs["X"][at] == -0.11278  # a magnitude as tabulated, on the body
    assert np.isnan(runs["N"][at]) and np.isnan(runs["X_std_error"][at])
    assert "asr-v-surge-damping.csv" in runs["source"][at]
    assert runs["history_flags"][at] == ""
    fast = db.runs(where=["u>=0.3"], body="asr-v")["id"]
    assert len(fast) == 5
    assert list(db.runs(where="u>=0.3", body="asr-v", exclude_runs=[int(fast[0])])["id"]) == list(fast[1:])
    assert len(db.runs()["id"]) == 39 + 400


def test_runs_match_the_cli_csv(db, db_path):
    runs = db.runs(body="grid")
    csv = run_cli(db_path, "runs", "--body", "grid", "--csv")[1].splitlines()
    header = csv[0].split(",")
    rows = [line.split(",") for line in csv[1:]]
    assert len(rows) == len(runs["id"])
    for name in ("u", "v", "X", "Y"):
        column = header.index(name)
        np.testing.assert_array_equal(runs[name], [float(row[column]) for row in rows])


def test_to_pandas(db, monkeypatch):
    runs = db.runs(body="asr-v")
    try:
        import pandas
    except ImportError:
        # Without pandas: a clear ImportError; with a stand-in, the columns go to DataFrame as a dict.
        with pytest.raises(ImportError, match="python3-pandas"):
            runs.to_pandas()
        import sys
        import types
        stand_in = types.ModuleType("pandas")
        stand_in.DataFrame = lambda columns: ("frame", columns)
        monkeypatch.setitem(sys.modules, "pandas", stand_in)
        kind, columns = runs.to_pandas()
        assert kind == "frame" and list(columns) == list(runs) and columns["X"] is runs["X"]
        return
    frame = runs.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == 39
    np.testing.assert_array_equal(frame["X"].to_numpy(), runs["X"])


def test_import_summary_and_identity(tmp_path):
    with hydrocoef.Database(tmp_path / "i.db") as db:
        settings = {"sign": "opposing", "rho": 998.2}
        first = db.import_files([ASR_V / "asr-v-surge-damping.csv"], body="asr-v", settings=settings)
        assert first.runs_created == 20 and first.files[0].format == "table" and first.files[0].runs == 20
        again = db.import_files([str(ASR_V / "asr-v-surge-damping.csv")], body="asr-v", settings=settings)
        assert again.already_imported == 1 and again.runs_created == 0
        # Other settings of the same file: refused unless replace.
        with pytest.raises(hydrocoef.InputError, match="rho"):
            db.import_files(ASR_V / "asr-v-surge-damping.csv", body="asr-v", settings={"sign": "opposing", "rho": 1000})
        replaced = db.import_files(ASR_V / "asr-v-surge-damping.csv", body="asr-v",
                                   settings={"sign": "opposing", "rho": 1000}, replace=True)
        assert replaced.files[0].replaced
    # The CLI sees the same import: the same file with the same settings adds nothing.
    code, out, _ = run_cli(tmp_path / "i.db", "import", str(ASR_V / "asr-v-surge-damping.csv"), "--body", "asr-v",
                           "--sign", "opposing", "--rho", "1000", "--json")
    assert json.loads(out)["summary"]["already_imported"] == 1


def test_fit_is_the_cli_fit(db_path, tmp_path):
    copy = tmp_path / "fit.db"
    copy.write_bytes(db_path.read_bytes())
    with hydrocoef.Database(copy, mode="rw") as db:
        fit = db.fit(body="asr-v", output="N", terms="1,r,r|r|")
        assert fit.name == "asr-v:N(1,r,r|r|)" and fit.id > 0 and fit.n == 20
        assert fit.sign_convention == "on-body"
        expected = cli_json(copy, "fit", "--body", "asr-v", "--dof", "N", "--terms", "1,r,r|r|", "--no-store")
        assert fit.coefficients == expected["coefficients"]
        assert fit.std_errors == expected["std_errors"]
        assert fit.units == expected["units"]
        assert fit.rmse == expected["rmse"] and fit.r2 == expected["r2"]
        # README: N(r) = 1.89812e-05 - 0.00607516 r - 0.0771371 r|r|
        assert fit.coefficients["r"] == pytest.approx(-0.00607516, rel=1e-5)
        assert [f.name for f in db.fits()] == ["asr-v:N(1,r,r|r|)"]
        assert db.fits()[0].coefficients == fit.coefficients
        with pytest.raises(hydrocoef.InputError, match="asr-v:N"):
            db.fit(body="asr-v", output="N", terms="1,r,r|r|")
        dry = db.fit(body="asr-v", output="X", terms="u,u|u|", where=["u<=0.2"], store=False)
        assert dry.id == 0 and dry.where == "u<=0.2" and len(db.fits()) == 1
        assert "Fit" in repr(dry)


def test_build_and_rebuild_surface_are_the_cli_ones(tmp_path):
    path = tmp_path / "s.db"
    with hydrocoef.Database(path) as db:
        db.import_files([ASR_V / "asr-v-surge-damping.csv"], body="asr-v", settings={"sign": "opposing"})
        info = db.build_surface("surge", body="asr-v", axes="u", outputs="X", method="pchip",
                                extrapolate="linear", where=["u<=0.5"])
        assert info.name == "surge" and info.method == "pchip" and not info.stale and info.run_count > 5
        with pytest.raises(hydrocoef.InputError, match="give --replace"):
            db.build_surface("surge", body="asr-v", axes="u", outputs="X")
        s = db.surface("surge")
        u = np.array([0.05, 0.25])
        mine = s(u=u)["X"]
    # The CLI answers the same at the same points, and lists what it was built from.
    for k, value in enumerate(u):
        assert cli_json(path, "query", "surge", f"u={value!r}")["values"]["X"] == mine[k]
    listed = run_cli(path, "surface", "list")[1]
    assert "u<=0.5" in listed
    # A run changes: the surface is stale, the rebuild from its stored specification has the new value.
    (tmp_path / "one.csv").write_text("u [m s^-1],X [N]\n0.04,1.5\n")
    with hydrocoef.Database(path) as db:
        db.import_files([tmp_path / "one.csv"], body="asr-v", settings={"sign": "opposing"}, replace=True)
        assert db.surfaces()[0].stale
        rebuilt = db.rebuild_surfaces(stale_only=True)
        assert [r.name for r in rebuilt] == ["surge"] and not rebuilt[0].stale
        assert db.surface("surge")(u=np.array([0.04]))["X"][0] == -1.5


def test_a_team_database_on_postgresql_gives_what_an_sqlite_file_gives(tmp_path):
    """hydrocoef.Database takes a postgresql:// URL as --db does: on a schema of
    its own on the test server (scripts/postgresql-test-server.sh), the same
    import, runs, fit and surface as in an SQLite file."""
    server = os.environ.get("HYDROCOEF_TEST_POSTGRESQL")
    if not server:
        if os.environ.get("HYDROCOEF_TEST_POSTGRESQL_REQUIRED"):
            pytest.fail("HYDROCOEF_TEST_POSTGRESQL is not set (scripts/postgresql-test-server.sh starts one)")
        pytest.skip("no PostgreSQL test server: HYDROCOEF_TEST_POSTGRESQL is not set")
    schema = f"py_{os.getpid()}"
    psql = ["psql", "-q", "-v", "ON_ERROR_STOP=1", server, "-c"]
    subprocess.run(psql + [f"DROP SCHEMA IF EXISTS {schema} CASCADE; CREATE SCHEMA {schema}"], check=True)
    url = server + ("&" if "?" in server else "?") + f"options=-csearch_path%3D{schema}"
    try:
        results = []
        for location in (url, tmp_path / "same.db"):
            with hydrocoef.Database(location) as db:
                summary = db.import_files([ASR_V / "asr-v-yaw-damping.csv"], body="asr-v", settings={"sign": "on-body"})
                assert summary.runs_created == 20
                fit = db.fit(body="asr-v", output="N", terms="1,r,r|r|")
                runs = db.runs(body="asr-v")
                results.append((runs["r"], runs["N"], fit.coefficients, fit.std_errors, [f.name for f in db.fits()]))
            # The CLI reads what the module wrote.
            assert len(cli_json(location, "runs", "--body", "asr-v")) == 20
        (r_pg, n_pg, c_pg, se_pg, names_pg), (r_sq, n_sq, c_sq, se_sq, names_sq) = results
        np.testing.assert_array_equal(r_pg, r_sq)
        np.testing.assert_array_equal(n_pg, n_sq)
        assert c_pg == c_sq and se_pg == se_sq and names_pg == names_sq == ["asr-v:N(1,r,r|r|)"]
        with pytest.raises(hydrocoef.InputError, match="password"):
            hydrocoef.Database("postgresql://cfd:secret@localhost/team")
    finally:
        subprocess.run(psql + [f"DROP SCHEMA IF EXISTS {schema} CASCADE"], check=False)
