"""The converged sphere study of data/openfoam-sphere/converged, shared by
the examples that import it (gci_study.py, drag_coefficient.py).

Steady RANS runs of a sphere of radius R = 0.15 m in water in a quarter
domain at 0.1 and 0.3 m/s on three systematically refined meshes;
reference.json gives each case's mesh level and cell count.
"""

import json
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUDY = ROOT / "data" / "openfoam-sphere" / "converged"
RADIUS = 0.15  # m


def import_study(db, body="sphere", **settings):
    """Imports the six case folders into `db` as runs of `body`, each with its
    mesh level and cell count as disturbance parameters; `settings` are added
    to each import's settings (axes, symmetry...)."""
    cases = json.loads((STUDY / "reference.json").read_text())["cases"]
    for case in cases.values():
        db.import_files(STUDY / case["case"], body=body,
                        settings={**settings, "disturbances": {"mesh": case["mesh"], "cells": case["cells"]}})
