"""DYNACAM scene files: a mechanism as options, parameters and a run, in TOML (SI units).

A scene names the elements its mechanism has (``[options]``, the fields of
:class:`camdyn.derive.models.dynacam.Options`), gives every parameter of the
variant those options select (``[parameters]``, SI, reduced to the output
member as in thesis sec. 2.4), and says how long to run (``[run]``, in the
dimensionless time T = t/t_m of the rise, the rise starting at T = 0).

Everything is checked before anything runs: an unknown key, a missing
parameter, a value of the wrong type or out of the declared range is refused
with a message that names it.  ``beta_0`` is not a scene parameter: the run
places the rise start itself from ``run.T_start``.
"""
from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, fields
from importlib import resources
from pathlib import Path

from .errors import CamdynInputError

_TOP = {"title", "reference", "note", "law", "theta", "options", "parameters", "run", "modes"}
# T_end >= 1: a run covers the whole rise, whose largest deceleration every summary reports
_RUN = {"T_start": (-5.0, 0.0), "T_end": (1.0, 50.0), "rtol": (1e-13, 1e-2), "method": None}


@dataclass(frozen=True)
class Scene:
    """A checked scene."""

    path: str
    title: str
    reference: str
    law: str
    theta: float | None
    options: object                 # dynacam.Options
    parameters: dict = field(default_factory=dict)
    modes: dict = field(default_factory=dict)
    T_start: float = -0.1
    T_end: float = 1.5
    rtol: float = 1e-8
    method: str = "dp54"

    @property
    def variant(self) -> str:
        """Name of the generated module these options select."""
        return self.options.name


def builtin(name: str) -> Path:
    """Path of a scene shipped with camdyn (``indexing``, ``spring_loaded``)."""
    files = resources.files("camdyn.runtime") / "scenes"
    path = Path(str(files / f"{name}.toml"))
    if not path.is_file():
        known = sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))
        raise CamdynInputError(f"no built-in scene {name!r}; built-in scenes: {', '.join(known)}")
    return path


def _float(where: str, value) -> float:
    try:
        return float(value)
    except OverflowError:   # an integer beyond any double (TOML integers have no size limit here)
        raise CamdynInputError(f"{where} must be finite, got an integer too large for a double") from None


def _number(where: str, value, low=None, high=None) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise CamdynInputError(f"{where} must be a number, got {value!r}")
    value = _float(where, value)
    if not math.isfinite(value):
        raise CamdynInputError(f"{where} must be finite, got {value!r}")
    if low is not None and not (low <= value <= high):
        raise CamdynInputError(f"{where}={value:g} is out of range [{low:g}, {high:g}]")
    return value


def _options(table) -> object:
    from camdyn.derive.models.dynacam import Options

    if not isinstance(table, dict):
        raise CamdynInputError("[options] must be a table")
    kinds = {f.name: f.type for f in fields(Options)}
    for key, value in table.items():
        if key not in kinds:
            raise CamdynInputError(f"options.{key} is not an option; options are {', '.join(kinds)}")
        if key in Options.CHOICES:
            if not isinstance(value, str) or value not in Options.CHOICES[key]:
                raise CamdynInputError(
                    f"options.{key}={value!r}: choose one of {', '.join(Options.CHOICES[key])}")
        elif not isinstance(value, bool):
            raise CamdynInputError(f"options.{key} must be true or false, got {value!r}")
    return Options(**table)


def _declared_parameters(options) -> dict:
    """The variant's parameters from the declaration (name -> Parameter), without compiling."""
    from camdyn.derive.models import dynacam

    return {p.name: p for p in dynacam.build(options).parameters}


