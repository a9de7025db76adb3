# Type stubs for the Python module hydrocoef (python/src/module.cpp, python/hydrocoef/__init__.py).
import os
from typing import Any, Iterable, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Path = Union[str, os.PathLike[str]]
_Texts = Union[str, Sequence[str], None]
_Values = Union[float, int, npt.ArrayLike]

class InputError(ValueError):
    """Bad input, with the message the hydrocoef command-line tool prints."""

class Table(dict[str, np.ndarray]):
    units: dict[str, str]
    notes: list[str]
    def to_pandas(self) -> Any: ...

class Surface:
    @property
    def name(self) -> str: ...
    @property
    def body(self) -> str: ...
    @property
    def method(self) -> str: ...
    @property
    def stale(self) -> bool: ...
    @property
    def axes(self) -> list[str]: ...
    @property
    def outputs(self) -> list[str]: ...
    @property
    def axis_units(self) -> list[str]: ...
    @property
    def output_units(self) -> list[str]: ...
    @property
    def bounds(self) -> dict[str, tuple[float, float]]: ...
    @property
    def out_of_range(self) -> dict[str, str]: ...
    def __call__(self, values: Mapping[str, _Values] | None = ..., /, *, gradient: bool = ..., uncertainty: bool = ...,
                 threads: int = ...,
                 **axes: _Values) -> dict[str, np.ndarray]: ...
    @property
    def gridded(self) -> bool: ...
    def table(self) -> dict[str, np.ndarray]: ...
    def tabulate(self, breakpoints: Mapping[str, npt.ArrayLike] | None = ..., /, *, threads: int = ...,
                 **axes: npt.ArrayLike) -> dict[str, np.ndarray]: ...
    def largest_standard_deviations(self, count: int = 3) -> dict[str, list[dict[str, Any]]]: ...

class Fit:
    name: str
    body: str
    output: str
    variable: str
    terms: str
    loss: str
    where: str
    mirror: str
    sign_convention: str
    @property
    def coefficients(self) -> dict[str, float]: ...
    @property
    def std_errors(self) -> dict[str, float]: ...
    @property
    def units(self) -> dict[str, str]: ...
    rmse: float
    r2: float
    n: int
    runs: list[int]
    warnings: list[str]
    id: int
    stale: bool
    created_at: str
    weighting: str
    chi2_reduced: float
    covariance_scale: float
    @property
    def covariance(self) -> np.ndarray: ...
    mirror_images: int
    varying_conditions: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

class LevelFit:
    level: float
    name: str
    n: int
    rmse: float
    r2: float
    @property
    def coefficients(self) -> dict[str, float]: ...
    @property
    def std_errors(self) -> dict[str, float]: ...
    id: int

class LevelFits:
    name: str
    by: str
    curve: str
    sign_convention: str
    levels: list[LevelFit]
    @property
    def skipped(self) -> list[dict[str, Any]]: ...
    @property
    def curves(self) -> dict[str, dict[str, Any]]: ...
    warnings: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

class Refits:
    previous: list[Fit]
    made: list[Fit]
    def text(self) -> str: ...
    def json(self) -> str: ...

class FitEvaluation:
    name: str
    output: str
    variable: str
    sign_convention: str
    unit: str
    variable_unit: str
    @property
    def at(self) -> np.ndarray: ...
    @property
    def value(self) -> np.ndarray: ...
    @property
    def std_error(self) -> np.ndarray: ...
    @property
    def fitted_range(self) -> tuple[float, float]: ...
    stale: bool
    def text(self) -> str: ...
    def json(self) -> str: ...

class RunDetails:
    id: int
    body: str
    velocity: list[float]
    disturbances: dict[str, float]
    force: list[float]
    force_std_error: list[float]
    sign_convention: list[str]
    source: list[str]
    density: float
    kinematic_viscosity: float
    reference_point: list[float]
    flags: list[str]
    @property
    def imports(self) -> list[dict[str, Any]]: ...
    def text(self) -> str: ...
    def json(self) -> str: ...

class DeleteSummary:
    runs: int
    components: int
    fits_made_stale: int
    surfaces_made_stale: int
    imports_removed: int
    def text(self) -> str: ...
    def json(self) -> str: ...

class MergeSummary:
    into: str
    @property
    def shards(self) -> list[dict[str, Any]]: ...
    def text(self) -> str: ...
    def json(self) -> str: ...

