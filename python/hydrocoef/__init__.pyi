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
                     replace: bool = False, also: str = "", jobs: int = 0) -> ImportSummary: ...
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
                      gp_degree: int = 1, gp_starts: int = 5) -> SurfaceInfo: ...
    def rebuild_surfaces(self, name: str | None = None, *, stale_only: bool = False) -> list[SurfaceInfo]: ...
    def surfaces(self, body: str | None = None) -> list[SurfaceInfo]: ...
    def surface(self, name: str) -> Surface: ...

def simulate(vehicle: Union[_Path, Mapping[str, Any]], scenario: Union[_Path, Mapping[str, Any]],
             database: Union[_Path, Database, None] = None) -> Table: ...
