"""simulate: the trajectory the CLI writes, as numpy columns."""

import json

import numpy as np

import hydrocoef
from conftest import ASR_V, run_cli


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def test_simulate_gives_the_cli_trajectory(db_path, tmp_path):
    scenario = ASR_V / "scenario-yaw-0.0027.json"
    for vehicle in ("vehicle.json", "vehicle-surfaces.json"):
        trajectory = hydrocoef.simulate(ASR_V / vehicle, scenario, database=db_path)
        out = tmp_path / "t.csv"
        run_cli(db_path, "simulate", "--vehicle", str(ASR_V / vehicle), "--scenario", str(scenario), "--out", str(out))
        header, values = read_csv(out)
        assert [name.split(" [")[0] for name in header] == list(trajectory)
        assert trajectory.units["u"] == "m s^-1" and trajectory.units["q_eta"] == ""
        for c, name in enumerate(trajectory):
            np.testing.assert_array_equal(trajectory[name], values[:, c], err_msg=name)
        assert trajectory["t"][-1] == 60.0 and trajectory["r"][-1] > 0.1
    # A dict, and a Database for the surfaces.
    with open(ASR_V / "scenario-yaw-0.0027.json") as f:
        text = f.read()
    scenario_dict = json.loads("\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//")))
    scenario_dict["duration"] = 2.0
    with hydrocoef.Database(db_path, mode="r") as db:
        short = hydrocoef.simulate(ASR_V / "vehicle-surfaces.json", scenario_dict, database=db)
    assert short["t"][-1] == 2.0 and len(short["t"]) == 21