class CopySummary:
    source: str
    target: str
    @property
    def rows(self) -> dict[str, int]: ...
    def text(self) -> str: ...
    def json(self) -> str: ...

class MigrationSummary:
    database: str
    from_version: int
    to_version: int
    def text(self) -> str: ...
    def json(self) -> str: ...

class ReportSummary:
    index: str
    plots: list[str]
    notes: list[str]
    runs: int
    fits: int
    surfaces: int
    histories: int
    sigma_maps: int
    mesh_study_rows: int
    pmm_fits: int
    def text(self) -> str: ...
    def json(self) -> str: ...

class SurfaceInfo:
    name: str
    body: str
    kind: str
    method: str
    axes: list[str]
    outputs: list[str]
    stale: bool
    run_count: int
    created_at: str

class SurfaceAxisReport:
    name: str
    unit: str
    lower: float
    upper: float
    out_of_range: str
    breakpoints: list[float]

class SurfaceOutputReport:
    name: str
    unit: str
    loo_max: float
    loo_rms: float
    worst_run: int
    worst_error: float
    @property
    def largest_sd(self) -> list[tuple[list[float], float]]: ...

class SurfaceReport:
    name: str
    body: str
    kind: str
    method: str
    created_at: str
    stale: bool
    runs: list[int]
    built_from: str
    axes: list[SurfaceAxisReport]
    outputs: list[SurfaceOutputReport]
    def text(self) -> str: ...
    def json(self) -> str: ...

class SurfaceList:
    surfaces: list[SurfaceReport]
    def text(self) -> str: ...
    def json(self) -> str: ...

class SurfaceBuildReport:
    surface: SurfaceReport
    id: int
    runs_measured: int
    mirror_images: int
    images_skipped: int
    runs_skipped: int
    mirror: str
    def text(self) -> str: ...
    def json(self) -> str: ...

class SurfaceRebuildReport:
    rebuilt: list[SurfaceBuildReport]
    def text(self) -> str: ...
    def json(self) -> str: ...

class SurfaceQueryResult:
    surface: str
    stale: bool
    warnings: list[str]
    axes: list[str]
    point: list[float]
    outputs: list[str]
    units: list[str]
    values: list[float]
    standard_deviation: list[float]
    new_run_standard_deviation: list[float]
    gradient: list[float]
    points: int
    output: str
    def text(self) -> str: ...
    def json(self) -> str: ...
    def note(self) -> str: ...

class TableExportAxis:
    name: str
    unit: str
    breakpoints: int
    lower: float
    upper: float
    extrapolation: str

class TableExportResult:
    surface: str
    body: str
    format: str
    method: str
    content_sha256: str
    runs: list[int]
    stale: bool
    nodes: int
    files: list[str]
    surfaces: list[str]
    vehicle: str
    axes: list[TableExportAxis]
    outputs: list[str]
    output_units: list[str]
    notes: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

class ForceCoeffsExportRun:
    id: int
    body: str
    file: str
    axes: str
    rows_from: str
    rows: int
    rho: float
    mag_u_inf: float
    l_ref: float
    a_ref: float
    area_name: str
    cofr: list[float]
    last_coefficients: list[float]

class ForceCoeffsExportResult:
    database: str
    directory: str
    precision: int
    runs: list[ForceCoeffsExportRun]
    values: int
    exact: int
    one_ulp: int
    notes: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

class GazeboFitExport:
    dof: str
    variable: str
    name: str
    id: int
    terms: str
    stored_sign: str
    linear: float
    quadratic: float
    linear_unit: str
    quadratic_unit: str
    runs: list[int]
    dropped_constant: float

class GazeboElementExport:
    name: str
    values: list[float]
    unit: str

class GazeboExportResult:
    body: str
    flavor: str
    file: str
    frame: str
    link_name: str
    linear_b: list[float]
    quadratic_b: list[float]
    added_mass_b: list[float]
    added_mass_source: str
    linearized_at: float
    fits: list[GazeboFitExport]
    missing: list[str]
    elements: list[GazeboElementExport]
    notes: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

class ImportedFile:
    path: str
    format: str
    runs: int
    runs_created: int
    runs_extended: int
    already_imported: bool
    replaced: bool
    notes: list[str]

class ImportSummary:
    files: list[ImportedFile]
    notes: list[str]
    excluded: int
    runs_created: int
    runs_extended: int
    already_imported: int
    replaced: int
    database: str
    def text(self, quiet: bool = ...) -> str: ...
    def json(self) -> str: ...

