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


def test_objects_without_their_cpp_part_are_refused(db_path):
    """pybind11 would run a method of an object made by __new__ alone on
    uninitialised memory: such objects are refused, never used."""
    import copy
    bare = hydrocoef.Database.__new__(hydrocoef.Database)
    for call in (lambda: bare.runs(), lambda: bare.close(), lambda: bare.path, lambda: repr(bare),
                 lambda: bare.surface("x"), lambda: bare.import_files("x"), lambda: bare.__enter__()):
        with pytest.raises(TypeError, match="__new__ without __init__"):
            call()
    # Each class's refusal names the call that makes its objects.
    made_by = {hydrocoef.Surface: r"Database\.surface\(name\)", hydrocoef.Fit: r"Database\.fit\(",
               hydrocoef.SurfaceInfo: r"Database\.surfaces\(\)", hydrocoef.ImportedFile: r"import_files",
               hydrocoef.ImportSummary: r"import_files", hydrocoef.RunDetails: r"Database\.show_run",
               hydrocoef.DeleteSummary: r"Database\.delete_runs", hydrocoef.MergeSummary: r"Database\.merge",
               hydrocoef.LevelFits: r"fit_by_level", hydrocoef.Refits: r"Database\.refit",
               hydrocoef.PlotFiles: r"plot_fit", hydrocoef.DerivativeModel: r"fit_derivative_model",
               hydrocoef.GciStudy: r"grid_convergence"}
    for cls, maker in made_by.items():
        with pytest.raises(TypeError, match=rf"hydrocoef\.{cls.__name__} objects come from .*{maker}"):
            cls.__new__(cls)
        with pytest.raises(TypeError):
            cls()
    with hydrocoef.Database(db_path, mode="r") as db:
        surface = db.surface("asr-v-yaw")
        with pytest.raises(TypeError):
            copy.copy(surface)
        with pytest.raises(TypeError):
            copy.copy(db)
    assert surface(r=0.1)["N"] < 0


VALUE_CLASSES = (hydrocoef.Surface, hydrocoef.Fit, hydrocoef.SurfaceInfo, hydrocoef.ImportedFile,
                 hydrocoef.ImportSummary)


def test_no_value_object_without_its_cpp_part(db_path):
    """Every way to __new__ a Surface, Fit, ... (its own, object's, its
    pybind11 base's, a subclass's) raises TypeError: an object without its
    C++ part, on which a method or repr() would crash the interpreter, never
    exists."""
    for cls in VALUE_CLASSES:
        base = cls.__mro__[1]
        for make in (lambda: cls(), lambda: cls.__new__(cls), lambda: object.__new__(cls),
                     lambda: base.__new__(cls), lambda: super(cls, cls).__new__(cls)):
            with pytest.raises(TypeError):
                made = make()
                repr(made)  # not reached; it would crash if it were
        with pytest.raises(TypeError):
            type("Sub", (cls,), {})  # final: no subclass could reach the base's __new__
    with hydrocoef.Database(db_path, mode="r") as db:
        surface = db.surface("asr-v-yaw")
        assert repr(surface).startswith("<hydrocoef.Surface 'asr-v-yaw'")
        assert surface.name == "asr-v-yaw" and surface.axes == ["r"]
        assert surface(r=0.1)["N"] < 0


def test_database_methods_refuse_an_object_without_its_database(db_path):
    """A Database made by __new__ alone (its own, object's, or its pybind11
    base's): every method, property and repr raises TypeError; so does a
    method given an object of another type as self."""
    compiled = hydrocoef._hydrocoef.Database
    for bare in (compiled.__new__(compiled), compiled.__mro__[1].__new__(compiled),
                 hydrocoef.Database.__mro__[2].__new__(hydrocoef.Database)):
        calls = [lambda: repr(bare), lambda: bare.path, lambda: bare.closed, lambda: bare.read_only,
                 lambda: bare.close(), lambda: bare.__enter__(), lambda: bare.__exit__(None, None, None),
                 lambda: bare.surface("x"), lambda: bare.surfaces(), lambda: bare.fits(),
                 lambda: bare.import_files("x"), lambda: bare.rebuild_surfaces()]
        if hasattr(bare, "runs"):
            calls.append(lambda: bare.runs())
        for call in calls:
            with pytest.raises(TypeError, match="__new__ without __init__"):
                call()
    for method in ("close", "surfaces", "__repr__"):
        with pytest.raises(TypeError, match="expected a hydrocoef.Database, got int"):
            getattr(compiled, method)(5)
    with pytest.raises(TypeError, match="expected a hydrocoef.Database"):
        compiled.path.fget("not a database")


def test_init_runs_once(db_path, tmp_path):
    """__init__ on a Database that was opened already (open or closed) raises
    instead of being ignored; the object keeps its first database."""
    other = tmp_path / "other.db"
    db = hydrocoef.Database(db_path, mode="r")
    with pytest.raises(RuntimeError, match="opened already"):
        db.__init__(other)
    with pytest.raises(RuntimeError, match="opened already"):
        hydrocoef._hydrocoef.Database.__init__(db, other, "create")
    assert not other.exists()
    assert db.path.endswith(db_path.name) and db.read_only
    assert db.surface("asr-v-yaw").name == "asr-v-yaw"
    db.close()
    with pytest.raises(RuntimeError, match="opened already"):
        db.__init__(db_path)
    assert db.closed
    # __init__ on an object made by __new__ alone opens it, once.
    bare = hydrocoef.Database.__new__(hydrocoef.Database)
    bare.__init__(db_path, "r")
    assert bare.surface("asr-v-yaw").name == "asr-v-yaw"
    with pytest.raises(RuntimeError, match="opened already"):
        bare.__init__(db_path, "r")
    bare.close()
