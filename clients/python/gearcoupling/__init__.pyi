# Type stubs of the gearcoupling module (docs/python.md). SI units everywhere: N, m, N·m, rad,
# Pa; the unit ends each name (_deg in results as the CLI's JSON prints them, each with its _rad
# attribute beside it).
import os
from typing import Any, Literal, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

class ModelError(Exception):
    """Base of every error the model raises (also the service's refusals); .field names the
    input where the error names one, else None."""
    field: str | None
    index: int

class InvalidInput(ModelError, ValueError):
    """An input outside its range: .field names it (e.g. 'operating_point.misalignment_rad');
    .index is the failed case of a vectorised call."""
    field: str
    index: int

class NotConverged(ModelError):
    """An iteration (eqs 20-22, eq 23's root) stopped before meeting its tolerance."""
    index: int

class Timeout(TimeoutError):
    """No reply from gearcoupling-service within the client's timeout."""

class Coupling:
    """A validated coupling: a catalogue name, a coupling file, or a dict with the file's fields."""
    def __init__(self, source: CouplingSource) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def catalogue_name(self) -> str | None: ...
    @property
    def teeth(self) -> int: ...
    @property
    def pitch_radius_m(self) -> float: ...
    @property
    def crown_radius_m(self) -> float: ...
    @property
    def mesh_stiffness_n_per_m(self) -> float: ...
    @property
    def jam_angle_rad(self) -> float: ...

CouplingSource = Union[Coupling, str, os.PathLike[str], Mapping[str, Any]]
ArrayLike = Union[float, Sequence[float], Sequence[Sequence[float]], npt.NDArray[np.float64]]
Errors = Literal["raise", "mask"]
# Renames: "msy_knm=Ch3_kNm,..." as validate --columns, or {"msy_knm": "Ch3_kNm"}.
Columns = Union[str, Mapping[str, str], None]
# Quantities read with the sign flipped: "torque,msy" as validate --negate, or ["torque"].
Negate = Union[str, Sequence[str], None]

class CaseTable(dict[str, np.ndarray]):
    """A vectorised call's columns, each an array of the inputs' broadcast shape."""
    inputs: dict[str, np.ndarray]
    index: Any  # pandas.Index of the first Series input, or None
    def __init__(self, columns: Mapping[str, np.ndarray],
                 inputs: Mapping[str, np.ndarray] | None = None, index: Any = None) -> None: ...
    @property
    def shape(self) -> tuple[int, ...]: ...
    def to_frame(self) -> Any:  # pandas.DataFrame
        """One row per case (C order): the inputs, then the columns; indexed by ``index``."""
    def series(self, name: str) -> Any:  # pandas.Series
        """One column with the inputs' index."""

CaseArrays = CaseTable

class Result:
    """A result message: fields as attributes (units in the names; X_rad beside every X_deg),
    .to_dict(), .to_json(), .to_frame()."""
    def __getattr__(self, name: str) -> Any: ...
    def fields(self) -> list[str]: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_json(self) -> str: ...
    def to_row(self) -> dict[str, Any]: ...
    def to_frame(self, field: str | None = None) -> Any:  # pandas.DataFrame
        ...

class ToothContactResult(Result):
    coupling: str
    total_normal_load_n: float
    mean_tooth_load_n: float
    peak_tooth_load_n: float
    elastic_deformation_m: float
    max_separation_m: float
    offset_alpha_deg: float
    offset_alpha_rad: float
    max_contact_offset_m: float
    teeth_in_contact: int
    max_load_tooth: int
    max_tooth_load_n: float
    sum_tooth_loads_n: float
    edge_loaded: bool

class InducedMomentsResult(Result):
    coupling: str
    q: float
    teeth_in_contact: int
    max_tooth_load_n: float
    moment_y_dd_nm: float
    moment_z_dd_nm: float
    moment_y_nm: float
    moment_z_nm: float
    sensor_moment_y_nm: float
    sensor_moment_z_nm: float
    self_weight_moment_nm: float
    magnitude_nm: float
    direction_deg: float
    direction_rad: float
    teeth_summed: int