class Database:
    def __init__(self, path: _Path, mode: str = "create") -> None: ...
    @property
    def path(self) -> str: ...
    @property
    def closed(self) -> bool: ...
    @property
    def read_only(self) -> bool: ...
    def close(self) -> None: ...
    def __enter__(self) -> Database: ...
    def __exit__(self, *args: Any) -> None: ...
    def runs(self, where: _Texts = None, body: str | None = None,
             exclude_runs: Iterable[int] | None = None) -> Table: ...
    def import_files(self, paths: Union[_Path, Sequence[_Path]], *, body: str | None = None, format: str = "auto",
                     settings: Mapping[str, Any] | None = None, columns: Mapping[str, str] | None = None,
                     units: Mapping[str, str] | None = None, disturbance_columns: _Texts = None,
                     ignore: _Texts = None, monitors: Mapping[str, str] | None = None, average_last: int = 1,
                     include: _Texts = None, exclude: _Texts = None, key_from_name: str | None = None,
                     manifest: _Path | None = None, sidecars: bool = True, prefer_surfaces: bool = False,
                     replace: bool = False, also: str = "", jobs: int = 0, form: str | None = None,
                     drift_convention: str | None = None, length: float | None = None,
                     speed: float | None = None, density: float | None = None, draft: float | None = None,
                     mass: float | None = None, volume: float | None = None,
                     gravity: float | None = None) -> ImportSummary: ...
    def fit(self, *, body: str, output: str, terms: str, where: _Texts = None,
            exclude_runs: Iterable[int] | None = None, mirror: _Texts = None, mirror_odd: _Texts = None,
            loss: str = "squared", name: str | None = None, replace: bool = False, store: bool = True,
            weighted: bool = True) -> Fit: ...
    def fit_by_level(self, *, body: str, output: str, terms: str, by: str, curve: str = "polynomial:2",
                     strict: bool = False, where: _Texts = None, exclude_runs: Iterable[int] | None = None,
                     mirror: _Texts = None, mirror_odd: _Texts = None, loss: str = "squared",
                     name: str | None = None, replace: bool = False, store: bool = True,
                     weighted: bool = True) -> LevelFits: ...
    def refit(self, name: str | None = None, body: str | None = None) -> Refits: ...
    def evaluate_fit(self, name: str, at: _Values) -> FitEvaluation: ...
    def fits(self, body: str | None = None) -> list[Fit]: ...
    def show_run(self, id: int) -> RunDetails: ...
    def delete_runs(self, ids: Iterable[int] | None = None, *, where: _Texts = None, body: str | None = None,
                    exclude_runs: Iterable[int] | None = None, source: _Path | None = None) -> DeleteSummary: ...
    def merge(self, shards: Union[_Path, Sequence[_Path]]) -> MergeSummary: ...
    def copy_to(self, target: Database) -> CopySummary: ...
    def migration(self) -> MigrationSummary: ...
    def report(self, output: _Path, *, body: str | None = None, where: _Texts = None,
               exclude_runs: Iterable[int] | None = None, trajectories: Sequence[_Path] | None = None,
               experiment: _Path | None = None, component: str = "r") -> ReportSummary: ...
    def build_surface(self, name: str, *, body: str, axes: _Texts, outputs: _Texts, method: str = "linear",
                      extrapolate: _Texts = None, where: _Texts = None, exclude_runs: Sequence[int] | None = None,
                      mirror: _Texts = None, mirror_odd: _Texts = None, rbf_kernel: str = "cubic",
                      rbf_degree: int = 1, rbf_smoothing: float = 0.0,
                      resample: Sequence[Sequence[float]] | None = None, resample_method: str = "linear",
                      far_threshold: float = 0.25, replace: bool = False, gp_kernel: str = "matern52",
                      gp_degree: int = 1, gp_starts: int = 5, gp_seed: int = 1) -> SurfaceInfo: ...
    def surface_build(self, name: str, *, body: str, axes: _Texts, outputs: _Texts, method: str = "linear",
                      extrapolate: _Texts = None, where: _Texts = None, exclude_runs: Sequence[int] | None = None,
                      mirror: _Texts = None, mirror_odd: _Texts = None, rbf_kernel: str = "cubic",
                      rbf_degree: int = 1, rbf_smoothing: float = 0.0,
                      resample: Sequence[Sequence[float]] | None = None, resample_method: str = "linear",
                      far_threshold: float = 0.25, replace: bool = False, gp_kernel: str = "matern52",
                      gp_degree: int = 1, gp_starts: int = 5, gp_seed: int = 1) -> SurfaceBuildReport: ...
    def surface_rebuild(self, name: str | None = None, *, body: str | None = None,
                        stale_only: bool = False) -> SurfaceRebuildReport: ...
    def surface_list(self, body: str | None = None) -> SurfaceList: ...
    def surface_show(self, name: str) -> SurfaceReport: ...
    def query_surface(self, name: str, point: Mapping[str, float] | None = None, *, input: _Path | None = None,
                      output: str = "-", gradient: bool = False, uncertainty: bool = False) -> SurfaceQueryResult: ...
    def export_surface(self, name: str, *, format: str, output: _Path, single_precision: bool = False,
                       identifier: str = "", surfaces: Sequence[str] = (),
                       vehicle: _Path | None = None) -> TableExportResult: ...
    def export_forcecoeffs(self, *, output: _Path, body: str = "", where: _Texts = None,
                           exclude_runs: Iterable[int] | None = None, area: str = "", axes: str = "",
                           precision: int = 16, mean_only: bool = False) -> ForceCoeffsExportResult: ...
    def export_gazebo(self, body: str, *, flavor: str, output: _Path, fits: _Texts = None,
                      added_mass: Union[str, Sequence[float], None] = None, added_mass_matrix: _Path | None = None,
                      sphere_radius: float | None = None, rho: float | None = None,
                      added_mass_rotation: Union[str, Sequence[float], None] = None,
                      added_mass_from_database: str | None = None, same: _Texts = None, zero: _Texts = None,
                      added_mass_period: float | None = None, drop_constant: bool = False,
                      allow_missing: bool = False, allow_unphysical: bool = False,
                      linearize_at: float | None = None, link: str | None = None, link_axes: str | None = None,
                      where: _Texts = None, exclude_runs: Iterable[int] | None = None) -> GazeboExportResult: ...
    def rebuild_surfaces(self, name: str | None = None, *, stale_only: bool = False) -> list[SurfaceInfo]: ...
    def surfaces(self, body: str | None = None) -> list[SurfaceInfo]: ...
    def surface(self, name: str) -> Surface: ...

