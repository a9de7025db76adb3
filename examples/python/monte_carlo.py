#!/usr/bin/python3
"""A Monte Carlo band of the ASR-V yaw response from the fitted law's covariance.

The yaw damping law N(r) = c0 + c1 r + c2 r|r| is fitted to the paper's CFD
table (moments on the body, body axes); the vehicle of examples/asr-v/ takes
its yaw damping from that stored fit, so the fit's covariance is what the
draws sample (one draw of the coefficients per run, not per step). Printed:
the steady yaw rate under the pool test's 0.0027 N m with its 95 % interval,
and the yaw rate's 5-50-95 % band at the end of a 20 s run from rest.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/monte_carlo.py --db /tmp/mc.db
"""

import argparse
import json
import pathlib

import hydrocoef

ASR_V = pathlib.Path(__file__).resolve().parents[1] / "asr-v"


def load_commented_json(path):
    """The example's JSON files open with // comment lines."""
    return json.loads("".join(line for line in open(path) if not line.lstrip().startswith("//")))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", required=True)
    parser.add_argument("--samples", type=int, default=200)
    args = parser.parse_args()

    with hydrocoef.Database(args.db, mode="create") as db:
        db.import_files(ASR_V / "asr-v-yaw-damping.csv", body="asr-v", settings={"sign": "on-body", "rho": 998.2})
        fit = db.fit(body="asr-v", output="N", terms="1,r,r|r|", replace=True)

    vehicle = load_commented_json(ASR_V / "vehicle.json")
    vehicle["damping"]["N"] = {"fit": fit.name}
    steady = hydrocoef.equilibrium(vehicle, args.db, tau={"N": 0.0027}, samples=args.samples, seed=1)
    low, high = (steady.velocity_percentiles[p]["r"] for p in (2.5, 97.5))
    print(f"steady r = {steady.velocity['r']:.6f} rad/s, 95 % interval [{low:.6f}, {high:.6f}]")

    scenario = load_commented_json(ASR_V / "scenario-yaw-0.0027.json")
    scenario["duration"] = 20.0
    run = hydrocoef.simulate(vehicle, scenario, args.db, samples=args.samples, seed=1)
    band = run.bands["r"][:, -1]  # percentiles 5, 50, 95 at the last time
    print(f"r at t = {run['t'][-1]:g} s: nominal {run['r'][-1]:.6f} rad/s, "
          f"band p5 {band[0]:.6f}, p50 {band[1]:.6f}, p95 {band[2]:.6f} "
          f"({run.monte_carlo['used']} of {run.monte_carlo['requested']} draws)")


if __name__ == "__main__":
    main()
