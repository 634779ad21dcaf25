"""Scene files: one format for every study camdyn runs, in TOML (SI units).

Every scene says which study it is with ``kind`` and has the same top-level shape: ``title``,
``reference``, ``note``, ``law`` (and ``theta``), then the tables its kind uses:

``kind = "dynacam"``
    a DYNACAM mechanism (thesis ch. 6-8): ``[options]`` names the elements it has (the option
    set of the DYNACAM declaration, listed in the generated variants' manifests),
    ``[parameters]`` gives every parameter of the variant those options select (SI, reduced
    to the output member as in thesis sec. 2.4), ``[run]`` how long to run in the
    dimensionless time T = t/t_m of the rise (the rise starting at T = 0), ``[modes]`` the
    initial modes of force elements.  ``beta_0`` is not a scene parameter: the run places the
    rise start itself from ``run.T_start``.  An optional ``[turn]`` makes the cam a full
    turn instead of one rise and dwell: ``upper_dwell`` and ``return`` in deg (the rise is
    ``beta_m``, the lower dwell the rest of 360 deg), ``return_law`` and ``return_theta``
    (default: the rise's law mirrored), as :func:`camdyn.runtime.core.laws.compose` takes them.
``kind = "camshaft1-study"``
    the CAMSHAFT-1 study of thesis ch. 4 (`camdyn run`'s default): ``[study.response]`` (fig.
    4.10) and ``[study.graphs]`` (fig. 4.11), ``[run]`` method and rtol
    (:mod:`camdyn.runtime.targets.camshaft1_study`).  An optional ``[follower]`` gives the
    machine behind the study in place of the response's tau and Fa: ``kind``
    "oscillating-roller" (``swing`` deg, ``arm_length``, ``arm_inertia`` or ``mass`` at the
    roller, ``arm_stiffness`` or ``stiffness`` at the roller) or "translating-roller"
    (``stroke``, ``mass``, ``stiffness``), with ``speed`` (r.p.m.), ``cam_angle`` (deg),
    ``pitch_radius`` R_1/2 and ``c_tan``.  Its design point, a rocker reduced to its arc by
    (2.55)-(2.57), tau (4.12) and Fa (4.14), is formed as `camdyn design` forms it
    (:mod:`camdyn.runtime.cam.reduction`); the response is run there and at Fa = 0, the
    graphs add its Fa and mark it.  ``[study.response]`` is then left out: tau or Fa there
    as well is refused.
``kind = "beam-follower"``
    the paper's Rayleigh-beam follower: ``[parameters]`` the fields of
    :class:`camdyn.runtime.targets.beam_case.Case`, ``[run]`` revolutions, rtol, formulation.

Every kind's ``[run]`` also takes the absolute tolerances of its adaptive method (one
reader, :func:`tolerances`): ``atol``, in units of each state's tolerance scale (default 1e-3
rtol; runtime/core/simulator.py tolerance_scales), and a table ``[run.state_atol]`` of
``state = absolute tolerance`` in the state's own units.

Everything is checked before anything runs, against the model's manifest where the model
declares it: an unknown key, a missing parameter, a value of the wrong type or out of the
declared range is refused with a message that names it.  `camdyn run SCENE` runs any kind,
`camdyn scenes` lists the built-in ones.
"""
from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, fields
from importlib import resources
from pathlib import Path

from ..cam.reduction import LARGEST
from ..core.errors import CamdynInputError, on_disk
from ..core.methods import DEFAULT_RTOL

_TOP = {"kind", "title", "reference", "note", "law", "theta", "options", "parameters", "run", "modes",
        "turn"}
_TURN = {"upper_dwell", "return", "return_law", "return_theta"}
# T_end >= 1: a run covers the whole rise, whose largest deceleration every summary reports
_RUN = {"T_start": (-5.0, 0.0), "T_end": (1.0, 50.0), "rtol": (1e-13, 1e-2), "method": None}
TOLERANCE_KEYS = ("atol", "state_atol")
"""The [run] keys every kind of scene takes (:func:`tolerances`)."""