class JamAngleResult(Result):
    coupling: str
    angle_deg: float
    angle_rad: float
    governing: str
    facewidth_deg: float
    facewidth_rad: float
    radial_deg: float
    radial_rad: float
    crown_radius_m: float
    crown_radius_derived: bool

class RestoringTorqueResult(Result):
    coupling: str
    torque_nm: float

class FrictionEstimateResult(Result):
    coupling: str
    friction_coefficient: float
    moment_z_dd_nm: float

class ValidationResult(Result):
    recording: str
    def samples(self, model: int | str = 0, threads: int = 0) -> Any:  # pandas.DataFrame
        """Per sample: inputs, measured, predicted, residual (Model.predict's columns)."""

class DiagnosisResult(Result):
    recording: str
    model: Model  # the model with the effects found (the JSON's "model" is its name)
    summary: str
    def samples(self, model: int | str = 0, threads: int = 0) -> Any:  # pandas.DataFrame
        """Per sample: inputs, measured, predicted, residual; model 0 given, 1 found."""

def catalogue() -> list[str]:
    """The catalogue's coupling names ($GEARCOUPLING_CATALOG, else the bundled ones)."""

def bundled_data_dir(kind: Literal["couplings", "models", "recordings"]) -> os.PathLike[str]:
    """The bundled data's folder of that kind."""

def tooth_contact(coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                  direction_rad: float = 0.0, *, mu: float = 0.0, slices: int = 20,
                  tolerance: float = 1e-9, max_iterations: int = 100) -> ToothContactResult:
    """Tooth contact at one load case (eqs 5-22)."""

def induced_moments(coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                    direction_rad: float = 0.0, *, mu: float, slices: int = 20,
                    tolerance: float = 1e-9, max_iterations: int = 100) -> InducedMomentsResult:
    """Induced bending moments at one load case (eqs 36-48) [N·m]."""

def jam_angle(coupling: CouplingSource) -> JamAngleResult:
    """The jam angle and its three criteria (eqs 23-35)."""

def restoring_torque(coupling: CouplingSource) -> RestoringTorqueResult:
    """The torque that lifts the hub off the sleeve (eqs 49-53) [N·m]."""

def estimate_friction(coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                      direction_rad: float, sensor_moment_y_nm: float,
                      sensor_moment_z_nm: float) -> FrictionEstimateResult:
    """mu [-] from measured torque, misalignment, direction and sensor moments (eqs 1-4)."""

def tooth_contact_many(coupling: CouplingSource, torque_nm: ArrayLike, misalignment_rad: ArrayLike,
                       direction_rad: ArrayLike = 0.0, *, slices: int = 20, tolerance: float = 1e-9,
                       max_iterations: int = 100, threads: int = 0,
                       errors: Errors = "raise") -> CaseTable:
    """tooth_contact over many cases on all cores: a dict of numpy arrays."""

def induced_moments_many(coupling: CouplingSource, torque_nm: ArrayLike, misalignment_rad: ArrayLike,
                         direction_rad: ArrayLike = 0.0, *, mu: ArrayLike, slices: int = 20,
                         tolerance: float = 1e-9, max_iterations: int = 100, threads: int = 0,
                         errors: Errors = "raise") -> CaseTable:
    """Contact and moments (eqs 5-48) over many cases on all cores, as gearcoupling batch."""

def estimate_friction_many(coupling: CouplingSource, torque_nm: ArrayLike, misalignment_rad: ArrayLike,
                           direction_rad: ArrayLike, sensor_moment_y_nm: ArrayLike,
                           sensor_moment_z_nm: ArrayLike, *, threads: int = 0,
                           errors: Errors = "raise") -> CaseTable:
    """estimate_friction over many measurements on all cores."""

class Model:
    """A model: a coupling and the library's effects in order (idl/model_config.proto)."""
    def __init__(self, source: Union[Model, str, os.PathLike[str], Mapping[str, Any]]) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def coupling(self) -> str: ...
    @property
    def effects(self) -> list[str]: ...
    def effect_parameters(self, name: str) -> dict[str, float]: ...
    def with_effect(self, spec: str) -> Model: ...
    def predict(self, recording: RecordingSource, *, columns: Columns = None,
                negate: Negate = None, threads: int = 0) -> CaseTable:
        """Every sample's prediction and residual (predicted - measured) [N·m]."""
    def to_text(self) -> str: ...
    def write(self, path: Union[str, os.PathLike[str]]) -> None: ...

