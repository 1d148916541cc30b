"""Result objects: the JSON the CLI prints with --json, as attributes (units in the names).

Every result is built from that JSON text (codec::to_json of the result's message,
idl/results.proto, idl/validation.proto, idl/diagnosis.proto): ``.to_json()`` is the CLI's
``--json`` output byte for byte, ``.to_dict()`` is it parsed, and each field is an attribute:
``r.sensor_moment_y_nm``, ``r.teeth[0].load_n``. Nested messages are Result objects, repeated
ones lists.
"""

from __future__ import annotations

import json
from typing import Any


def _wrap(value: Any) -> Any:
    if isinstance(value, dict):
        return Result._from_dict(value)
    if isinstance(value, list):
        return [_wrap(item) for item in value]
    return value


class Result:
    """A result message: its fields as attributes, ``to_dict()``, ``to_json()``."""

    __slots__ = ("_dict", "_json", "__dict__")

    def __init__(self, json_text: str) -> None:
        self._json = json_text
        self._dict = json.loads(json_text)

    @classmethod
    def _from_dict(cls, value: dict) -> "Result":
        result = cls.__new__(cls)
        result._json = None
        result._dict = value
        return result

    def __getattr__(self, name: str) -> Any:
        try:
            return _wrap(self._dict[name])
        except KeyError:
            raise AttributeError(
                f"{type(self).__name__} has no field {name!r} (fields: {', '.join(self._dict)})"
            ) from None

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._dict))

    def fields(self) -> list[str]:
        """The message's field names, in the order the JSON prints them."""
        return list(self._dict)

    def to_dict(self) -> dict:
        """The result as the CLI's ``--json`` prints it, parsed (a fresh copy)."""
        return json.loads(self.to_json())

    def to_json(self) -> str:
        """The CLI's ``--json`` output for this result, byte for byte (top-level results)."""
        if self._json is None:
            self._json = json.dumps(self._dict, indent=1) + "\n"
        return self._json

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Result) and self._dict == other._dict

    def __repr__(self) -> str:
        shown = []
        for key, value in self._dict.items():
            shown.append(f"{key}=..." if isinstance(value, (dict, list)) else f"{key}={value!r}")
            if len(shown) == 8:
                shown.append("...")
                break
        return f"{type(self).__name__}({', '.join(shown)})"


class ToothContactResult(Result):
    """Tooth contact at one load case (eqs 5-22): ``gearcoupling contact --json``."""


class InducedMomentsResult(Result):
    """Induced bending moments (eqs 36-48): ``gearcoupling moments --json``."""


class JamAngleResult(Result):
    """The jam angle (eqs 23-35): ``gearcoupling jam-angle --json``."""


class RestoringTorqueResult(Result):
    """The restoring torque (eqs 49-53): ``gearcoupling restoring-torque --json``."""


class FrictionEstimateResult(Result):
    """The friction coefficient from measurements (eqs 1-4): ``gearcoupling friction --json``."""


class ValidationResult(Result):
    """A recording against a model: ``gearcoupling validate --json``."""


class DiagnosisResult(Result):
    """What a model lacks: ``gearcoupling diagnose --json``; ``.model`` is the model with the
    effects found (a gearcoupling.Model)."""