@dataclass(frozen=True)
class DynacamScene:
    """A checked DYNACAM scene (kind "dynacam")."""

    path: str
    title: str
    reference: str
    law: str
    theta: float | None
    options: object                 # variants.Options
    parameters: dict = field(default_factory=dict)
    modes: dict = field(default_factory=dict)
    T_start: float = -0.1
    T_end: float = 1.5
    rtol: float = DEFAULT_RTOL
    method: str = "dp54"
    turn: dict | None = None
    atol: float | None = None
    state_atol: tuple = ()
    """The ``[turn]`` table, checked: upper_dwell, return (deg), return_law, return_theta."""

    @property
    def variant(self) -> str:
        """Name of the generated module these options select."""
        return self.options.name

    def cam_law(self):
        """The cam input of the runs: the law (a LawChoice), or the full turn (a Turn)."""
        from ..core.laws import choose, compose

        if self.turn is None:
            return choose(self.law, self.theta)
        return compose(self.law, self.turn.get("return_law"), turn_angles(self),
                       self.theta, self.turn.get("return_theta"))


def turn_angles(sc) -> tuple:
    """(rise, upper dwell, return, lower dwell) in deg: the rise is beta_m, the lower dwell
    what is left of 360 deg."""
    rise = math.degrees(sc.parameters["beta_m"])
    up, ret = float(sc.turn["upper_dwell"]), float(sc.turn["return"])
    return (rise, up, ret, max(0.0, 360.0 - rise - up - ret))


def _turn(table, params: dict) -> dict | None:
    from ..core.laws import choose

    if table is None:
        return None
    if not isinstance(table, dict):
        raise CamdynInputError("[turn] must be a table (upper_dwell, return in deg; return_law)")
    unknown = sorted(set(table) - _TURN)
    if unknown:
        raise CamdynInputError(f"turn.{unknown[0]} is not a turn setting; settings are "
                               f"{', '.join(sorted(_TURN))}")
    for key in ("upper_dwell", "return"):
        if key not in table:
            raise CamdynInputError(f"turn.{key} is missing (deg)")
    up = _number("turn.upper_dwell", table["upper_dwell"], 0.0, 360.0)
    ret = _number("turn.return", table["return"], 0.0, 360.0)
    if ret <= 0:
        raise CamdynInputError(f"turn.return={ret:g} is out of range: 0 < return < 360 deg")
    rise = math.degrees(params["beta_m"])
    low = 360.0 - rise - up - ret
    if low < -1e-9:
        raise CamdynInputError(f"turn: rise (beta_m = {rise:g} deg) + upper_dwell ({up:g}) + "
                               f"return ({ret:g}) = {rise + up + ret:g} deg exceeds 360 deg")
    out = {"upper_dwell": up, "return": ret}
    if "return_law" in table:
        if not isinstance(table["return_law"], str):
            raise CamdynInputError(f"turn.return_law must be a cam-law name, got "
                                   f"{table['return_law']!r}")
        out["return_law"] = table["return_law"]
    if "return_theta" in table:
        if "return_law" not in out:
            raise CamdynInputError("turn.return_theta goes with turn.return_law")
        out["return_theta"] = _number("turn.return_theta", table["return_theta"])
    if "return_law" in out:
        choose(out["return_law"], out.get("return_theta"))    # raises naming the law's range
    return out


def builtin(name: str) -> Path:
    """Path of a scene shipped with camdyn (``indexing``, ``spring_loaded``)."""
    files = resources.files("camdyn.runtime") / "scenes"
    path = Path(str(files / f"{name}.toml"))
    if not path.is_file():
        known = sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))
        raise CamdynInputError(f"no built-in scene {name!r}; built-in scenes: {', '.join(known)}")
    return path


# -- the CAMSHAFT-1 study (kind camshaft1-study), run by camdyn.runtime.targets.camshaft1_study --------------

DYNACAM = "dynacam"
STUDY = "camshaft1-study"
BEAM = "beam-follower"
"""The kinds of scene file, each the ``scene_kind`` of the target class that runs it
(runtime/targets/resolve.py)."""
STUDY_SCHEMA = {
    "kind": str, "title": str, "law": str,
    "study": {"response": {"tau": float, "Fa": list},
              "graphs": {"tau_min": float, "tau_max": float, "n_tau": int, "Fa": list}},
    "run": {"method": str, "rtol": float},
}
_STUDY_OPTIONAL = {"reference": str, "note": str}


