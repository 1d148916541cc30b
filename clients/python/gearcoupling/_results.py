"""Result objects: the JSON the CLI prints with --json, as attributes (units in the names).

Every result is built from that JSON text (codec::to_json of the result's message,
idl/results.proto, idl/validation.proto, idl/diagnosis.proto): ``.to_json()`` is the CLI's
``--json`` output byte for byte, ``.to_dict()`` is it parsed, and each field is an attribute:
``r.sensor_moment_y_nm``, ``r.teeth[0].load_n``. Nested messages are Result objects, repeated
ones lists.
"""

from __future__ import annotations

import json
import math
from typing import Any


def _wrap(value: Any, radians: Any = None) -> Any:
    if isinstance(value, dict):
        return Result._from_dict(value, radians if isinstance(radians, dict) else None)
    if isinstance(value, list):
        exact = radians if isinstance(radians, list) and len(radians) == len(value) else None
        return [_wrap(item, exact[i] if exact else None) for i, item in enumerate(value)]
    return value


def _pandas():
    try:
        import pandas
    except ImportError as error:  # pragma: no cover (the tests have pandas)
        raise ImportError("to_frame() needs pandas (Debian: apt install python3-pandas)") from error
    return pandas


class Result:
    """A result message: its fields as attributes, ``to_dict()``, ``to_json()``, ``to_frame()``.

    Angles: the JSON has them in degrees (``direction_deg``), as the CLI prints them; each
    ``X_deg`` field also has the attribute ``X_rad``, the radians the core computed or was given
    (exactly: not converted back from the degrees), so angles come back in the unit they went in.
    """

    __slots__ = ("_dict", "_json", "_radians", "__dict__")

    def __init__(self, json_text: str, radians: dict | None = None) -> None:
        self._json = json_text
        self._dict = json.loads(json_text)
        self._radians = radians or {}

    @classmethod
    def _from_dict(cls, value: dict, radians: dict | None = None) -> "Result":
        result = cls.__new__(cls)
        result._json = None
        result._dict = value
        result._radians = radians or {}
        return result

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        try:
            return _wrap(self._dict[name], self._radians.get(name))
        except KeyError:
            pass
        if name.endswith("_rad") and name[:-4] + "_deg" in self._dict:
            exact = self._radians.get(name)
            return exact if exact is not None else math.radians(self._dict[name[:-4] + "_deg"])
        raise AttributeError(
            f"{type(self).__name__} has no field {name!r} (fields: {', '.join(self._dict)})"
        ) from None

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._dict) | set(self._radian_fields()))

    def _radian_fields(self) -> list[str]:
        return [key[:-4] + "_rad" for key in self._dict
                if key.endswith("_deg") and key[:-4] + "_rad" not in self._dict]

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

    def to_row(self) -> dict:
        """The scalar fields as one flat dict: nested messages' fields joined with ``_``
        (``operating_point_torque_nm``), each ``X_deg`` followed by its ``X_rad``; lists left out
        (``to_frame(field)`` gives one row per element)."""
        row: dict = {}

        def add(prefix: str, result: "Result") -> None:
            for key, value in result._dict.items():
                if isinstance(value, list):
                    continue
                if isinstance(value, dict):
                    add(prefix + key + "_", getattr(result, key))
                    continue
                row[prefix + key] = value
                if key.endswith("_deg") and key[:-4] + "_rad" not in result._dict:
                    row[prefix + key[:-4] + "_rad"] = getattr(result, key[:-4] + "_rad")

        add("", self)
        return row

    def to_frame(self, field: str | None = None):
        """A pandas DataFrame: one row of ``to_row()``; with ``field``, the repeated field's
        elements one row each (``r.to_frame("teeth")``: every tooth's load and angle)."""
        pandas = _pandas()
        if field is None:
            return pandas.DataFrame([self.to_row()])
        items = getattr(self, field)
        if not isinstance(items, list):
            raise ValueError(f"{field!r} is not a repeated field of {type(self).__name__}")
        return pandas.DataFrame([item.to_row() if isinstance(item, Result) else {field: item}
                                 for item in items])

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


class CaseTable(dict):
    """What a vectorised call returns: a dict of column name -> numpy array, every array of the
    inputs' broadcast shape (units end the names, as in the batch CSV), and ``inputs``, the
    arguments broadcast to that shape. ``to_frame()`` makes it one pandas DataFrame.

    ``index``: the pandas index of the first input given as a Series, when the cases are that
    Series' rows (else None); ``to_frame()`` and ``series()`` keep it, so results line up with
    the frame the inputs came from."""

    def __init__(self, columns: dict, inputs: dict | None = None, index: Any = None) -> None:
        super().__init__(columns)
        self.inputs = dict(inputs or {})
        self.index = index

    @property
    def shape(self) -> tuple:
        """The broadcast shape of the inputs, which every column has."""
        for value in self.values():
            return value.shape
        return ()

    def to_frame(self):
        """A pandas DataFrame, one row per case in C order (arrays flattened): the inputs first
        (``torque_nm``, ``misalignment_rad``, ...), then the columns."""
        pandas = _pandas()
        data = {}
        for name, value in list(self.inputs.items()) + list(self.items()):
            data[name] = value.reshape(-1)
        return pandas.DataFrame(data, index=self.index)

    def series(self, name: str):
        """Column ``name`` as a pandas Series with the inputs' index (``index``, else 0..n-1)."""
        pandas = _pandas()
        if name not in self:
            raise KeyError(f"{name!r} is not a column (columns: {', '.join(self)})")
        return pandas.Series(self[name].reshape(-1), index=self.index, name=name)


def _samples(result: Result, model: int | str = 0, threads: int = 0):
    sources = getattr(result, "_sample_sources", None)
    if sources is None:
        raise ValueError(f"this {type(result).__name__} was not made by gearcoupling: no samples")
    recording, columns, models = sources
    if isinstance(model, str):
        names = [m.name for m in models]
        if model not in names:
            raise ValueError(f"model {model!r} is not one of {names}")
        model = names.index(model)
    if not 0 <= model < len(models):
        raise ValueError(f"model {model} is out of range: 0 to {len(models) - 1}")
    from gearcoupling._gearcoupling import read_recording

    return models[model].predict(read_recording(recording, columns=columns),
                                 threads=threads).to_frame()


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
    """A recording against a model: ``gearcoupling validate --json``; ``samples()`` its
    per-sample predictions and residuals."""

    def samples(self, model: int | str = 0, threads: int = 0):
        """Every sample of the recording with the model's prediction and residual, as a pandas
        DataFrame (``Model.predict``'s columns): ``model`` 0 (or its name) is the model
        validated, 1 the model with the effect added (``add=``)."""
        return _samples(self, model, threads)


class DiagnosisResult(Result):
    """What a model lacks: ``gearcoupling diagnose --json``; ``.model`` is the model with the
    effects found (a gearcoupling.Model), ``samples()`` the per-sample predictions and
    residuals."""

    def samples(self, model: int | str = 0, threads: int = 0):
        """Every sample of the recording with a model's prediction and residual, as a pandas
        DataFrame (``Model.predict``'s columns): ``model`` 0 is the model diagnosed, 1 the model
        found (``.model``); or a model's name."""
        return _samples(self, model, threads)
