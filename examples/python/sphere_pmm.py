"""The sphere's forced-oscillation runs of examples/openfoam-sphere/pmm
(PROVENANCE.md there), shared by the examples that analyse them
(pmm_analysis.py, pmm_derivatives.py).

OpenFOAM v1912, the whole mesh of a sphere of radius 0.15 m in water moved
along the case's x axis as x = A sin(pi t) (period 2 s) at A = 0.015 and
0.045 m.
"""

import math
import pathlib

import hydrocoef

ROOT = pathlib.Path(__file__).resolve().parents[2]
RUNS = ROOT / "examples" / "openfoam-sphere" / "pmm"
RHO, RADIUS = 998.2, 0.15  # kg/m^3, m
VOLUME = 4.0 / 3.0 * math.pi * RADIUS ** 3


def analyse_runs(axes, **options):
    """hydrocoef.analyse_pmm of both runs as body "sphere", the case's axes
    read as `axes` (e.g. "-x,y,-z": surge; "y,x,-z": sway), with rho and any
    further keyword of analyse_pmm."""
    return hydrocoef.analyse_pmm([RUNS / "surge-A0.015-T2", RUNS / "surge-A0.045-T2"], body="sphere", axes=axes,
                                 rho=RHO, **options)