def check_study(data: dict, where: str) -> dict:
    """A camshaft1-study scene: every key of the schema, the right types, tau and Fa inside
    the ranges the CAMSHAFT-1 manifest declares, a known method and law.  With a ``[follower]``
    the returned table has the follower's design point as [study.response] (tau, and Fa with
    Fa = 0 beside it), its Fa among the graphs' and the point itself under ``design``
    (:func:`study_follower`)."""
    from ..core.laws import choose
    from ..core.methods import METHODS
    from ..core.compiled import load

    design = None
    if "follower" in data:
        _one_design_point(data, where)
        design = study_follower(data["follower"], where)
        data = _with_design_point(data, design)
    run = data.get("run")
    if isinstance(run, dict):          # the tolerances are read apart, by the one reader
        tolerances(run, where)
        _check({**data, "run": {k: v for k, v in run.items() if k not in TOLERANCE_KEYS}},
               STUDY_SCHEMA, where)
    else:
        _check(data, STUDY_SCHEMA, where)
    choose(data["law"])
    if data["run"]["method"] not in METHODS:
        raise CamdynInputError(f"{where}: run.method={data['run']['method']!r}: choose one of "
                               f"{', '.join(METHODS)}")
    model = load("camshaft1")
    study = data["study"]
    for key, values in (("study.response", [(study["response"]["tau"], F)
                                            for F in study["response"]["Fa"]]),
                        ("study.graphs", [(t, F) for t in (study["graphs"]["tau_min"],
                                                          study["graphs"]["tau_max"])
                                          for F in study["graphs"]["Fa"]])):
        for tau, Fa in values:
            try:
                model.parameter_vector({"tau": tau, "Fa": Fa})
            except CamdynInputError as exc:
                raise CamdynInputError(f"{where}: {key}: {exc}") from None
    graphs = study["graphs"]
    if not graphs["tau_max"] > graphs["tau_min"]:
        raise CamdynInputError(f"{where}: study.graphs.tau_min must be below study.graphs.tau_max")
    if design is None:
        return data
    # the design point's own curve, so that its mark on fig. 4.11 lies on a graph
    Fa = graphs["Fa"] if design["Fa"] in graphs["Fa"] else [*graphs["Fa"], design["Fa"]]
    return {**data, "study": {**study, "graphs": {**graphs, "Fa": Fa}}, "design": design}


# -- the machine behind a study ([follower]): its design point (tau, Fa) -------------------

ROCKER, TRANSLATING = "oscillating-roller", "translating-roller"
FOLLOWER_KEYS = {
    # key: (what it is, unit, upper bound; the lower is 0, open): LARGEST bounds them as
    # `camdyn design` bounds its inputs
    "swing": ("the rocker's swing Phi", "deg", 180.0),
    "arm_length": ("the arm l, pivot to roller centre", "m", LARGEST),
    "arm_inertia": ("the arm's inertia J about the pivot", "kg m^2", LARGEST),
    "arm_stiffness": ("the arm's torsional stiffness k_t at the pivot", "N m/rad", LARGEST),
    "stroke": ("h_m', the stroke of the output", "m", LARGEST),
    "mass": ("m, the mass at the output (4.39)", "kg", LARGEST),
    "stiffness": ("c_c, the stiffness at the output (4.3)", "N/m", LARGEST),
    "speed": ("the camshaft's speed", "r.p.m.", LARGEST),
    "cam_angle": ("beta_m, the cam angle of the rise", "deg", 360.0),
    "pitch_radius": ("R_1/2, the pitch radius at half the stroke (4.1)", "m", LARGEST),
    "c_tan": ("the camshaft's tangential stiffness at R_1/2 (4.4)", "N/m", LARGEST),
}
"""The keys of [follower] besides ``kind``."""
_CAMSHAFT = (("speed",), ("cam_angle",), ("pitch_radius",), ("c_tan",))
FOLLOWER_KINDS = {
    # a rocker gives its arm at the pivot, or a quantity at the roller already
    ROCKER: (("swing",), ("arm_length",), ("arm_inertia", "mass"), ("arm_stiffness", "stiffness"),
             *_CAMSHAFT),
    TRANSLATING: (("stroke",), ("mass",), ("stiffness",), *_CAMSHAFT),
}
"""What each kind of follower needs: one key of each group."""


