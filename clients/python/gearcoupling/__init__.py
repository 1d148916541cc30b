"""gearcoupling: the crowned-tooth gear-coupling model of Guo et al. (NREL) for Python.

In process (all cores, the GIL released while the core runs) and through gearcoupling-service
(``Client``). SI units everywhere: N, m, N·m, rad; the unit ends every name. See docs/python.md.
"""

from gearcoupling._gearcoupling import (  # noqa: F401
    Coupling,
    InvalidInput,
    ModelError,
    NotConverged,
    Timeout,
    catalogue,
    estimate_friction,
    estimate_friction_many,
    induced_moments,
    induced_moments_many,
    jam_angle,
    restoring_torque,
    tooth_contact,
    tooth_contact_many,
)
from gearcoupling._gearcoupling import (  # noqa: F401
    Model,
    Recording,
    bundled_data_dir,
    diagnose,
    read_recording,
    validate,
)
from gearcoupling._results import (  # noqa: F401
    CaseTable,
    DiagnosisResult,
    FrictionEstimateResult,
    InducedMomentsResult,
    JamAngleResult,
    RestoringTorqueResult,
    Result,
    ToothContactResult,
    ValidationResult,
)

__all__ = [
    "Coupling", "InvalidInput", "ModelError", "NotConverged", "Timeout", "catalogue",
    "tooth_contact", "induced_moments", "jam_angle", "restoring_torque", "estimate_friction",
    "tooth_contact_many", "induced_moments_many", "estimate_friction_many",
    "Model", "Recording", "bundled_data_dir", "read_recording", "validate", "diagnose",
    "Result", "CaseTable", "ToothContactResult", "InducedMomentsResult", "JamAngleResult",
    "RestoringTorqueResult", "FrictionEstimateResult", "ValidationResult", "DiagnosisResult",
]

try:
    from gearcoupling._gearcoupling import Client  # noqa: F401  (built with the service)

    __all__.append("Client")
except ImportError:  # pragma: no cover
    pass

__version__ = "@PROJECT_VERSION@"
