"""integrate_surface: one surface export's forces and moments, as `hydrocoef integrate` prints them."""

import json
import pathlib

import pytest

import hydrocoef
from conftest import cli_error, run_cli

SPHERE = pathlib.Path(__file__).resolve().parents[2] / "data" / "openfoam-sphere" / "full" / "u0.10_v0.05"
FILE = SPHERE / "u0.10_v0.05_sphere_t1000.vtp"


def test_integrate_gives_the_cli_numbers(tmp_path):
    result = hydrocoef.integrate_surface(FILE, settings={"rho": 998.2})
    _, out, _ = run_cli(tmp_path / "unused.db", "integrate", str(FILE), "--rho", "998.2", "--json")
    cli = json.loads(out)
    # The same document but for where each setting came from (--rho there, the settings map here).
    mine = json.loads(result.json())
    assert mine.pop("settings")["rho"]["value"] == cli.pop("settings")["rho"]["value"] == 998.2
    assert mine == cli
    assert list(result.force) == cli["force"] and list(result.moment) == cli["moment"]
    assert result.closed and result.faces == cli["faces"]
    # The solver's own forces (its forces function object) in the file's axes.
    with open(SPHERE / "case.json") as f:
        own = json.load(f)["openfoam_final_force_N"]["total"]
    assert result.force == pytest.approx(own, abs=2e-6)
    _, text, _ = run_cli(tmp_path / "unused.db", "integrate", str(FILE), "--rho", "998.2")
    def without_origins(lines):
        return [line for line in lines.splitlines() if not line.startswith("  setting ")]
    assert without_origins(result.text()) == without_origins(text)
    assert not (tmp_path / "unused.db").exists()  # nothing stored


def test_integrate_refuses_with_the_cli_message(tmp_path):
    with pytest.raises(hydrocoef.InputError) as error:
        hydrocoef.integrate_surface(FILE, settings={"rho": 998.2, "pressure": "NoSuchArray"})
    assert str(error.value) == cli_error(tmp_path / "unused.db", "integrate", str(FILE), "--rho", "998.2",
                                         "--pressure", "NoSuchArray")