def _follower_numbers(table, where: str) -> tuple[str, dict]:
    """(kind, the given numbers): every key known and of the follower's kind, a number in its
    range, one of each group of FOLLOWER_KINDS."""
    if not isinstance(table, dict):
        raise CamdynInputError(f"{where}: [follower] must be a table")
    kind = table.get("kind")
    if kind not in FOLLOWER_KINDS:
        said = " is missing" if kind is None else f"={kind!r}"
        raise CamdynInputError(f'{where}: follower.kind{said}: choose "{ROCKER}" or '
                               f'"{TRANSLATING}"')
    takes = [k for group in FOLLOWER_KINDS[kind] for k in group]
    for key in table:
        if key in FOLLOWER_KEYS and key not in takes:
            why = ("a rocker's stroke is its arc, arm_length x swing (2.55)" if key == "stroke"
                   else "a rocker's key")
            raise CamdynInputError(f'{where}: follower.{key} is refused with kind = "{kind}" '
                                   f"({why}); it takes {', '.join(takes)}")
        if key != "kind" and key not in FOLLOWER_KEYS:
            raise CamdynInputError(f"{where}: follower.{key} is not a follower key; keys are "
                                   f"kind, {', '.join(FOLLOWER_KEYS)}")
    values = {}
    for key in takes:
        if key in table:
            what, unit, upper = FOLLOWER_KEYS[key]
            v = _number(f"{where}: follower.{key}", table[key])
            if not 0 < v < upper:
                raise CamdynInputError(f"{where}: follower.{key}={v:g} is out of range: "
                                       f"0 < {key} < {upper:g} ({unit}, {what})")
            values[key] = v
    for group in FOLLOWER_KINDS[kind]:
        given = [k for k in group if k in values]
        if len(given) > 1:
            raise CamdynInputError(f"{where}: follower.{given[0]} and follower.{given[1]}: the "
                                   "arm's about the pivot or the one at the roller, not both")
        if not given:
            what, unit, _ = FOLLOWER_KEYS[group[0]]
            alt = "".join(f"; or {k} ({FOLLOWER_KEYS[k][1]} at the roller)" for k in group[1:])
            raise CamdynInputError(f"{where}: follower.{group[0]} is missing ({unit}, {what}"
                                   f"{alt})")
    return kind, values


def study_follower(table, where: str = "<scene>") -> dict:
    """The design point of a [follower] table (README "Scenes"): its inputs checked, a rocker
    reduced to its roller centre's arc (2.55)-(2.57), tau (4.12) and Fa (4.14) formed as
    `camdyn design` forms them (runtime/cam/reduction.py) and inside the CAMSHAFT-1
    manifest's ranges.  A record: ``tau``, ``Fa``, the ``follower`` as given and the
    ``figures`` at the output, each {value, unit, formula}."""
    from ..cam import reduction as red

    kind, v = _follower_numbers(table, where)
    try:
        at = _at_output(kind, v)
        point = red.design_point(stroke=at["stroke"][0], mass=at["mass"][0],
                                 stiffness=at["stiffness"][0], speed=v["speed"],
                                 cam_angle=math.radians(v["cam_angle"]),
                                 pitch_radius=v["pitch_radius"], c_tan=v["c_tan"])
    except (ZeroDivisionError, OverflowError):   # a product or square beyond a double
        raise CamdynInputError(f"{where}: [follower]: {_inputs(v, v)} give no finite tau and "
                               "Fa ((4.12), (4.14))") from None
    _in_manifest(point, v, where)
    formulas = {**{k: f for k, (_, f) in at.items()}, **red.FORMULAS}
    return {"tau": point.tau, "Fa": point.Fa, "follower": {"kind": kind, **v},
            "figures": {k: {"value": getattr(point, k), "unit": unit, "formula": formulas[k]}
                        for k, unit in red.UNITS.items()}}


def _at_output(kind: str, v: dict) -> dict:
    """The follower's stroke, mass and stiffness at the output, each (value, formula): a
    rocker's reduced to its roller centre's arc (2.55)-(2.57) unless given there."""
    from ..cam import reduction as red

    if kind != ROCKER:
        return {k: (v[k], "given") for k in ("stroke", "mass", "stiffness")}
    l = v["arm_length"]
    at = {"stroke": (red.arc_stroke(l, v["swing"]), red.ROCKER_FORMULAS["stroke"])}
    for name, pivot, reduce in (("mass", "arm_inertia", red.arc_mass),
                                ("stiffness", "arm_stiffness", red.arc_stiffness)):
        at[name] = ((reduce(v[pivot], l), red.ROCKER_FORMULAS[name]) if pivot in v
                    else (v[name], "given at the roller"))
    return at


