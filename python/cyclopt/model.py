"""Feet and the walker's periodic gait (seed 001 ch. 2-5), computed by cyclopt's C++ libraries.

Units are SI throughout (m, rad, s, kg, N, J); every returned mapping names its unit in its keys,
e.g. ``"step_length [m]"``. Long calls release the GIL.
"""

from __future__ import annotations

import functools
import json
from dataclasses import dataclass
from typing import Any, Mapping, Optional

import numpy as np

from . import _model


class Foot:
    """A foot: the point foot or a rolling HM / HMT foot (seed 001 ch. 3, appendix E).

    ``Foot(model="HM", h_F=..., l_HA=..., ...)`` takes the fields of a foot spec
    (docs/feet.md: lengths in m, angles and regularisations k in rad, ``density`` in kg/m^2,
    ``theta_F0`` in rad, ``periodic_terms``, ``name``) and checks them as the server does:
    a bad value raises :class:`cyclopt.SpecError` whose ``field`` names it (``"foot.k_HM"``).
    """

    def __init__(self, **fields: Any) -> None:
        self._spec = _model.foot_from_json(json.dumps(fields))
        self._json = self._spec.to_json()

    @classmethod
    def preset(cls, name: str) -> "Foot":
        """A named foot (``"point"``, ``"P1-barefoot-left-HM"``, ...; :meth:`preset_names`)."""
        foot = cls.__new__(cls)
        foot._spec = _model.foot_preset(name)
        foot._json = foot._spec.to_json()
        return foot

    @staticmethod
    def preset_names() -> list[str]:
        return _model.foot_preset_names()

    @property
    def model(self) -> str:
        """``"point"``, ``"HM"`` or ``"HMT"``."""
        return self._spec.model

    @property
    def name(self) -> str:
        return self._spec.name

    def to_dict(self) -> dict[str, Any]:
        """The foot spec as a job spec's ``"foot"`` takes it."""
        return json.loads(self._json)

    def mass_properties(self, density: Optional[float] = None) -> dict[str, float]:
        """Area, mass, centre of mass, inertias and theta_F0 at ``density`` (kg/m^2; default: the
        foot's own), appendix E: keys ``"mass [kg]"``, ``"com_x [m]"``, ``"inertia_com [kg m^2]"``, ..."""
        return _model.mass_properties(self._spec, density)

    def rolling(self, theta: Any) -> dict[str, np.ndarray]:
        """The rolling function F and its derivatives at foot angles ``theta`` (rad, eq. 3.19 / 3.22):
        ``"F [m]"`` (ankle x minus x_0), ``"dF [m]"`` (ankle height), ``"ddF [m]"``, ``"dddF [m]"``
        and ``"curvature_radius [m]"`` (eq. 3.14)."""
        return _model.rolling(self._spec, np.atleast_1d(np.asarray(theta, dtype=float)))

    def __repr__(self) -> str:
        return f"Foot({self.to_dict()!r})"


@dataclass
class Gait:
    """A periodic gait: ``scalars`` (``"f_mech [-]"`` eq. 5.102, ``"step_length [m]"``,
    ``"floquet_multiplier [-]"`` eq. 5.89, ``"real"``, ``"stable"``, ...), ``trajectories`` on the
    phase grid (``"time [s]"``, ``"q [rad]"`` rows theta and q_b, ``"torque [N m]"``, ...; None
    without a real gait) and the gait parameters ``x`` (rad, eq. 5.92)."""

    scalars: dict[str, Any]
    trajectories: Optional[dict[str, np.ndarray]]
    x: np.ndarray


@dataclass
class GaitOptimum(Gait):
    """An optimal gait with ``values``, the point a job would store (its ``"solver"`` summary:
    ``termination``, ``success``, ``iterations``, ...)."""

    values: dict[str, Any]

    @property
    def converged(self) -> bool:
        return bool(self.values.get("solver", {}).get("success", False))


@functools.lru_cache(maxsize=16)
def _cached_scene(foot_json: str, speed: float, fields_json: str) -> Any:
    spec = {"scene": "walker", "task": "optimise", "foot": json.loads(foot_json), "speed": speed,
            **json.loads(fields_json)}
    return _model.gait_scene(json.dumps(spec))


def _scene(foot: Foot, speed: float, fields: Mapping[str, Any]) -> Any:
    """The walker problem (its fields checked, its model and evaluator built) of recent calls."""
    return _cached_scene(foot._json, float(speed), json.dumps(fields, sort_keys=True))


def starting_gait(foot: Foot, speed: float, **fields: Any) -> np.ndarray:
    """The automatic starting gait's parameters x at ``speed`` (m/s). ``fields``: the walker fields
    of a job spec (docs/walker-jobs.md), e.g. ``points=200``, ``bezier_degree=6``."""
    return _model.starting_gait(_scene(foot, speed, fields))


def evaluate_gait(foot: Foot, x: Any, speed: float, points: int = 200, **fields: Any) -> Gait:
    """The periodic gait of the hybrid zero dynamics at gait parameters ``x`` (rad), seed 001
    section 5.3, on ``points`` grid points P (eq. 5.93) with target speed ``speed`` (m/s, for the
    speed equality 5.103). ``fields``: further walker fields (``bezier_degree``, ``objective``,
    ``quadrature``); bad values raise :class:`cyclopt.SpecError`."""
    x = np.ascontiguousarray(x, dtype=float)
    scalars, trajectories = _model.evaluate_gait(_scene(foot, speed, {"points": points, **fields}), x)
    return Gait(scalars, trajectories, x)


def optimise_gait(foot: Foot, speed: float, points: int = 200, start: Any = None, **fields: Any) -> GaitOptimum:
    """An energy-optimal gait at ``speed`` (m/s), seed 001 section 5.4, as the job kind
    ``optimise`` solves it: from ``start`` (gait parameters, rad) or the automatic starting gait,
    with the spec's ``solver`` (default: the seed's SQP, Table 6.2), ``objective``
    (``"f_mech"`` or ``"f_usq"``), ``bezier_degree``, ...; a solve that did not converge is returned
    with ``converged`` False."""
    if start is not None:
        fields = {**fields, "start": [float(v) for v in np.asarray(start, dtype=float)]}
    values_json, scalars, trajectories = _model.optimise_gait(_scene(foot, speed, {"points": points, **fields}))
    values = json.loads(values_json)
    return GaitOptimum(scalars, trajectories, np.asarray(values.get("x", []), dtype=float), values)