class Simulation(Table):
    units: dict[str, str]
    notes: list[str]
    steps: int
    rejected_steps: int
    evaluations: int
    wall_time_s: float
    comparison: list[dict[str, Any]]
    monte_carlo: dict[str, Any]
    band_t: np.ndarray
    bands: dict[str, np.ndarray]
    band_units: dict[str, str]
    measured_inside_band: dict[str, float]
    def text(self) -> str: ...
    def json(self) -> dict[str, Any]: ...

class Equilibrium:
    tau: dict[str, float]
    velocity: dict[str, float]
    relative_velocity: dict[str, float]
    damping: dict[str, float]
    residual: dict[str, float]
    iterations: int
    continuation_s: float
    monte_carlo: dict[str, Any]
    mean: dict[str, float]
    standard_deviation: dict[str, float]
    velocity_percentiles: dict[float, dict[str, float]]
    def text(self) -> str: ...
    def json(self) -> dict[str, Any]: ...

def simulate(vehicle: Union[_Path, Mapping[str, Any]], scenario: Union[_Path, Mapping[str, Any]],
             database: Union[_Path, Database, None] = None, *, out: _Path | None = None,
             experiment: _Path | None = None, steady_fraction: float = 0.2, samples: int = 0, seed: int = 1,
             percentiles: Sequence[float] | None = None, threads: int = 0) -> Simulation: ...
def equilibrium(vehicle: Union[_Path, Mapping[str, Any]], database: Union[_Path, Database, None] = None, *,
                tau: Mapping[str, float] | None = None, current: Mapping[str, float] | None = None,
                disturbances: Mapping[str, float] | None = None,
                attitude_deg: Sequence[float] = (0.0, 0.0, 0.0), samples: int = 0, seed: int = 1,
                percentiles: Sequence[float] | None = None, threads: int = 0) -> Equilibrium: ...