class Recording:
    """A test-cell recording read whole (docs/recordings.md)."""
    @property
    def source(self) -> str: ...
    @property
    def rows_read(self) -> int: ...
    @property
    def excluded_rows(self) -> int: ...
    @property
    def problems(self) -> list[dict[str, Any]]: ...
    @property
    def ignored_columns(self) -> list[str]: ...
    def to_arrays(self) -> dict[str, np.ndarray]: ...
    def __len__(self) -> int: ...

RecordingSource = Union[Recording, str, os.PathLike[str], Any]  # Any: a pandas.DataFrame
ModelSource = Union[Model, str, os.PathLike[str], Mapping[str, Any]]

def read_recording(source: RecordingSource, *, columns: Columns = None,
                   negate: Negate = None) -> Recording: ...
def validate(recording: RecordingSource, model: ModelSource, *, add: str = "",
             reference_torque_nm: float = 1.5e6, threads: int = 0, columns: Columns = None,
             negate: Negate = None, html: Union[str, os.PathLike[str], None] = None,
             force_scale: bool = False) -> ValidationResult: ...
def diagnose(recording: RecordingSource, model: ModelSource, *,
             write_model: Union[str, os.PathLike[str], None] = None, threads: int = 0,
             columns: Columns = None, negate: Negate = None,
             force_scale: bool = False) -> DiagnosisResult: ...

class Client:
    """The same calculations through gearcoupling-service over DDS ($CYCLONEDDS_URI)."""
    def __init__(self, domain: int = 0, timeout: float = 5.0) -> None:
        """domain: DDS domain id [0, 232]; timeout: per call, discovery included [s]."""
    def tooth_contact(self, coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                      direction_rad: float = 0.0, *, mu: float = 0.0, slices: int = 20,
                      tolerance: float = 1e-9, max_iterations: int = 100) -> ToothContactResult: ...
    def induced_moments(self, coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                        direction_rad: float = 0.0, *, mu: float, slices: int = 20,
                        tolerance: float = 1e-9, max_iterations: int = 100) -> InducedMomentsResult: ...
    def jam_angle(self, coupling: CouplingSource) -> JamAngleResult: ...
    def restoring_torque(self, coupling: CouplingSource) -> RestoringTorqueResult: ...
    def estimate_friction(self, coupling: CouplingSource, torque_nm: float, misalignment_rad: float,
                          direction_rad: float, sensor_moment_y_nm: float,
                          sensor_moment_z_nm: float) -> FrictionEstimateResult: ...
    def tooth_contact_many(self, coupling: CouplingSource, torque_nm: ArrayLike,
                           misalignment_rad: ArrayLike, direction_rad: ArrayLike = 0.0, *,
                           slices: int = 20, tolerance: float = 1e-9, max_iterations: int = 100,
                           in_flight: int = 256, errors: Errors = "raise") -> CaseTable: ...
    def induced_moments_many(self, coupling: CouplingSource, torque_nm: ArrayLike,
                             misalignment_rad: ArrayLike, direction_rad: ArrayLike = 0.0, *,
                             mu: ArrayLike, slices: int = 20, tolerance: float = 1e-9,
                             max_iterations: int = 100, in_flight: int = 16384,
                             errors: Errors = "raise") -> CaseTable: ...
    def estimate_friction_many(self, coupling: CouplingSource, torque_nm: ArrayLike,
                               misalignment_rad: ArrayLike, direction_rad: ArrayLike,
                               sensor_moment_y_nm: ArrayLike, sensor_moment_z_nm: ArrayLike, *,
                               in_flight: int = 256, errors: Errors = "raise") -> CaseTable: ...
    def wait_for_service(self, timeout: float) -> bool: ...
    def counters(self) -> dict[str, int]: ...
