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
Table, simulate (Simulation), equilibrium (Equilibrium), InputError, __version__.
Analyses: grid_convergence (gci), analyse_pmm and store_pmm (pmm), pmm_runs, delete_pmm_runs,
added_mass_matrix (added-mass), suggest_runs (suggest).
Reference data and coefficients: set_body_reference (body set), body_references (body show),
run_coefficients (runs --coefficients).
Sway and yaw derivatives from forced oscillation: pmm_derivatives (derivatives pmm).
FMUs: export_fmu (export-fmu), a surface as an FMI 2.0 Co-Simulation FMU.
Runtime files: RuntimeModel, a runtime file (export --format runtime) loaded through libhydrocoef_runtime.
"""

import json as _json
import os as _os

from . import _hydrocoef
from ._hydrocoef import (Fit, ImportedFile, ImportSummary, InputError, Surface,
                         SurfaceInfo, __version__)
from ._hydrocoef import (GazeboExportResult, SurfaceBuildReport, SurfaceList, SurfaceQueryResult,
                         SurfaceRebuildReport, SurfaceReport, TableExportResult)
from ._hydrocoef import (AddedMassMatrix, GciStudy, PmmAnalysis, PmmDeletion, PmmRunList, Suggestion,
                         added_mass_matrix, analyse_pmm, delete_pmm_runs, grid_convergence, pmm_runs, store_pmm,
                         suggest_runs)
from ._hydrocoef import SurfaceIntegration, integrate_surface
from ._hydrocoef import (PlotFiles, plot_coefficient, plot_curves, plot_fit, plot_history, plot_simulation,
                         plot_steady, plot_surface)
from ._hydrocoef import (BodyReference, BodyReferences, RunCoefficients, body_references, run_coefficients,
                         set_body_reference)
from ._hydrocoef import (CopySummary, DeleteSummary, FitEvaluation, LevelFit, LevelFits, MergeSummary,
                         MigrationSummary, Refits, ReportSummary, RunDetails)
from ._hydrocoef import (DerivativeCoefficient, DerivativeDeletion, DerivativeEvaluation, DerivativeModel,
                         DerivativeModelList, delete_derivative_model, evaluate_derivative_model,
                         fit_derivative_model, list_derivative_models, show_derivative_model)
from ._hydrocoef import (PmmDerivative, PmmDerivativeRun, PmmDerivatives, PmmFrequencyDerivatives,
                         pmm_derivatives)
from ._hydrocoef import FmuExportResult, FmuVariable, export_fmu
from ._hydrocoef import RuntimeModel
from ._hydrocoef import (DerivativeExportResult, ResistanceScalingPoint, ResistanceScalingResult, export_derivatives,
                         scale_surge_resistance)
from ._hydrocoef import ForceCoeffsExportResult, ForceCoeffsExportRun

__all__ = ["Database", "Surface", "Fit", "SurfaceInfo", "ImportSummary", "ImportedFile", "Table", "Simulation",
           "Equilibrium", "simulate", "equilibrium", "InputError", "__version__"]
__all__ += ["SurfaceReport", "SurfaceList", "SurfaceBuildReport", "SurfaceRebuildReport", "SurfaceQueryResult",
            "TableExportResult", "GazeboExportResult"]
__all__ += ["LevelFit", "LevelFits", "Refits", "FitEvaluation", "RunDetails", "DeleteSummary", "MergeSummary",
            "CopySummary", "MigrationSummary", "ReportSummary"]
__all__ += ["integrate_surface", "SurfaceIntegration"]
__all__ += ["export_fmu", "FmuExportResult", "FmuVariable"]
__all__ += ["RuntimeModel"]
__all__ += ["plot_fit", "plot_curves", "plot_surface", "plot_history", "plot_simulation", "plot_steady", "PlotFiles",
            "plot_coefficient"]
__all__ += ["grid_convergence", "GciStudy", "analyse_pmm", "store_pmm", "PmmAnalysis", "pmm_runs", "PmmRunList",
            "delete_pmm_runs", "PmmDeletion", "added_mass_matrix", "AddedMassMatrix", "suggest_runs", "Suggestion"]
__all__ += ["set_body_reference", "body_references", "BodyReference", "BodyReferences", "run_coefficients",
            "RunCoefficients"]
__all__ += ["fit_derivative_model", "list_derivative_models", "show_derivative_model", "delete_derivative_model",
            "evaluate_derivative_model", "DerivativeModel", "DerivativeCoefficient", "DerivativeModelList",
            "DerivativeDeletion", "DerivativeEvaluation"]
__all__ += ["pmm_derivatives", "PmmDerivatives", "PmmFrequencyDerivatives", "PmmDerivative", "PmmDerivativeRun"]
__all__ += ["export_derivatives", "DerivativeExportResult", "scale_surge_resistance", "ResistanceScalingResult",
            "ResistanceScalingPoint"]
__all__ += ["ForceCoeffsExportResult", "ForceCoeffsExportRun"]


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


class Simulation(Table):
    """A simulated trajectory (a Table of the trajectory CSV's columns) with what
    ``hydrocoef simulate`` reports beside it: ``units``, ``notes``, ``steps``,
    ``rejected_steps``, ``evaluations``, ``wall_time_s``; ``comparison`` (a list
    of dicts, one per compared velocity component, with an experiment); and with
    samples, ``monte_carlo`` (what was drawn, seed, percentiles, failures),
    ``band_t`` [s], ``bands`` (quantity -> array [percentile, time]: x_n..z_n [m],
    phi..psi [rad], u..w [m/s], p..r [rad/s]), ``band_units`` and
    ``measured_inside_band``. ``text()`` and ``json()`` give what the CLI prints."""

    def text(self):
        """What ``hydrocoef simulate`` prints."""
        return self._text

    def json(self):
        """What ``hydrocoef simulate --json`` prints, parsed."""
        return _json.loads(self._json)


class Equilibrium:
    """A steady state as ``hydrocoef equilibrium`` finds it: ``tau`` (the force
    applied, X..N [N, N m]), ``velocity`` and ``relative_velocity`` (u..r [m/s,
    rad/s], body axes), ``damping`` and ``residual`` (X..N), ``iterations``,
    ``continuation_s``; with samples, ``monte_carlo``, ``mean``,
    ``standard_deviation`` and ``velocity_percentiles`` (percentile -> u..r).
    ``text()`` and ``json()`` give what the CLI prints."""

    def __init__(self, outcome):
        self._text = outcome.pop("text")
        self._json = outcome.pop("json")
        for key, value in outcome.items():
            setattr(self, key, value)

    def text(self):
        """What ``hydrocoef equilibrium`` prints."""
        return self._text

    def json(self):
        """What ``hydrocoef equilibrium --json`` prints, parsed."""
        return _json.loads(self._json)

    def __repr__(self):
        return f"Equilibrium(velocity={self.velocity})"


def _database_text(database):
    if isinstance(database, _hydrocoef.Database):
        return database.path
    return "" if database is None else _os.fspath(database)


def simulate(vehicle, scenario, database=None, *, out=None, experiment=None, steady_fraction=0.2, samples=0,
             seed=1, percentiles=None, threads=0):
    """Runs a scenario on a vehicle with the 6-DOF model, as ``hydrocoef simulate``.

    vehicle, scenario: a path to a JSON file, the JSON text, or a dict (formats:
    examples/asr-v/vehicle.json, scenario-*.json). database: where the fits and
    surfaces the vehicle names are read from (a path or a Database; None: none).
    out: write the trajectory CSV there; experiment: a measured trajectory CSV
    to compare with (the last ``steady_fraction`` of it as steady state);
    samples > 0: Monte Carlo over the damping's uncertainty (seed, percentiles,
    default 5, 50, 95; threads, 0: every core).

    Returns a Simulation: a Table of numpy columns, the trajectory CSV's: t [s];
    x_n, y_n, z_n [m] (NED); phi, theta, psi [rad]; q_eta..q_eps3; u, v, w [m/s],
    p, q, r [rad/s] and u_r..r_r (relative to the water); X_control..N_control,
    X_damping.., X_hydrostatic.., X_coriolis.. [N, N m] (forces on the body), with
    the report's other figures as attributes (see Simulation). Raises InputError
    as the CLI would.
    """
    outcome = _hydrocoef._simulate(_json_argument(vehicle, "vehicle"), _json_argument(scenario, "scenario"),
                                   _database_text(database), "" if out is None else _os.fspath(out),
                                   "" if experiment is None else _os.fspath(experiment), steady_fraction, samples,
                                   seed, list(percentiles or []), threads)
    table = Simulation(outcome.pop("columns"))
    table._text = outcome.pop("text")
    table._json = outcome.pop("json")
    for key, value in outcome.items():
        setattr(table, key, value)
    return table


def equilibrium(vehicle, database=None, *, tau=None, current=None, disturbances=None, attitude_deg=(0.0, 0.0, 0.0),
                samples=0, seed=1, percentiles=None, threads=0):
    """The steady body velocity under a constant force, the attitude held, as
    ``hydrocoef equilibrium``.

    tau: force on the body by component, e.g. {"X": 0.5} [N, N m], body axes;
    current: water velocity {"u": 0.1} [m/s], body axes; disturbances: the
    parameters the vehicle's surfaces read; attitude_deg: roll, pitch, yaw held;
    samples > 0: its distribution over the damping's uncertainty (percentiles
    default 2.5, 50, 97.5). Returns an Equilibrium. Raises InputError as the CLI would.
    """
    outcome = _hydrocoef._equilibrium(_json_argument(vehicle, "vehicle"), _database_text(database),
                                      dict(tau or {}), dict(current or {}), dict(disturbances or {}),
                                      tuple(attitude_deg), samples, seed, list(percentiles or []), threads)
    return Equilibrium(outcome)