_TAU_FROM = ("arm_inertia", "mass", "arm_stiffness", "stiffness", "arm_length", "speed",
             "cam_angle")
_FA_FROM = ("arm_stiffness", "stiffness", "arm_length", "swing", "stroke", "pitch_radius",
            "cam_angle", "c_tan")
"""The follower's inputs that tau = T_e/t_m and Fa = (c_c/c_tan) tan^2 alpha_me come from."""


def _inputs(values: dict, keys) -> str:
    return ", ".join(f"{k}={values[k]:g}" for k in keys if k in values)


def _in_manifest(point, values: dict, where: str) -> None:
    """tau and Fa of the design point inside CAMSHAFT-1's declared ranges, else refused naming
    the follower's inputs they come from."""
    from ..core.compiled import load

    declared = {p["name"]: p for p in load("camshaft1").manifest["parameters"]}
    for name, value, formula, keys in (("tau", point.tau, "T_e/t_m (4.12)", _TAU_FROM),
                                       ("Fa", point.Fa, "(c_c/c_tan) tan^2 alpha_me (4.14)",
                                        _FA_FROM)):
        p = declared[name]
        if not parameter_spec(p).admits(value):
            raise CamdynInputError(f"{where}: [follower]: {_inputs(values, keys)} give {name} = "
                                   f"{formula} = {value:.4g}, out of CAMSHAFT-1's range "
                                   f"{p['range']}")


def _response(data: dict):
    """The scene's [study.response] table as given ({} if left out), None if not a table."""
    study = data.get("study")
    response = study.get("response", {}) if isinstance(study, dict) else None
    return response if isinstance(response, dict) else None


def _one_design_point(data: dict, where: str) -> None:
    """A [follower] gives the design point: tau or Fa in [study.response] as well is refused."""
    for key in ("tau", "Fa"):
        if key in (_response(data) or {}):
            raise CamdynInputError(f"{where}: study.response.{key} and [follower] both given: the "
                                   "follower gives the design point's tau (4.12) and Fa (4.14); "
                                   "give one or the other")


def _with_design_point(data: dict, design: dict) -> dict:
    """The scene with the follower's design point as its [study.response]: tau, and its Fa
    with Fa = 0 (the rigid camshaft) beside it, to compare."""
    out = {k: v for k, v in data.items() if k != "follower"}
    response = _response(data)
    if response is None:
        return out              # the schema names what is wrong
    Fa = [0.0, design["Fa"]] if design["Fa"] > 0 else [0.0]
    out["study"] = {**data["study"], "response": {**response, "tau": design["tau"], "Fa": Fa}}
    return out


def _finite(v) -> bool:
    try:
        return math.isfinite(v)
    except OverflowError:   # a TOML integer beyond any double
        return False


def _check(d: dict, schema: dict, where: str, prefix: str = ""):
    optional = _STUDY_OPTIONAL if not prefix else {}
    for key, kind in {**schema, **optional}.items():
        name = prefix + key
        if key not in d:
            if key in optional:
                continue
            raise CamdynInputError(f"{where}: {name} is missing")
        v = d[key]
        if isinstance(kind, dict):
            if not isinstance(v, dict):
                raise CamdynInputError(f"{where}: [{name}] must be a table")
            _check(v, kind, where, name + ".")
        elif kind is float:
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not _finite(v):
                raise CamdynInputError(f"{where}: {name} must be a finite number, got {v!r}")
        elif kind is int:
            if isinstance(v, bool) or not isinstance(v, int) or v < 1:
                raise CamdynInputError(f"{where}: {name} must be a positive integer, got {v!r}")
        elif kind is list:
            if not isinstance(v, list) or not v or not all(
                    isinstance(x, (int, float)) and not isinstance(x, bool) and _finite(x) for x in v):
                raise CamdynInputError(f"{where}: {name} must be a non-empty list of finite numbers")
        elif not isinstance(v, kind):
            raise CamdynInputError(f"{where}: {name} must be a {kind.__name__}, got {v!r}")
    extra = sorted(set(d) - set(schema) - set(optional))
    if extra:
        raise CamdynInputError(f"{where}: unknown key {prefix}{extra[0]}")


