"""hydrocoef: CFD results to hydrodynamic coefficient databases, from Python.

The same library the ``hydrocoef`` command-line tool runs, with numpy arrays in
and out:

    import hydrocoef, numpy as np
    with hydrocoef.Database("asr-v.db") as db:
        db.import_files(["asr-v-surge-damping.csv"], body="asr-v",
                        settings={"sign": "opposing", "rho": 998.2})
        fit = db.fit(body="asr-v", output="X", terms="1,u,u|u|")
        runs = db.runs(where=["u>=0"])          # a Table: dict of numpy columns
        s = db.surface("asr-v-surge")           # built with `hydrocoef surface build`
        X = s(u=np.linspace(0, 0.5, 101))["X"]  # forces on the body [N]

Conventions: SI units; body axes after Fossen/SNAME (x forward, y starboard,
z down); velocity u, v, w [m/s], p, q, r [rad/s]; generalized force X, Y, Z
[N], K, M, N [N m] on the body (a damping force is negative along the motion).
Bad input raises hydrocoef.InputError (a ValueError) with the message the
command-line tool prints.

Contents: Database, Surface, Fit, SurfaceInfo, ImportSummary, ImportedFile,
Table, simulate, InputError, __version__.
Analyses: grid_convergence (gci), analyse_pmm and store_pmm (pmm), pmm_runs, delete_pmm_runs,
added_mass_matrix (added-mass), suggest_runs (suggest).
"""

import json as _json
import os as _os

from . import _hydrocoef
from ._hydrocoef import (Fit, ImportedFile, ImportSummary, InputError, Surface,
                         SurfaceInfo, __version__)
from ._hydrocoef import (AddedMassMatrix, GciStudy, PmmAnalysis, PmmDeletion, PmmRunList, Suggestion,
                         added_mass_matrix, analyse_pmm, delete_pmm_runs, grid_convergence, pmm_runs, store_pmm,
                         suggest_runs)

__all__ = ["Database", "Surface", "Fit", "SurfaceInfo", "ImportSummary", "ImportedFile", "Table", "simulate",
           "InputError", "__version__"]
__all__ += ["grid_convergence", "GciStudy", "analyse_pmm", "store_pmm", "PmmAnalysis", "pmm_runs", "PmmRunList",
            "delete_pmm_runs", "PmmDeletion", "added_mass_matrix", "AddedMassMatrix", "suggest_runs", "Suggestion"]


class Table(dict):
    """Columns of one length, by name, each a numpy array (what Database.runs
    and simulate return). ``to_pandas()`` gives a pandas.DataFrame when pandas
    is installed."""

    def to_pandas(self):
        """The columns as a pandas.DataFrame (pandas is imported here, and only here)."""
        try:
            import pandas
        except ImportError as error:  # pandas is optional
            raise ImportError("Table.to_pandas needs pandas (Debian: apt-get install python3-pandas)") from error
        return pandas.DataFrame(dict(self))


class Database(_hydrocoef.Database):
    __doc__ = _hydrocoef.Database.__doc__

    def runs(self, where=None, body=None, exclude_runs=None):
        return Table(super().runs(where, body, exclude_runs))

    runs.__doc__ = _hydrocoef.Database.runs.__doc__


def _json_argument(value, what):
    """A dict as JSON text; a path or JSON text as it is."""
    if isinstance(value, dict):
        return _json.dumps(value, allow_nan=False)
    if isinstance(value, (str, _os.PathLike)):
        return _os.fspath(value)
    raise TypeError(f"{what}: expected a path, JSON text or a dict, got {type(value).__name__}")


def simulate(vehicle, scenario, database=None):
    """Runs a scenario on a vehicle with the 6-DOF model, as ``hydrocoef simulate``.

    vehicle, scenario: a path to a JSON file, the JSON text, or a dict (formats:
    examples/asr-v/vehicle.json, scenario-*.json). database: where the surfaces
    the vehicle's damping names are read from (a path or a Database's path; None:
    no surfaces). Returns a Table of numpy columns, the trajectory CSV's: t [s];
    x_n, y_n, z_n [m] (NED); phi, theta, psi [rad]; q_eta..q_eps3; u, v, w [m/s],
    p, q, r [rad/s] and u_r..r_r (relative to the water); X_control..N_control,
    X_damping.., X_hydrostatic.., X_coriolis.. [N, N m] (forces on the body). Its
    ``units`` attribute maps each column to its unit, ``notes`` lists what a user
    should know (a clamped thrust). Raises InputError as the CLI would.
    """
    if isinstance(database, _hydrocoef.Database):
        database = database.path
    columns, units, notes = _hydrocoef._simulate(_json_argument(vehicle, "vehicle"),
                                                 _json_argument(scenario, "scenario"),
                                                 "" if database is None else _os.fspath(database))
    table = Table(columns)
    table.units = units
    table.notes = notes
    return table
