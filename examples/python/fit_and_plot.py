#!/usr/bin/python3
"""The ASR-V example of examples/asr-v/run.sh, from Python.

Data: the two damping tables of the ASR-V study (examples/asr-v/README.md):
the surge damping force X(u) as printed in the paper's Table I (magnitudes:
positive opposes motion) and the yaw damping moment N(r) (on the body).

What it does, with the hydrocoef module:
  1. imports both tables into a run database (one run per row, keyed by the
     body velocity u or r; SI units, body axes);
  2. fits the paper's laws  X(u) = c0 + c1 u + c2 u|u|  and
     N(r) = c0 + c1 r + c2 r|r|  (Ceres least squares), printing each
     coefficient with its standard error and unit;
  3. builds the lookup surfaces X(u) and N(r) (PCHIP through the runs, continued
     linearly beyond them, as `hydrocoef surface build` does) and evaluates
     them and their slopes on a grid of 201 points with one vectorised call each;
  4. plots runs, fitted laws and surfaces to a PNG (matplotlib, Agg backend),
     or prints a table of numbers when matplotlib is not installed.

Expected (README, paper eq. 5 and 6):
  X(u) = 0.000618201 + 0.0155077 u + 11.0364 u|u|   (as tabulated: positive opposes motion)
  N(r) = 1.89812e-05 - 0.00607516 r - 0.0771371 r|r| (on the body)

Run from the repository after a build (scripts/build.sh):
  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/fit_and_plot.py \
      [--db build/asr-v-python.db] [--png build/asr-v-python.png]
"""

import argparse
import pathlib

import numpy as np

import hydrocoef

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
TABLES = ROOT / "examples" / "asr-v"


def law_text(fit):
    """ "X(u) = 0.000618201 + 0.0155077 u + 11.0364 u|u|" """
    parts = []
    for term, c in fit.coefficients.items():
        sign = "-" if c < 0 else "+"
        parts.append(f"{sign} {abs(c):.6g}" + ("" if term == "1" else f" {term}"))
    text = " ".join(parts)
    return f"{fit.output}({fit.variable}) = " + (text[2:] if text.startswith("+ ") else "-" + text[2:])


def law_values(fit, x):
    basis = {"1": np.ones_like(x), fit.variable: x, f"{fit.variable}|{fit.variable}|": x * np.abs(x)}
    return sum(c * basis[t] for t, c in fit.coefficients.items())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", default=str(ROOT / "build" / "asr-v-python.db"))
    parser.add_argument("--png", default=str(ROOT / "build" / "asr-v-python.png"))
    args = parser.parse_args()
    pathlib.Path(args.db).parent.mkdir(parents=True, exist_ok=True)

    with hydrocoef.Database(args.db, mode="create") as db:
        # 1. Import: each table records its own sign convention.
        for table, sign in (("asr-v-surge-damping.csv", "opposing"), ("asr-v-yaw-damping.csv", "on-body")):
            summary = db.import_files(TABLES / table, body="asr-v",
                                      settings={"sign": sign, "rho": 998.2, "nu": 1.004e-6})
            print(f"import {table}: {summary.runs_created} new runs, {summary.runs_extended} extended, "
                  f"{summary.already_imported} already imported")
        runs = db.runs(body="asr-v")
        print(f"{len(runs['id'])} runs of body asr-v")

        # 2. Fit the paper's laws.
        fits = {}
        for output, terms in (("X", "1,u,u|u|"), ("N", "1,r,r|r|")):
            fit = db.fit(body="asr-v", output=output, terms=terms, replace=True)
            fits[output] = fit
            print(f"\nfit {fit.name} ({fit.sign_convention}; n = {fit.n}, RMSE = {fit.rmse:.3g}, R^2 = {fit.r2:.6f})")
            print("  " + law_text(fit))
            for term in fit.coefficients:
                print(f"    {term:6s} {fit.coefficients[term]: .6g} ± {fit.std_errors[term]:.2g} {fit.units[term]}")

        # 3. Surfaces through the runs (forces on the body).
        for name, output, axis in (("asr-v-surge", "X", "u"), ("asr-v-yaw", "N", "r")):
            db.build_surface(name, body="asr-v", outputs=[output], axes=[axis], method="pchip",
                             extrapolate=["linear"], replace=True)
        surge, yaw = db.surface("asr-v-surge"), db.surface("asr-v-yaw")
    u = np.linspace(0.0, 0.38, 201)
    r = np.linspace(0.0, 0.2792, 201)
    X = surge(u=u, gradient=True)  # {"X": ..., "dX/du": ...}, one call for the 201 points
    N = yaw(r=r, gradient=True)
    # The surge law was fitted to magnitudes (positive opposes motion): on the body it is the negative.
    X_law = -law_values(fits["X"], u)
    N_law = law_values(fits["N"], r)
    print(f"\nsurface {surge.name} and fitted law at u [m/s] (forces on the body, N):")
    for i in range(0, 201, 40):
        print(f"  u = {u[i]:5.3f}  X = {X['X'][i]: .5f}  law {X_law[i]: .5f}  dX/du = {X['dX/du'][i]: .4f} N/(m/s)")
    print(f"surface {yaw.name} and fitted law at r [rad/s] (moments on the body, N m):")
    for i in range(0, 201, 40):
        print(f"  r = {r[i]:6.4f}  N = {N['N'][i]: .6f}  law {N_law[i]: .6f}  dN/dr = {N['dN/dr'][i]: .5f} N m/(rad/s)")

    # 4. Plot, when matplotlib is there.
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("\nmatplotlib is not installed (Debian: python3-matplotlib): numbers only, no plot")
        return
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    on_u = runs["r"] == 0
    on_r = runs["u"] == 0
    left.plot(runs["u"][on_u], runs["X"][on_u], "o", label="CFD runs (Table I)")
    left.plot(u, X["X"], "-", label="surface (PCHIP)")
    left.plot(u, X_law, "--", label="law: -(" + law_text(fits["X"]).replace("X(u) = ", "") + ")")
    left.set(xlabel="u [m/s]", ylabel="X [N] (force on the body)", title="ASR-V surge damping")
    right.plot(runs["r"][on_r], runs["N"][on_r], "o", label="CFD runs")
    right.plot(r, N["N"], "-", label="surface (PCHIP)")
    right.plot(r, N_law, "--", label="law (1, r, r|r|)")
    right.set(xlabel="r [rad/s]", ylabel="N [N m] (moment on the body)", title="ASR-V yaw damping")
    for axes in (left, right):
        axes.grid(True, alpha=0.3)
        axes.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(args.png, dpi=120)
    print(f"\nplot: {args.png}")


if __name__ == "__main__":
    main()