def check_parameters(options, table) -> dict:
    """Every parameter of the variant present, a number, inside its declared range."""
    if not isinstance(table, dict):
        raise CamdynInputError("[parameters] must be a table")
    declared = _declared_parameters(options)
    if "beta_0" in table:
        raise CamdynInputError("parameters.beta_0 is set by the run (run.T_start); remove it")
    unknown = sorted(set(table) - set(declared))
    if unknown:
        raise CamdynInputError(
            f"parameters.{unknown[0]} is not a parameter of {options.name} (with these options); "
            f"its parameters are {', '.join(n for n in declared if n != 'beta_0')}")
    out = {}
    for name, spec in declared.items():
        if name == "beta_0":
            continue
        if name not in table:
            raise CamdynInputError(f"parameters.{name} is missing ({spec.doc}, {spec.unit})")
        value = table[name]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise CamdynInputError(f"parameters.{name} must be a number in {spec.unit}, got {value!r}")
        value = _float(f"parameters.{name}", value)
        if not spec.admits(value):
            lo = "(" if spec.open_low else "["
            hi = ")" if spec.open_high or spec.high == math.inf else "]"
            raise CamdynInputError(
                f"parameters.{name}={value:g} is out of range {lo}{spec.low:g}, {spec.high:g}{hi} "
                f"{spec.unit} ({spec.doc})")
        out[name] = value
    return out


def load(path) -> Scene:
    """Read and check a scene file (or a built-in scene name)."""
    path = Path(path)
    if not path.suffix and not path.exists():
        path = builtin(str(path))
    try:
        data = tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise CamdynInputError(f"scene file {path} not found") from None
    except OSError as exc:      # a folder, no permission
        raise CamdynInputError(f"scene file {path}: {exc.strerror}") from None
    except ValueError as exc:   # not TOML, not UTF-8, an integer of more than 4300 digits
        raise CamdynInputError(f"scene file {path}: {exc}") from None
    return from_dict(data, str(path))


def from_dict(data: dict, path: str = "<scene>") -> Scene:
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise CamdynInputError(f"{unknown[0]} is not a scene key; keys are {', '.join(sorted(_TOP))}")
    for key in ("options", "parameters"):
        if key not in data:
            raise CamdynInputError(f"the scene has no [{key}] table")
    from .laws import choose

    law = data.get("law", "cycloidal")
    theta = data.get("theta")
    if theta is not None:
        theta = _number("theta", theta)
    if not isinstance(law, str):
        raise CamdynInputError(f"law must be a cam-law name, got {law!r}")
    choose(law, theta)   # raises with the list of laws
    options = _options(data["options"])
    params = check_parameters(options, data["parameters"])
    run = data.get("run", {})
    if not isinstance(run, dict):
        raise CamdynInputError("[run] must be a table")
    settings = {}
    for key, value in run.items():
        if key not in _RUN:
            raise CamdynInputError(f"run.{key} is not a run setting; settings are {', '.join(_RUN)}")
        if key == "method":
            if value != "dp54":
                raise CamdynInputError(f"run.method={value!r}: scenes need the adaptive dp54 "
                                       "(contact changes are located on its dense output)")
            settings[key] = value
        else:
            settings[key] = _number(f"run.{key}", value, *_RUN[key])
    if settings.get("T_end", 1.5) <= settings.get("T_start", -0.1):
        raise CamdynInputError("run.T_end must be greater than run.T_start")
    modes = data.get("modes", {})
    if not isinstance(modes, dict) or not all(isinstance(v, str) for v in modes.values()):
        raise CamdynInputError("[modes] must map mode names to value names")
    return Scene(path=path, title=str(data.get("title", Path(path).stem)),
                 reference=str(data.get("reference", "")), law=law, theta=theta,
                 options=options, parameters=params, modes=dict(modes), **settings)


def replace(sc: Scene, options: dict | None = None, parameters: dict | None = None,
            drop: tuple = ()) -> Scene:
    """The scene with some options or parameters changed (``drop``: parameters the new
    options no longer have), checked again as a scene file would be."""
    from dataclasses import asdict

    opts = {**asdict(sc.options), **(options or {})}
    params = {k: v for k, v in {**sc.parameters, **(parameters or {})}.items() if k not in drop}
    data = {"title": sc.title, "reference": sc.reference, "law": sc.law, "options": opts,
            "parameters": params, "modes": dict(sc.modes),
            "run": {"T_start": sc.T_start, "T_end": sc.T_end, "rtol": sc.rtol, "method": sc.method}}
    if sc.theta is not None:
        data["theta"] = sc.theta
    return from_dict(data, sc.path)


def without_backlash(sc: Scene) -> Scene:
    """The scene with a rigid gear and a bilateral roller (figs 7.15 against 7.16)."""
    return replace(sc, {"gear": "rigid", "roller": "bilateral"}, drop=("s_g", "s_r", "V_T", "V_R"))