# Analyses (python/src/analysis.cpp, include/hydrocoef/analysis.hpp). Each result has .text() (what the
# CLI prints) and .json() (what --json prints).
class GciComponent:
    component: str
    phi: list[float]
    r21: float
    r32: float
    convergence: str
    apparent_order: float | None
    extrapolated: float | None
    relative_error: float | None
    extrapolated_relative_error: float | None
    gci_fine: float | None
    gci_medium: float | None
    asymptotic_ratio: float | None
    numerical_uncertainty: float | None
    values_convergence: list[str]
    values_error: list[float]
    note: str

class GciKey:
    body: str
    velocity: list[float]
    disturbances: dict[str, float]
    description: str
    levels: list[float]
    cell_sizes: list[float]
    runs: list[int]
    cell_size_from: str
    components: list[GciComponent]
    notes: list[str]

class GciStudy:
    body: str
    mesh_parameter: str
    safety_factor: float
    coverage_factor: float
    keys: list[GciKey]
    single_level_keys: int
    runs_without_level: int
    stored: bool
    fits_made_stale: int
    surfaces_made_stale: int
    def text(self) -> str: ...
    def json(self) -> str: ...

class PmmComponent:
    component: str
    mean: float
    added_mass: float
    added_mass_se: float
    added_mass_unit: str
    damping: float
    damping_se: float
    damping_unit: str
    explained: float
    harmonics: list[float]
    added_mass_coefficient: float | None
    in_phase_spread: float
    quadrature_spread: float

class PmmRun:
    path: str
    format: str
    body: str
    velocity: list[float]
    dof: str
    amplitude: float
    omega: float
    period: float
    phase: float
    motion_source: str
    medium: str
    window_start: float
    window_end: float
    periods: int
    transient_periods: int
    samples: int
    harmonics: int
    size: float | None
    keulegan_carpenter: float | None
    stokes_number: float | None
    rho: float | None
    displaced_volume: float | None
    restoring: float | None
    notes: list[str]
    components: list[PmmComponent]
    stored_id: int
    replaced: bool

class PmmAnalysis:
    runs: list[PmmRun]
    stored: bool
    database: str
    def text(self) -> str: ...
    def json(self) -> str: ...

class PmmRunSummary:
    id: int
    body: str
    dof: str
    amplitude: float
    amplitude_unit: str
    period: float
    omega: float
    medium: str
    restoring: float | None
    added_mass: float | None
    damping: float | None
    added_mass_unit: str
    damping_unit: str
    source_path: str
    created_at: str

class PmmRunList:
    runs: list[PmmRunSummary]
    def text(self) -> str: ...
    def json(self) -> str: ...

class PmmDeletedRun:
    id: int
    body: str
    dof: str
    source_path: str

class PmmDeletion:
    database: str
    deleted: list[PmmDeletedRun]
    def text(self) -> str: ...
    def json(self) -> str: ...

class AddedMassEntry:
    row: str
    column: str
    name: str
    unit: str
    runs: int
    added_mass: float
    added_mass_se: float
    added_mass_spread: float
    damping: float
    damping_se: float
    omega_min: float
    omega_max: float
    kc_min: float | None
    kc_max: float | None
    pmm_runs: list[int]

class AddedMassFrequency:
    dof: str
    omega: float
    period: float
    runs: int
    amplitude_min: float
    amplitude_max: float
    added_mass: float
    added_mass_se: float
    damping: float
    damping_se: float
    used: bool

class QuadraticDampingFit:
    dof: str
    omega: float
    amplitudes: list[float]
    linear: float
    linear_se: float
    quadratic: float
    quadratic_se: float

class AddedMassMatrix:
    body: str
    omega: float
    period: float
    records: int
    other_frequency_records: int
    @property
    def added_mass(self) -> np.ndarray: ...
    @property
    def added_mass_se(self) -> np.ndarray: ...
    @property
    def damping(self) -> np.ndarray: ...
    @property
    def damping_se(self) -> np.ndarray: ...
    entries: list[AddedMassEntry]
    missing: list[str]
    notes: list[str]
    positive_definite: bool
    smallest_eigenvalue: float
    quadratic_damping: list[QuadraticDampingFit]
    by_frequency: list[AddedMassFrequency]
    def text(self) -> str: ...
    def json(self) -> str: ...

class SuggestedKey:
    key: list[float]
    sd_before: float

class Suggestion:
    surface: str
    output: str
    unit: str
    axes: list[str]
    lower: list[float]
    upper: list[float]
    resolution: list[float]
    resolution_given: list[bool]
    mirror: str
    domain: str
    candidates: int
    imported_skipped: int
    running_skipped: int
    runs: list[SuggestedKey]
    largest_sd_after: float
    manifest: str
    def text(self) -> str: ...
    def json(self) -> str: ...

