"""Database.export_forcecoeffs gives what `hydrocoef export --format openfoam-forcecoeffs --json` prints on the
same database (the OpenFOAM sphere runs of data/openfoam-sphere/cases, with the sphere's frontal area and
length), writes the CLI's files byte for byte, and refuses with the CLI's message."""

import json
import math
from pathlib import Path

import pytest

import hydrocoef
from conftest import SOURCE_DIR, cli_error, cli_json

CASES = sorted((SOURCE_DIR / "data" / "openfoam-sphere" / "cases").iterdir())
FRONTAL = math.pi * 0.15 ** 2


@pytest.fixture
def sphere_db(tmp_path):
    path = tmp_path / "sphere.db"
    with hydrocoef.Database(path, mode="create") as db:
        db.import_files(CASES, body="sphere", settings={"axes": "-x,y,-z"})
        hydrocoef.set_body_reference(db, "sphere", length=0.3, areas={"frontal": FRONTAL})
    return path


def test_export_gives_the_cli_json_and_files(sphere_db, tmp_path):
    theirs = cli_json(sphere_db, "export", "--format", "openfoam-forcecoeffs", "-o", str(tmp_path / "cli"))
    with hydrocoef.Database(sphere_db, mode="r") as db:
        ours = db.export_forcecoeffs(output=tmp_path / "py")
    assert [r.id for r in ours.runs] == [r["id"] for r in theirs["runs"]]
    assert (ours.values, ours.exact, ours.one_ulp) == (theirs["values"], theirs["exact"], theirs["one_ulp"])
    assert ours.exact + ours.one_ulp == ours.values == 6 * len(CASES)
    for run, their in zip(ours.runs, theirs["runs"]):
        assert run.axes == "-x,y,-z" and run.rho == their["rho"] == 998.2
        names = ["Cd", "Cs", "Cl", "CmRoll", "CmPitch", "CmYaw"]
        assert list(run.last_coefficients) == [their["last_coefficients"][name] for name in names]
        relative = Path(run.file).relative_to(tmp_path / "py")
        assert Path(run.file).read_bytes() == (tmp_path / "cli" / relative).read_bytes()
        assert run.last_coefficients[0] > 0.1  # the drag along the case's +x
    assert json.loads(ours.json())["convention"] == theirs["convention"]


def test_export_refuses_with_the_cli_message(sphere_db, tmp_path):
    with hydrocoef.Database(sphere_db, mode="r") as db:
        with pytest.raises(hydrocoef.InputError) as error:
            db.export_forcecoeffs(output=tmp_path / "out", precision=17)
    assert str(error.value) == cli_error(sphere_db, "export", "--format", "openfoam-forcecoeffs", "-o",
                                         str(tmp_path / "out"), "--precision", "17")
    assert not (tmp_path / "out").exists()