def tolerances(run: dict, where: str = "") -> dict:
    """``atol`` and ``state_atol`` of a scene's [run] table (any kind), checked: atol > 0 and
    finite, in units of each state's tolerance scale; [run.state_atol] a table of state name =
    absolute tolerance > 0 in the state's units, as (name, value) pairs.  The names are checked
    against the model when its run is made (the error lists its states)."""
    at = f"{where}: " if where else ""
    out = {}
    if "atol" in run:
        v = _number(f"{at}run.atol", run["atol"])
        if not v > 0:
            raise CamdynInputError(f"{at}run.atol={v:g} is out of range: atol > 0 (in units of "
                                   "each state's tolerance scale)")
        out["atol"] = v
    if "state_atol" in run:
        table = run["state_atol"]
        if not isinstance(table, dict) or not table:
            raise CamdynInputError(f"{at}[run.state_atol] must be a table of state = absolute "
                                   f"tolerance, got {table!r}")
        pairs = []
        for name, value in table.items():
            v = _number(f"{at}run.state_atol.{name}", value)
            if not v > 0:
                raise CamdynInputError(f"{at}run.state_atol.{name}={v:g} is out of range: > 0 "
                                       "(an absolute tolerance in the state's units)")
            pairs.append((name, v))
        out["state_atol"] = tuple(pairs)
    return out


# -- DYNACAM (kind dynacam) -----------------------------------------------------------------

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
    from ..core.variants import CHOICES, Options

    if not isinstance(table, dict):
        raise CamdynInputError("[options] must be a table")
    kinds = {f.name: f.type for f in fields(Options)}
    for key, value in table.items():
        if key not in kinds:
            raise CamdynInputError(f"options.{key} is not an option; options are {', '.join(kinds)}")
        if key in CHOICES:
            if not isinstance(value, str) or value not in CHOICES[key]:
                raise CamdynInputError(
                    f"options.{key}={value!r}: choose one of {', '.join(CHOICES[key])}")
        elif not isinstance(value, bool):
            raise CamdynInputError(f"options.{key} must be true or false, got {value!r}")
    return Options(**table)


@dataclass(frozen=True)
class ParameterSpec:
    """A parameter as the variant's manifest declares it (name, unit, doc, range)."""

    name: str
    unit: str
    doc: str
    low: float
    high: float
    open_low: bool
    open_high: bool

    def admits(self, value: float) -> bool:
        above = self.low < value if self.open_low else self.low <= value
        below = value < self.high if self.open_high else value <= self.high
        return math.isfinite(value) and above and below


def declared_parameters(options, progress=None) -> dict:
    """The variant's parameters (name -> ParameterSpec) from its compiled manifest: a
    pre-generated variant's at once, any other's once it is built on demand."""
    from ..core.variants import variant_manifest

    return {p["name"]: parameter_spec(p) for p in variant_manifest(options, progress)["parameters"]}


def parameter_spec(p: dict) -> ParameterSpec:
    """A parameter of a compiled manifest as a ParameterSpec (no bound: infinite)."""
    return ParameterSpec(p["name"], p["unit"], p["doc"],
                         -math.inf if p["low"] is None else p["low"],
                         math.inf if p["high"] is None else p["high"],
                         p["open_low"], p["open_high"])


def check_parameters(options, table) -> dict:
    """Every parameter of the variant present, a number, inside its declared range."""
    if not isinstance(table, dict):
        raise CamdynInputError("[parameters] must be a table")
    declared = declared_parameters(options)
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


MAX_SCENE_BYTES = 1 << 20
"""The largest scene file read: the built-in ones are about 2 KB; a device or a huge file is
refused before it is read."""


def read(path) -> tuple[dict, str]:
    """The TOML table of a scene file (or a built-in scene name), and the path it came from.
    Only a regular file is opened: a named pipe would block, a device (/dev/zero) never
    end."""
    path = Path(path)
    if not path.suffix and not path.exists():
        path = builtin(str(path))
    what = on_disk(path)
    if what not in (None, "file"):    # never opened: a named pipe or /dev/zero would not end
        raise CamdynInputError(f"scene file {path} is a {what}, not a scene file (.toml)")
    if what == "file" and path.stat().st_size > MAX_SCENE_BYTES:
        raise CamdynInputError(f"scene file {path}: {path.stat().st_size} bytes is too large "
                               f"for a scene (at most {MAX_SCENE_BYTES} bytes)")
    try:
        return tomllib.loads(path.read_text()), str(path)
    except FileNotFoundError:
        raise CamdynInputError(f"scene file {path} not found") from None
    except OSError as exc:      # a folder, no permission
        raise CamdynInputError(f"scene file {path}: {exc.strerror}") from None
    except ValueError as exc:   # not TOML, not UTF-8, an integer of more than 4300 digits
        raise CamdynInputError(f"scene file {path}: {exc}") from None


