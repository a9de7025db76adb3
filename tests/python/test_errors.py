"""Bad input raises Python exceptions with the CLI's messages; nothing crashes
the interpreter: NaN, out of range, wrong shapes, wrong types, closed databases."""

import math

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, cli_error


def test_input_error_is_a_value_error():
    assert issubclass(hydrocoef.InputError, ValueError)
    assert "hydrocoef: error" in hydrocoef.InputError.__doc__


def test_out_of_range_and_nan_carry_the_cli_message(db, db_path):
    s = db.surface("grid-linear")
    message = cli_error(db_path, "query", "grid-linear", "u=0.7", "v=0")
    with pytest.raises(hydrocoef.InputError) as error:
        s(u=0.7, v=0.0)
    assert str(error.value) == message
    u = np.full(100_000, 0.1)
    u[54_321] = 0.7
    u[60_000] = np.nan
    with pytest.raises(hydrocoef.InputError) as error:
        s(u=u, v=0.0)
    assert str(error.value) == "point 54321: " + message
    u[54_321] = 0.1
    with pytest.raises(hydrocoef.InputError, match=r"^point 60000: axis 'u' = nan"):
        s(u=u, v=0.0)
    with pytest.raises(hydrocoef.InputError, match="'v'"):
        s(u=0.1, v=math.inf)
    with pytest.raises(ValueError):  # as ValueError too
        s(u=np.array([np.nan]), v=0.0)


def test_wrong_shapes_axes_and_types(db):
    s = db.surface("grid-linear")
    with pytest.raises(ValueError, match=r"axes u and v have different shapes \(3,\) and \(4,\)"):
        s(u=np.zeros(3), v=np.zeros(4))
    with pytest.raises(ValueError, match="different shapes"):
        s(u=np.zeros((2, 3)), v=np.zeros(6))
    with pytest.raises(TypeError, match="no value for v; surface 'grid-linear' takes .* u, v"):
        s(u=0.1)
    with pytest.raises(TypeError, match="'w' is not an axis"):
        s(u=0.1, v=0.1, w=0.1)
    with pytest.raises(TypeError, match="positional"):
        s(0.1, 0.1)
    with pytest.raises(TypeError, match="dtype"):
        s(u=np.array(["a", "b"]), v=0.1)
    with pytest.raises(TypeError, match="dtype"):
        s(u=np.array([1 + 2j]), v=0.1)
    with pytest.raises(TypeError):
        s(u=None, v=0.1)
    with pytest.raises(TypeError):
        s(u=object(), v=0.1)
    with pytest.raises(TypeError):
        s(u=np.array([True]), v=0.1)
    with pytest.raises(ValueError, match="threads"):
        s(u=0.1, v=0.1, threads=-1)
    with pytest.raises(TypeError):
        s(u=[[0.1, 0.2], [0.3]], v=0.1)  # ragged
    s(u=[0.1, 0.2], v=(0.0, 0.1))  # sequences are fine


def test_closed_database_raises(db_path):
    db = hydrocoef.Database(db_path, mode="r")
    surface = db.surface("grid-linear")
    db.close()
    assert db.closed
    for call in (lambda: db.runs(), lambda: db.fits(), lambda: db.surfaces(), lambda: db.surface("grid-linear"),
                 lambda: db.fit(body="asr-v", output="X", terms="1,u")):
        with pytest.raises(hydrocoef.InputError) as error:
            call()
        assert str(error.value) == f"{db_path}: database is closed"
    assert surface(u=0.1, v=0.0)["X"] < 0  # read before: still valid
    db.close()
    with hydrocoef.Database(db_path, mode="r") as second:
        pass
    with pytest.raises(hydrocoef.InputError, match="database is closed"):
        second.runs()


def test_database_errors_carry_the_cli_message(db, db_path, tmp_path):
    with pytest.raises(hydrocoef.InputError) as error:
        db.runs(where="u>=abc")
    assert str(error.value) == cli_error(db_path, "runs", "--where", "u>=abc")
    with pytest.raises(hydrocoef.InputError) as error:
        db.surface("nope")
    assert str(error.value) == cli_error(db_path, "query", "nope", "u=1")
    with pytest.raises(hydrocoef.InputError, match="read-only"):
        db.import_files(ASR_V / "asr-v-surge-damping.csv", body="x")
    with pytest.raises(hydrocoef.InputError):
        hydrocoef.Database(tmp_path / "missing.db", mode="rw")
    with pytest.raises(ValueError, match="mode"):
        hydrocoef.Database(tmp_path / "x.db", mode="w")
    not_a_database = tmp_path / "text.db"
    not_a_database.write_text("hello\n" * 100)
    with pytest.raises(hydrocoef.InputError):
        hydrocoef.Database(not_a_database)
    with pytest.raises(TypeError):
        db.runs(where=5)
    with pytest.raises(TypeError):
        db.runs(exclude_runs=["a"])


def test_import_and_fit_errors(tmp_path):
    with hydrocoef.Database(tmp_path / "e.db") as db:
        with pytest.raises(hydrocoef.InputError):
            db.import_files(tmp_path / "missing.csv")
        with pytest.raises(hydrocoef.InputError, match="unknown key 'density'"):
            db.import_files(ASR_V / "asr-v-surge-damping.csv", settings={"density": 1000})
        with pytest.raises(ValueError):
            db.import_files(ASR_V / "asr-v-surge-damping.csv", settings={"rho": math.nan})
        with pytest.raises(TypeError):
            db.import_files(ASR_V / "asr-v-surge-damping.csv", settings=["rho"])
        with pytest.raises(hydrocoef.InputError):
            db.fit(body="nobody", output="X", terms="1,u")
        with pytest.raises(hydrocoef.InputError):
            db.fit(body="b", output="Q", terms="1,u")
        with pytest.raises(hydrocoef.InputError):
            db.fit(body="b", output="X", terms="1,u,zz")
        assert db.runs()["id"].size == 0  # nothing was imported


def test_simulate_errors(db_path, tmp_path):
    scenario = ASR_V / "scenario-yaw-0.0027.json"
    with pytest.raises(hydrocoef.InputError, match="asr-v-surge"):
        hydrocoef.simulate(ASR_V / "vehicle-surfaces.json", scenario)  # surfaces but no database
    with pytest.raises(hydrocoef.InputError):
        hydrocoef.simulate({"mass": -1}, scenario)
    with pytest.raises(hydrocoef.InputError):
        hydrocoef.simulate(tmp_path / "missing.json", scenario)
    with pytest.raises(TypeError):
        hydrocoef.simulate(5, scenario)
