#!/usr/bin/python3
"""hydrocoef's Python module against scipy.interpolate.RegularGridInterpolator,
in one run, on the same 2-D table and the same random points.

The table: 20 x 20 nodes, u in [0, 0.38] m/s, v in [-0.2, 0.2] m/s, one output
X = -10 u|u| - 2 v + 0.3 u v [N] (forces on the body). It is imported into a
temporary run database through the module, and two surfaces are built from it
(Database.build_surface): linear and PCHIP. scipy gets the same node values in a RegularGridInterpolator with
method "linear" and "pchip" (scipy 1.10 has "pchip": successive 1-D PCHIP
interpolation along each axis).

Timed: one call for all the points (default 10^6, uniform in the table's
range), best of --repeats. hydrocoef on 1 thread and on every core
(threads=0); scipy on the one thread it uses. Printed: seconds, points per
second, scipy's time / hydrocoef's time, and the largest difference between
the two answers (linear: rounding; PCHIP: the two N-D extensions of PCHIP
differ between grid lines, see src/surface/grid_table.hpp).

scipy's "pchip" in RegularGridInterpolator 1.10 runs a Python-level 1-D
interpolation per point (about 0.5 ms per point here): 10^6 points take
minutes, so it is timed once (repeats do not apply), unless --scipy-pchip-points N
times it on the first N points only (the time is then scaled to the full count
and printed as such).

  PYTHONPATH=build/release/python /usr/bin/python3 bench/python_vs_scipy.py \
      [--points 1000000] [--repeats 5] [--scipy-pchip-points N]
"""

import argparse
import os
import pathlib
import tempfile
import time

import numpy as np
import scipy
from scipy.interpolate import RegularGridInterpolator

import hydrocoef

U = np.linspace(0.0, 0.38, 20)
V = np.linspace(-0.2, 0.2, 20)


def table_values(u, v):
    return -10 * u * np.abs(u) - 2 * v + 0.3 * u * v


def best_of(repeats, call):
    best = float("inf")
    result = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - start)
    return best, result


def make_surfaces(directory):
    db_path = pathlib.Path(directory) / "bench.db"
    csv = pathlib.Path(directory) / "table.csv"
    uu, vv = np.meshgrid(U, V, indexing="ij")
    with open(csv, "w") as out:
        out.write("u [m s^-1],v [m s^-1],X [N]\n")
        for a, b, x in zip(uu.ravel(), vv.ravel(), table_values(uu, vv).ravel()):
            out.write(f"{a!r},{b!r},{x!r}\n")
    with hydrocoef.Database(db_path) as db:
        db.import_files(csv, body="bench")
        for method in ("linear", "pchip"):
            db.build_surface(method, body="bench", outputs=["X"], axes=["u", "v"], method=method)
        return {method: db.surface(method) for method in ("linear", "pchip")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--scipy-pchip-points", type=int, default=0,
                        help="time scipy's pchip on the first N points only and scale (0: all points)")
    args = parser.parse_args()

    rng = np.random.default_rng(2026)
    u = rng.uniform(U[0], U[-1], args.points)
    v = rng.uniform(V[0], V[-1], args.points)
    uv = np.column_stack([u, v])  # scipy's layout; hydrocoef reads its columns in place (stride 2)
    uu, vv = np.meshgrid(U, V, indexing="ij")
    values = table_values(uu, vv)

    with tempfile.TemporaryDirectory() as directory:
        surfaces = make_surfaces(directory)
    print(f"{args.points} random points on a 20 x 20 table, one output; numpy {np.__version__}, "
          f"scipy {scipy.__version__}, hydrocoef {hydrocoef.__version__}, {os.cpu_count()} cores; "
          f"best of {args.repeats}\n")
    print(f"{'method':8s} {'implementation':34s} {'time [s]':>10s} {'M points/s':>11s} {'scipy / this':>13s}")
    for method in ("linear", "pchip"):
        interpolator = RegularGridInterpolator((U, V), values, method=method)
        n_scipy = args.points
        if method == "pchip" and args.scipy_pchip_points:
            n_scipy = min(args.points, args.scipy_pchip_points)
        repeats = args.repeats if method == "linear" else 1
        t_scipy, expected = best_of(repeats, lambda: interpolator(uv[:n_scipy]))
        t_scipy *= args.points / n_scipy
        rows = []
        for threads in (1, 0):
            surface = surfaces[method]
            t, answer = best_of(args.repeats, lambda: surface(u=uv[:, 0], v=uv[:, 1], threads=threads)["X"])
            difference = np.max(np.abs(answer[:n_scipy] - expected))
            rows.append((f"hydrocoef, {'1 thread' if threads == 1 else f'{os.cpu_count()} threads'}", t, difference))
        scaled = "" if n_scipy == args.points else f" (timed on {n_scipy} points, scaled)"
        print(f"{method:8s} {'scipy RegularGridInterpolator' + scaled:34s} {t_scipy:10.4f} "
              f"{args.points / t_scipy / 1e6:11.3f} {1.0:13.1f}")
        for label, t, difference in rows:
            print(f"{'':8s} {label:34s} {t:10.4f} {args.points / t / 1e6:11.3f} {t_scipy / t:13.1f}"
                  f"   (max |difference| {difference:.2g} N)")


if __name__ == "__main__":
    main()