def kind_of(data: dict, where: str, kinds: dict | None = None) -> str:
    """The scene's ``kind``, one of ``kinds`` (kind -> what a run of it gives; default: any
    name); a file of the format before kinds gets told what changed."""
    kind = data.get("kind")
    if kind is None:
        if "options" in data:
            hint = 'a DYNACAM scene: add the line kind = "dynacam" at the top'
        elif {"response", "graphs", "integration"} & set(data):
            hint = ('a `camdyn run` study: add kind = "camshaft1-study", move [response] and '
                    '[graphs] under [study] ([study.response], [study.graphs]) and rename '
                    '[integration] to [run]')
        else:
            hint = f"add kind = one of {', '.join(repr(k) for k in kinds or ())}"
        raise CamdynInputError(f"{where}: the scene has no kind; every scene file now says which "
                               f"study it is with kind = ... ({hint})")
    if not isinstance(kind, str) or (kinds is not None and kind not in kinds):
        raise CamdynInputError(f"{where}: kind={kind!r}: choose one of {', '.join(kinds or ())}")
    return kind


def expect_kind(data: dict, where: str, kind: str) -> None:
    got = kind_of(data, where)
    if got != kind:
        raise CamdynInputError(f"{where} is a {got} scene, not a {kind} one; `camdyn run` runs "
                               f"any kind")


def beside(law: str, scene: str) -> str:
    """A law file named in a scene, relative to the scene file's folder."""
    from ..core.shaped import is_law_file

    if not is_law_file(law) or Path(law).is_absolute() or scene.startswith("<"):
        return law
    return str(Path(scene).parent / law)


def load(path) -> DynacamScene:
    """Read and check a DYNACAM scene file (or a built-in scene name)."""
    data, where = read(path)
    expect_kind(data, where, DYNACAM)
    return from_dict(data, where)


def builtins() -> list[tuple[str, str, str]]:
    """(name, kind, title) of every scene shipped with camdyn, sorted by name."""
    files = resources.files("camdyn.runtime") / "scenes"
    out = []
    for p in sorted(files.iterdir(), key=lambda p: p.name):
        if p.name.endswith(".toml"):
            data = tomllib.loads(p.read_text())
            out.append((p.name[:-5], data.get("kind", "?"), data.get("title", "")))
    return out


@dataclass(frozen=True)
class BeamScene:
    """A checked beam-follower scene: the case to run."""

    path: str
    title: str
    reference: str
    case: object    # beam_case.Case


_BEAM_RUN = ("revolutions", "rtol", "formulation", "method", "mode_atol") + TOLERANCE_KEYS


def beam_from_dict(data: dict, path: str = "<scene>") -> BeamScene:
    """A beam-follower scene: [parameters] and [run] are fields of beam_case.Case, checked as
    the command line checks them."""
    from dataclasses import fields

    from .beam_case import Case, check

    allowed = {"kind", "title", "reference", "note", "law", "parameters", "run"}
    unknown = sorted(set(data) - allowed)
    if unknown:
        raise CamdynInputError(f"{unknown[0]} is not a key of a beam-follower scene; keys are "
                               f"{', '.join(sorted(allowed))}")
    names = {f.name for f in fields(Case)} - set(_BEAM_RUN) - {"law"}
    values = {}
    for table, keys in (("parameters", names), ("run", set(_BEAM_RUN))):
        t = data.get(table, {})
        if not isinstance(t, dict):
            raise CamdynInputError(f"[{table}] must be a table")
        for key, value in t.items():
            if key not in keys:
                raise CamdynInputError(f"{table}.{key} is not a beam-follower {table} key; "
                                       f"choose from {', '.join(sorted(keys))}")
            values[key] = value
    if "law" in data:
        values["law"] = data["law"]
    if isinstance(data.get("run"), dict):
        values.update(tolerances(data["run"]))
    for key, value in values.items():
        if key in TOLERANCE_KEYS:
            continue
        if key in ("rayleigh",):
            if not isinstance(value, bool):
                raise CamdynInputError(f"{key} must be true or false, got {value!r}")
        elif key in ("formulation", "law", "method"):
            if not isinstance(value, str):
                raise CamdynInputError(f"{key} must be a name, got {value!r}")
        elif key == "modes":
            if isinstance(value, bool) or not isinstance(value, int):
                raise CamdynInputError(f"parameters.modes must be an integer, got {value!r}")
        else:
            values[key] = _number(key, value)
    case = check(Case(**values))
    return BeamScene(path=path, title=str(data.get("title", Path(path).stem)),
                     reference=str(data.get("reference", "")), case=case)


