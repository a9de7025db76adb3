"""Derivative exports and scaling from Python give what the CLI gives on the same database:
export_derivatives writes the bytes `hydrocoef derivatives export` writes (csv in the prime form, json, gazebo,
matlab) and its json() is the CLI's --json; scale_surge_resistance gives `hydrocoef scale --json` for points
and for a stored surge law; fit_derivative_model's u0 sets du = u - U0; a refusal is the CLI's message."""
import json

import pytest

import hydrocoef
from conftest import cli_error, cli_json, run_cli, write_grid_table

SHIP = dict(from_length=5, from_area=4, from_viscosity=1.13902e-6, from_density=999.1, to_length=125, to_area=2500,
            to_viscosity=1.18831e-6, to_density=1025.9)
SHIP_ARGS = ["--from-length", "5", "--from-area", "4", "--from-viscosity", "1.13902e-6", "--from-density", "999.1",
             "--to-length", "125", "--to-area", "2500", "--to-viscosity", "1.18831e-6", "--to-density", "1025.9"]


@pytest.fixture
def grid_db(tmp_path):
    """The 2-D grid table (X = -10 u|u| - 2 v, Y = u - 5 v|v| + 0.3 u v) with models fitted by the CLI."""
    path = tmp_path / "d.db"
    table = tmp_path / "grid.csv"
    write_grid_table(table)
    run_cli(path, "import", str(table), "--body", "grid")
    run_cli(path, "derivatives", "fit", "--body", "grid", "--output", "Y", "--terms", "v, v*|v|, u*v", "--name",
            "sway")
    run_cli(path, "derivatives", "fit", "--body", "grid", "--output", "X", "--terms", "u*|u|, v", "--name", "surge")
    surge = tmp_path / "surge.csv"
    surge.write_text("u [m s^-1],X [N]\n" + "".join(f"{u!r},{-2 * u - 12 * u * abs(u)!r}\n"
                                                      for u in (0.3, 0.6, 0.9, 1.2, 1.5)))
    run_cli(path, "import", str(surge), "--body", "model", "--sign", "on-body")
    run_cli(path, "fit", "--body", "model", "--dof", "X", "--terms", "u,u|u|", "--name", "surge-law")
    return path


@pytest.mark.parametrize("names,options,cli", [
    (["sway"], dict(format="csv", form="prime", length=2.0, speed=0.3, density=1000.0),
     ["--format", "csv", "--form", "prime", "--length", "2", "--speed", "0.3", "--density", "1000"]),
    (["sway"], dict(format="json"), ["--format", "json"]),
    (["surge", "sway"], dict(format="gazebo", added_mass="1,2,3,0.1,0.2,0.3"),
     ["--format", "gazebo", "--added-mass", "1,2,3,0.1,0.2,0.3"]),
    (["surge", "sway"], dict(format="matlab", mass_diagonal="20,30,30,1,2,2"),
     ["--format", "matlab", "--mass-diagonal", "20,30,30,1,2,2"]),
])
def test_exports_write_the_cli_bytes(grid_db, tmp_path, names, options, cli):
    suffix = {"csv": ".csv", "json": ".json", "gazebo": ".sdf", "matlab": ".m"}[options["format"]]
    ours_path = tmp_path / ("ours" + suffix)
    theirs_path = tmp_path / ("theirs" + suffix)
    with hydrocoef.Database(grid_db) as db:
        ours = hydrocoef.export_derivatives(db, names, output=ours_path, **options)
    _, out, _ = run_cli(grid_db, "derivatives", "export", *names, *cli, "-o", str(theirs_path), "--json")
    theirs = json.loads(out)
    if options["format"] == "matlab":  # the function is named after the file
        assert ours.function_name == "ours"
        assert theirs["function_name"] == "theirs"
        assert ours_path.read_text().replace("ours", "theirs") == theirs_path.read_text()
    else:
        assert ours_path.read_bytes() == theirs_path.read_bytes()
    assert ours.content == ours_path.read_text()
    assert ours.models == [m["name"] for m in theirs["models"]]
    assert ours.body == theirs["body"] == "grid"
    assert ours.notes == theirs["notes"]


def test_a_refused_export_is_the_cli_message(grid_db, tmp_path):
    with hydrocoef.Database(grid_db) as db:
        with pytest.raises(hydrocoef.InputError) as refused:
            hydrocoef.export_derivatives(db, ["sway", "surge"], format="csv", output=tmp_path / "x.csv")
    assert str(refused.value) == cli_error(grid_db, "derivatives", "export", "sway", "surge", "--format", "csv", "-o",
                                           str(tmp_path / "x.csv"))
    assert not (tmp_path / "x.csv").exists()


def test_scaling_gives_the_cli_numbers(grid_db):
    ours = hydrocoef.scale_surge_resistance(points=[(1.5, -30.0)], wave="froude", form_factor="1.15",
                                            to_roughness=150e-6, **SHIP)
    theirs = cli_json(grid_db, "scale", "--point", "1.5,-30", "--wave", "froude", "--form-factor", "1.15",
                      "--to-roughness", "150e-6", *SHIP_ARGS)
    assert json.loads(ours.json()) == theirs
    assert ours.points[0].resistance_to == pytest.approx(378474.8, rel=5e-7)
    assert ours.points[0].speed_to == pytest.approx(7.5)
    with hydrocoef.Database(grid_db) as db:
        law = hydrocoef.scale_surge_resistance(db, fit="surge-law", speeds=[0.3, 0.9, 1.5], wave="froude",
                                               form_factor="1.1", **SHIP)
    theirs = cli_json(grid_db, "scale", "--fit", "surge-law", "--speeds", "0.3,0.9,1.5", "--wave", "froude",
                      "--form-factor", "1.1", *SHIP_ARGS)
    assert law.coefficients_to == theirs["law"]["coefficients_to"]
    assert json.loads(law.json()) == theirs


def test_u0_sets_du(grid_db):
    with hydrocoef.Database(grid_db) as db:
        model = hydrocoef.fit_derivative_model(db, body="grid", output="X", terms="du^2, v", u0=0.0, store=False)
        with pytest.raises(hydrocoef.InputError, match="--u0"):
            hydrocoef.fit_derivative_model(db, body="grid", output="X", terms="du^2, v", store=False)
    # On u >= 0, du^2 with U0 = 0 is u|u|: X = -10 u|u| - 2 v.
    values = {c.term: c.value for c in model.coefficients}
    assert values["du^2"] == pytest.approx(-10.0, abs=1e-9)
    assert values["v"] == pytest.approx(-2.0, abs=1e-9)
