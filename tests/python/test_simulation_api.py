"""simulate with samples and an experiment, and equilibrium: the numbers the
CLI's --json prints, through the module; the Monte Carlo example runs."""

import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import hydrocoef
from conftest import ASR_V, cli_error, run_cli

FIT = "asr-v:N(1,r,r|r|)"
EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "monte_carlo.py"


def commented_json(path):
    with open(path) as f:
        return json.loads("".join(line for line in f if not line.lstrip().startswith("//")))


def without_wall_times(doc):
    if isinstance(doc, dict):
        return {k: without_wall_times(v) for k, v in doc.items() if k != "wall_time_s"}
    return doc


@pytest.fixture(scope="module")
def fitted(tmp_path_factory):
    """A database with the yaw law fitted, and a vehicle file naming it (its covariance is drawn)."""
    folder = tmp_path_factory.mktemp("mc")
    path = folder / "mc.db"
    with hydrocoef.Database(path, mode="create") as db:
        db.import_files(ASR_V / "asr-v-yaw-damping.csv", body="asr-v", settings={"sign": "on-body", "rho": 998.2})
        assert db.fit(body="asr-v", output="N", terms="1,r,r|r|").name == FIT
    vehicle = commented_json(ASR_V / "vehicle.json")
    vehicle["damping"]["N"] = {"fit": FIT}
    vehicle_path = folder / "vehicle-fit.json"
    vehicle_path.write_text(json.dumps(vehicle))
    scenario = commented_json(ASR_V / "scenario-yaw-0.0027.json")
    scenario["duration"] = 3.0
    scenario_path = folder / "short.json"
    scenario_path.write_text(json.dumps(scenario))
    return path, vehicle_path, scenario_path


def test_simulate_with_samples_gives_the_cli_numbers(fitted, tmp_path):
    db, vehicle, scenario = fitted
    measured = tmp_path / "measured.csv"
    run_cli(db, "simulate", "--vehicle", str(vehicle), "--scenario", str(scenario), "--out", str(measured))
    run = hydrocoef.simulate(vehicle, scenario, db, experiment=measured, samples=10, seed=5,
                             percentiles=[10, 50, 90])
    _, out, _ = run_cli(db, "simulate", "--vehicle", str(vehicle), "--scenario", str(scenario), "--experiment",
                        str(measured), "--samples", "10", "--seed", "5", "--percentiles", "10,50,90", "--json")
    cli = json.loads(out)
    assert without_wall_times(run.json()) == without_wall_times(cli)
    assert run.steps == cli["steps"]
    assert run["r"][-1] == cli["final"]["velocity"]["r"]
    assert [c["rms_error"] for c in run.comparison] == [c["rms_error"] for c in cli["comparison"]]
    final = cli["monte_carlo"]["final"]["percentiles"]["r"]
    np.testing.assert_array_equal(run.bands["r"][:, -1], [final["p10"], final["p50"], final["p90"]])
    assert run.bands["r"][0, -1] < run.bands["r"][2, -1]
    assert run.band_t[-1] == 3.0 and run.monte_carlo["used"] == 10
    assert run.measured_inside_band["r"] == cli["monte_carlo"]["measured_inside_band"]["r"]


def test_equilibrium_gives_the_cli_numbers(fitted):
    db, vehicle, _ = fitted
    eq = hydrocoef.equilibrium(vehicle, db, tau={"N": 0.0027}, samples=30, seed=2)
    _, out, _ = run_cli(db, "equilibrium", "--vehicle", str(vehicle), "--tau", "N=0.0027", "--samples", "30",
                        "--seed", "2", "--json")
    cli = json.loads(out)
    assert without_wall_times(eq.json()) == without_wall_times(cli)
    assert eq.velocity == cli["velocity"] and eq.damping == cli["damping"]
    assert eq.mean == cli["monte_carlo"]["mean"]
    assert eq.velocity_percentiles[97.5] == cli["monte_carlo"]["velocity_percentiles"]["p97.5"]
    assert abs(eq.damping["N"] + 0.0027) < 1e-9
    # Refusals carry the CLI's message.
    with pytest.raises(hydrocoef.InputError) as error:
        hydrocoef.equilibrium(vehicle, db, tau={"Q": 1.0})
    assert str(error.value) == cli_error(db, "equilibrium", "--vehicle", str(vehicle), "--tau", "Q=1")


def test_monte_carlo_example_runs(fitted, tmp_path):
    db, vehicle, _ = fitted
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(hydrocoef.__file__).resolve().parents[1]))
    result = subprocess.run([sys.executable, str(EXAMPLE), "--db", str(tmp_path / "example.db"), "--samples", "50"],
                            capture_output=True, text=True, env=env, check=True)
    lines = result.stdout.splitlines()
    steady = lines[0].split()
    r, low, high = float(steady[3]), float(steady[8].strip("[,")), float(steady[9].rstrip("]"))
    assert low < r < high
    # The steady rate is the CLI's for the same fit.
    _, out, _ = run_cli(db, "equilibrium", "--vehicle", str(vehicle), "--tau", "N=0.0027", "--json")
    assert r == pytest.approx(json.loads(out)["velocity"]["r"], abs=5e-7)  # printed to 6 decimals
    band = [float(lines[1].split(f"{name} ")[1].split()[0].rstrip(",")) for name in ("p5", "p50", "p95")]
    assert band[0] < band[1] < band[2]


def test_plots_write_what_the_cli_writes(fitted, tmp_path):
    db, vehicle, _ = fitted
    with hydrocoef.Database(db, mode="r") as database:
        files = hydrocoef.plot_fit(database, FIT, image=tmp_path / "py-fit.svg")
    _, out, _ = run_cli(db, "plot", "fit", FIT, "-o", str(tmp_path / "cli-fit.svg"), "--json")
    cli = json.loads(out)
    assert files.format == "svg" and files.title == cli["title"]
    assert [s["points"] for s in files.series] == [s["points"] for s in cli["series"]]
    assert pathlib.Path(files.data).read_text() == pathlib.Path(cli["data"]).read_text()
    steady = hydrocoef.plot_steady(str(vehicle), db, tau_from=0.001, tau_to=0.004, count=4,
                                   image=tmp_path / "py-steady.svg")
    run_cli(db, "plot", "steady", "--vehicle", str(vehicle), "--tau-from", "0.001", "--tau-to", "0.004", "--count",
            "4", "-o", str(tmp_path / "cli-steady.svg"))
    assert pathlib.Path(steady.data).read_text() == (tmp_path / "cli-steady.dat").read_text()
    with pytest.raises(hydrocoef.InputError) as error:
        hydrocoef.plot_history(hydrocoef.Database(db, mode="r"), 999)
    assert str(error.value) == cli_error(db, "plot", "history", "999")