def grid_convergence(database: Database, *, body: str, mesh_parameter: str = "mesh", volume: float | None = None,
                     dimension: int = 3, allow_unconverged: bool = False, store: bool = True) -> GciStudy: ...
def analyse_pmm(inputs: Union[_Path, Sequence[_Path]], *, body: str = "", axes: str = "",
                origin: Sequence[float] | None = None, ref_point: Sequence[float] | None = None,
                rho: float | None = None, nu: float | None = None, set: Mapping[str, float] | None = None,
                columns: Mapping[str, str] | None = None, units: Mapping[str, str] | None = None,
                sign: str | None = None, motion: str | None = None, amplitude: float | None = None,
                period: float | None = None, phase: float = 0.0, ccl: str | None = None, harmonics: int = 1,
                start: float | None = None, stream: bool = False, volume: float | None = None,
                restoring: float | None = None, size: float | None = None, jobs: int = 0) -> PmmAnalysis: ...
def store_pmm(database: Database, analysis: PmmAnalysis) -> None: ...
def pmm_runs(database: Database, body: str | None = None) -> PmmRunList: ...
def delete_pmm_runs(database: Database, ids: Iterable[int]) -> PmmDeletion: ...
def added_mass_matrix(database: Database, body: str, *, same: Mapping[str, str] | None = None, zero: _Texts = None,
                      period: float | None = None, allow_indefinite: bool = False) -> AddedMassMatrix: ...
def suggest_runs(database: Database, surface: str, *, count: int = 5, bounds: _Texts = None,
                 output: str | None = None, candidates: int = 4096, round: _Texts = None, running: _Texts = None,
                 manifest: _Path | None = None) -> Suggestion: ...

class BodyReference:
    body: str
    length: float
    areas: dict[str, float]
    default_area: str
    draft: float
    displaced_volume: float
    moment_reference_point: tuple[float, float, float]
    updated_at: str
    def text(self) -> str: ...
    def json(self) -> str: ...

class BodyReferences:
    database: str
    bodies: list[BodyReference]
    def text(self) -> str: ...
    def json(self) -> str: ...

class RunCoefficients:
    database: str
    gravity: float
    references: list[dict[str, Any]]
    id: npt.NDArray[np.int64]
    body: list[str]
    velocity: dict[str, npt.NDArray[np.float64]]
    disturbances: dict[str, npt.NDArray[np.float64]]
    speed: npt.NDArray[np.float64]
    density: npt.NDArray[np.float64]
    kinematic_viscosity: npt.NDArray[np.float64]
    reynolds: npt.NDArray[np.float64]
    froude: npt.NDArray[np.float64]
    coefficients: dict[str, npt.NDArray[np.float64]]
    note: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...
    def csv(self) -> str: ...

def set_body_reference(database: Database, body: str, *, length: float | None = None,
                       areas: Mapping[str, float] | None = None, default_area: str | None = None,
                       remove_areas: _Texts = None, draft: float | None = None, volume: float | None = None,
                       moment_point: Sequence[float] | None = None, unset: _Texts = None) -> BodyReference: ...
def body_references(database: Database, body: str | None = None) -> BodyReferences: ...
def run_coefficients(database: Database, *, body: str | None = None, where: _Texts = None,
                     exclude_runs: Iterable[int] | None = None, area: str | None = None) -> RunCoefficients: ...
def plot_coefficient(database: Database, *, coefficient: str = "C_X", against: str = "Re", area: str | None = None,
                     body: str | None = None, where: _Texts = None, exclude_runs: Iterable[int] | None = None,
                     image: _Path | None = None, size: str | None = None) -> PlotFiles: ...

class SurfaceIntegration:
    file: str
    format: str
    force: tuple[float, float, float]
    force_pressure: tuple[float, float, float]
    force_viscous: tuple[float, float, float]
    moment: tuple[float, float, float]
    moment_pressure: tuple[float, float, float]
    moment_viscous: tuple[float, float, float]
    reference_point: tuple[float, float, float]
    area: float
    signed_volume: float
    faces: int
    closed: bool
    warnings: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

def integrate_surface(path: _Path, *, body: str | None = None, format: str = "auto",
                      settings: Mapping[str, Any] | None = None, sidecars: bool = True) -> SurfaceIntegration: ...