def from_dict(data: dict, path: str = "<scene>") -> DynacamScene:
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise CamdynInputError(f"{unknown[0]} is not a scene key; keys are {', '.join(sorted(_TOP))}")
    for key in ("options", "parameters"):
        if key not in data:
            raise CamdynInputError(f"the scene has no [{key}] table")
    from ..core.laws import choose

    law = data.get("law", "cycloidal")
    theta = data.get("theta")
    if theta is not None:
        theta = _number("theta", theta)
    if not isinstance(law, str):
        raise CamdynInputError(f"law must be a cam-law name or a law file, got {law!r}")
    law = beside(law, path)
    choose(law, theta)   # raises with the list of laws
    options = _options(data["options"])
    params = check_parameters(options, data["parameters"])
    run = data.get("run", {})
    if not isinstance(run, dict):
        raise CamdynInputError("[run] must be a table")
    settings = tolerances(run)
    for key, value in run.items():
        if key in TOLERANCE_KEYS:
            continue
        if key not in _RUN:
            raise CamdynInputError(f"run.{key} is not a run setting; settings are "
                                   f"{', '.join((*_RUN, *TOLERANCE_KEYS))}")
        if key == "method":
            from ..core.methods import ADAPTIVE

            if value not in ADAPTIVE:
                raise CamdynInputError(f"run.method={value!r}: scenes need an adaptive method, "
                                       f"{' or '.join(ADAPTIVE)} (contact changes are located on "
                                       "its dense output)")
            settings[key] = value
        else:
            settings[key] = _number(f"run.{key}", value, *_RUN[key])
    if settings.get("T_end", 1.5) <= settings.get("T_start", -0.1):
        raise CamdynInputError("run.T_end must be greater than run.T_start")
    modes = data.get("modes", {})
    if not isinstance(modes, dict) or not all(isinstance(v, str) for v in modes.values()):
        raise CamdynInputError("[modes] must map mode names to value names")
    turn = _turn(data.get("turn"), params)
    return DynacamScene(path=path, title=str(data.get("title", Path(path).stem)),
                 reference=str(data.get("reference", "")), law=law, theta=theta,
                 options=options, parameters=params, modes=dict(modes), turn=turn, **settings)


def replace(sc: DynacamScene, options: dict | None = None, parameters: dict | None = None,
            drop: tuple = ()) -> DynacamScene:
    """The scene with some options or parameters changed (``drop``: parameters the new
    options no longer have), checked again as a scene file would be."""
    from dataclasses import asdict

    opts = {**asdict(sc.options), **(options or {})}
    params = {k: v for k, v in {**sc.parameters, **(parameters or {})}.items() if k not in drop}
    data = {"title": sc.title, "reference": sc.reference, "law": sc.law, "options": opts,
            "parameters": params, "modes": dict(sc.modes),
            "run": {"T_start": sc.T_start, "T_end": sc.T_end, "rtol": sc.rtol, "method": sc.method}}
    if sc.atol is not None:
        data["run"]["atol"] = sc.atol
    if sc.state_atol:
        data["run"]["state_atol"] = dict(sc.state_atol)
    if sc.theta is not None:
        data["theta"] = sc.theta
    if sc.turn is not None:
        data["turn"] = dict(sc.turn)
    return from_dict(data, sc.path)


def without_backlash(sc: DynacamScene) -> DynacamScene:
    """The scene with a rigid gear and a bilateral roller (figs 7.15 against 7.16)."""
    return replace(sc, {"gear": "rigid", "roller": "bilateral"}, drop=("s_g", "s_r", "V_T", "V_R"))
