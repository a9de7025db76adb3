#!/usr/bin/python3
"""A damping law fitted to the ASR-V surge runs and evaluated with its standard-error band.

The surge table of the ASR-V study (examples/asr-v/asr-v-surge-damping.csv:
magnitudes, positive opposes motion) is imported with a stated uncertainty of
2 % of each value, the law X(u) = c0 + c1 u + c2 u|u| is fitted to it
(weighted by the uncertainties, as `hydrocoef fit` does) and stored, and the
stored law is evaluated on a grid of u with the one-sigma standard error of
each value from the coefficients' covariance, as
`hydrocoef fits evaluate NAME --at ...` prints it.

Run from the repository after a build:
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/fit_law.py --db build/fit-law.db
"""

import argparse
import pathlib

import numpy as np

import hydrocoef

TABLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "asr-v" / "asr-v-surge-damping.csv"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", required=True, help="the run database to make (or add to)")
    db_path = pathlib.Path(parser.parse_args().db)
    db_path.parent.mkdir(parents=True, exist_ok=True)

    with hydrocoef.Database(db_path, mode="create") as db:
        db.import_files(TABLE, body="asr-v", settings={"sign": "opposing", "rho": 998.2, "uncertainty": "X=2%"})
        fit = db.fit(body="asr-v", output="X", terms="1,u,u|u|", replace=True)
        print(fit.text(), end="")
        u = np.linspace(0.0, 0.5, 11)  # 0.4 and 0.5 m/s lie beyond the runs: the band widens
        law = db.evaluate_fit(fit.name, u)

    print(f"\n{'u [m/s]':>8} {'X [N]':>10} {'sigma [N]':>10}   band X +- 2 sigma")
    for x, value, sigma in zip(law.at, law.value, law.std_error):
        print(f"{x:8.2f} {value:10.5f} {sigma:10.2e}   [{value - 2 * sigma:.5f}, {value + 2 * sigma:.5f}]")
    low, high = law.fitted_range
    print(f"fitted over u = {low:g} to {high:g} m/s; X as tabulated ({law.sign_convention}: positive opposes motion)")


if __name__ == "__main__":
    main()