class PlotFiles:
    title: str
    image: str
    data: str
    script: str
    format: str
    width: int
    height: int
    series: list[dict[str, Any]]
    def text(self) -> str: ...
    def json(self) -> str: ...

def plot_fit(database: Database, name: str, *, image: _Path | None = None, size: str | None = None) -> PlotFiles: ...
def plot_curves(database: Database, name: str | None = None, *, body: str | None = None, dof: str | None = None,
                terms: str | None = None, by: str | None = None, curve: str = "polynomial:2",
                image: _Path | None = None, size: str | None = None) -> PlotFiles: ...
def plot_surface(database: Database, name: str, *, output: str | None = None, image: _Path | None = None,
                 size: str | None = None) -> PlotFiles: ...
def plot_history(database: Database, run: int, *, image: _Path | None = None, size: str | None = None) -> PlotFiles: ...
def plot_simulation(trajectory: _Path, *, experiment: _Path | None = None, component: str = "r",
                    image: _Path | None = None, size: str | None = None) -> PlotFiles: ...
def plot_steady(vehicle: str, database: _Path | None = None, *, dof: str = "N", taus: Sequence[float] = (),
                tau_from: float | None = None, tau_to: float | None = None, count: int = 6,
                experiment_points: _Path | None = None, samples: int = 0, seed: int = 1,
                percentiles: Sequence[float] = (), image: _Path | None = None, size: str | None = None) -> PlotFiles: ...

# ---- derivative models of several variables (hydrocoef derivatives) ----

class DerivativeCoefficient:
    term: str
    unit: str
    value: float
    std_error: float
    interval_low: float
    interval_high: float
    vif: float
    normalisation: str

class DerivativeModel:
    name: str
    body: str
    output: str
    terms: str
    template: str
    selection: str
    candidates: str
    where: str
    unit: str
    form: str
    coefficients: list[DerivativeCoefficient]
    covariance: list[float]
    condition_number: float
    rmse: float
    r2: float
    n: int
    weighting: str
    chi2_reduced: float
    covariance_scale: float
    interval_factor: float
    runs: list[int]
    warnings: list[str]
    id: int
    stale: bool
    created_at: str
    def text(self) -> str: ...
    def json(self) -> str: ...

class DerivativeModelList:
    models: list[DerivativeModel]
    def text(self) -> str: ...
    def json(self) -> str: ...

class DerivativeDeletion:
    name: str
    id: int
    def text(self) -> str: ...
    def json(self) -> str: ...

class DerivativeEvaluation:
    name: str
    output: str
    unit: str
    at: dict[str, float]
    value: float
    std_error: float
    basis: list[float]
    stale: bool
    def text(self) -> str: ...
    def json(self) -> str: ...

def fit_derivative_model(database: Database, *, body: str, output: str, terms: str = "", template: str = "",
                         select: str = "", seed: int = 1, where: str | Sequence[str] | None = None,
                         exclude_runs: Sequence[int] | None = None, name: str = "", replace: bool = False,
                         store: bool = True, weighted: bool = True, vif_threshold: float = 10.0,
                         u0: float | None = None) -> DerivativeModel: ...
def list_derivative_models(database: Database, body: str = "") -> DerivativeModelList: ...
def show_derivative_model(database: Database, name: str, *, form: str = "dimensional", length: float | None = None,
                          speed: float | None = None, density: float | None = None, draft: float | None = None,
                          mass: float | None = None, volume: float | None = None,
                          gravity: float = 9.80665) -> DerivativeModel: ...
def delete_derivative_model(database: Database, name: str) -> DerivativeDeletion: ...
def evaluate_derivative_model(database: Database, name: str, at: Mapping[str, float]) -> DerivativeEvaluation: ...

class PmmDerivative:
    name: str
    value: float
    std_error: float
    unit: str
    source: str
    prime: float | None
    prime_std_error: float | None
    normalisation: str

class PmmFrequencyDerivatives:
    motion: str
    dof: str
    speed: float
    omega: float
    period: float
    omega_prime: float | None
    runs: int
    amplitude_min: float
    amplitude_max: float
    amplitude_unit: str
    pmm_runs: list[int]
    derivatives: list[PmmDerivative]

class PmmDerivativeRun:
    id: int
    dof: str
    speed: float
    amplitude: float
    omega: float
    source_path: str
    derivatives: list[PmmDerivative]

class PmmDerivatives:
    body: str
    length: float | None
    density: float | None
    length_from: str
    density_from: str
    sets: list[PmmFrequencyDerivatives]
    runs: list[PmmDerivativeRun]
    other_runs: int
    notes: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

def pmm_derivatives(database: Database, body: str, *, runs: Sequence[int] | None = None, speed: float | None = None,
                    length: float | None = None, density: float | None = None,
                    prime: bool = False) -> PmmDerivatives: ...
# ---- FMUs (hydrocoef export-fmu) ----
class FmuVariable:
    value_reference: int
    name: str
    causality: str
    unit: str
    start: float | None
    description: str

class FmuExportResult:
    body: str
    surface: str
    vehicle: str
    kind: str
    model_identifier: str
    guid: str
    file: str
    runtime_file_bytes: int
    binary_bytes: int
    fmu_bytes: int
    variables: list[FmuVariable]
    notes: list[str]
    def text(self) -> str: ...
    def json(self) -> str: ...

def export_fmu(
    database: Database, body: str, *, surface: str = "", output: str, vehicle: str = ""
) -> FmuExportResult: ...
# ---- runtime files through libhydrocoef_runtime ----
class RuntimeModel:
    def __init__(self, path: _Path) -> None: ...
    @property
    def surfaces(self) -> list[str]: ...
    @property
    def has_vehicle(self) -> bool: ...
    @property
    def disturbances(self) -> list[str]: ...
    def axes(self, surface: str) -> list[str]: ...
    def outputs(self, surface: str) -> list[str]: ...
    def evaluate(self, surface: str, x: npt.ArrayLike) -> dict[str, np.ndarray | None]: ...
    def vehicle_step_rk4(self, x: npt.ArrayLike, tau: npt.ArrayLike, current: npt.ArrayLike | None, dt: float,
                         disturbances: npt.ArrayLike | None = None) -> np.ndarray: ...
# ---- derivative exports (hydrocoef derivatives export) and scaling (hydrocoef scale) ----
class DerivativeExportResult:
    database: str
    format: str
    form: str
    file: str
    body: str
    models: list[str]
    outputs: list[str]
    terms: list[str]
    stale: list[bool]
    function_name: str
    inputs: list[str]
    dropped: list[str]
    notes: list[str]
    bytes: int
    content: str
    def text(self) -> str: ...
    def json(self) -> str: ...

def export_derivatives(database: Database, names: Sequence[str], *, format: str, output: str | os.PathLike[str],
                       form: str = "dimensional", length: float | None = None, speed: float | None = None,
                       density: float | None = None, draft: float | None = None, mass: float | None = None,
                       volume: float | None = None, gravity: float = 9.80665, link: str | None = None,
                       link_axes: str | None = None, drop_unrepresentable: bool = False,
                       added_mass: str | None = None, added_mass_matrix: str | os.PathLike[str] | None = None,
                       mass_diagonal: str | None = None,
                       mass_matrix: str | os.PathLike[str] | None = None) -> DerivativeExportResult: ...

class ResistanceScalingPoint:
    speed_from: float
    speed_to: float
    force_from: float
    force_to: float
    resistance_from: float
    resistance_to: float
    froude_from: float
    froude_to: float
    reynolds_from: float
    reynolds_to: float
    friction_from: float
    friction_to: float
    wave: float
    residual: float
    total_from: float
    total_to: float

class ResistanceScalingResult:
    method: str
    sign: str
    wave: str
    one_plus_k: float
    form_factor_method: str
    prohaska_slope: float
    form_factor: str
    points: list[ResistanceScalingPoint]
    assumptions: list[str]
    fit: str
    terms: str
    coefficients_from: list[float]
    coefficients_to: list[float]
    units: list[str]
    max_relative_deviation: float
    def text(self) -> str: ...
    def json(self) -> str: ...

def scale_surge_resistance(database: Database | None = None, *, from_length: float, from_area: float,
                           from_viscosity: float, from_density: float, to_length: float, to_area: float,
                           to_viscosity: float, to_density: float, wave: str, form_factor: str = "",
                           points: Sequence[tuple[float, float]] | None = None, fit: str = "",
                           speeds: Sequence[float] | None = None, target_speeds: Sequence[float] | None = None,
                           from_roughness: float | None = None, to_roughness: float | None = None,
                           from_air_area: float | None = None, to_air_area: float | None = None,
                           gravity: float = 9.80665, sign: str = "on-body") -> ResistanceScalingResult: ...
