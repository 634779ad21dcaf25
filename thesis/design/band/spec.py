"""A machine, described once: the follower and its geometry, the stroke (or a rocker's swing),
the four cam angles, the band of speeds, the follower train's mass (or a rocker's inertia) and
stiffness, the spring, the cam's base circle and materials, optionally the camshaft.

The same description comes from a scene file of kind "machine" (:func:`from_dict`) and from
`camdyn design`'s options (:func:`from_options`); every missing required value is named in one
message.  Units follow :mod:`.units`: a number is SI (an angle in degrees), a string carries
its own unit.  :data:`TEMPLATE` is the commented file `camdyn scenes --template machine`
writes.

A rocker is reduced to its roller centre's arc as sec. 2.4 reduces a linkage (the design's
(2.55)-(2.57), :mod:`camdyn.runtime.cam.reduction`): stroke l Phi, mass J/l^2, stiffness
k_t/l^2; its spring's rate and preload, given at the pivot as N m/rad and N m, are k/l^2 and
F_0/l at the roller.  What the models take is then :attr:`Machine.stroke`, :attr:`mass`,
:attr:`stiffness`, :attr:`spring_rate`, :attr:`spring_preload` at the output (the roller).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

from camdyn.runtime.cam import reduction as red
from camdyn.runtime.cam.names import KINDS, MATERIALS
from camdyn.runtime.core.errors import CamdynInputError

from . import units

KIND = "machine"
"""The scene kind of a machine file."""

TABLES = {
    "follower": {"type": None, "roller_radius": "length", "roller_width": "length",
                 "offset": "length", "pivot_distance": "length", "arm_length": "length",
                 "face_offset": "length", "crown_radius": "length"},
    "motion": {"stroke": "length", "swing": "angle", "angles": None, "laws": None},
    "speed": {"band": None},
    "train": {"mass": "mass", "inertia": "inertia", "stiffness": "stiffness",
              "torsional_stiffness": "torsional stiffness", "damping_ratio": "ratio"},
    "spring": {"rate": None, "preload": None, "margin": "ratio"},
    "cam": {"base_radius": "length", "width": "length", "materials": None,
            "allowable_stress": "stress", "max_pressure_angle": "angle"},
    "camshaft": {"torsional_stiffness": "torsional stiffness", "bending_stiffness": "stiffness",
                 "inertia": "inertia"},
    "drive": {"speed_fluctuation": "ratio"},
}
"""Every table of a machine file and its keys, each with the kind of quantity it holds (None:
read by its own rule)."""

TOP = ("kind", "title", *TABLES)

MARGIN = 0.3
"""The spring's margin over the inertia force unless given: its force at least 1.3 times
what pulls the follower off the cam (secs 4.5.5, 7.5)."""

MAX_PRESSURE_ANGLE = 30.0
"""The pressure-angle limit unless given, deg (`camdyn profile`'s)."""


@dataclass(frozen=True)
class Machine:
    """A machine in SI units (angles in degrees), as the designer gave it.

    follower         one of KINDS
    stroke, swing    a translating follower's stroke (m); an oscillating one's swing (deg)
    angles           rise, outer dwell, return, inner dwell (deg, summing to 360)
    speeds           the band (lo, hi) in rad/s; ``speed_unit`` the unit to print it in
    mass, stiffness  the follower train at the output, or a rocker's ``inertia`` (kg m^2)
                     and ``torsional_stiffness`` (N m/rad) about its pivot
    spring_rate, spring_preload
                     at the output (N/m, N), or a rocker's at its pivot (N m/rad, N m);
                     a preload of None is sized (with ``spring_margin``)
    camshaft_*       optional: its torsion (N m/rad), bending at the cam (N/m) and inertia
                     (kg m^2), which bring in Fa and Fv and the thesis's larger models
    """

    follower: str
    angles: tuple
    speeds: tuple
    base_radius: float
    stroke: float | None = None
    swing: float | None = None
    speed_unit: str = "rpm"
    laws: tuple = ("all",)
    title: str = "machine"
    roller_radius: float | None = None
    roller_width: float | None = None
    offset: float = 0.0
    pivot_distance: float | None = None
    arm_length: float | None = None
    face_offset: float = 0.0
    crown_radius: float | None = None
    mass: float | None = None
    inertia: float | None = None
    stiffness: float | None = None
    torsional_stiffness: float | None = None
    damping_ratio: float = 0.0
    spring_rate: float | None = None
    spring_preload: float | None = None
    spring_margin: float = MARGIN
    cam_width: float | None = None
    materials: tuple = ("steel", "steel")
    allowable_stress: float | None = None
    max_pressure_angle: float = MAX_PRESSURE_ANGLE
    camshaft_torsional_stiffness: float | None = None
    camshaft_bending_stiffness: float | None = None
    camshaft_inertia: float | None = None
    speed_fluctuation: float | None = None
    source: str = ""

    # -- the follower reduced to its output -------------------------------------------------

    @property
    def rocker(self) -> bool:
        return self.follower.startswith("oscillating")

    @property
    def roller(self) -> bool:
        return self.follower.endswith("roller")

    @property
    def lever(self) -> float:
        """The ratio from the rocker's pivot to its output (the roller centre's arc, or for a
        flat face its pivot distance, sec. 2.4), 1 for a translating follower."""
        if not self.rocker:
            return 1.0
        return self.arm_length if self.arm_length is not None else self.pivot_distance

    @property
    def output_stroke(self) -> float:
        """h_m', the stroke at the output (2.55): the stroke, or l Phi."""
        return self.stroke if not self.rocker else red.arc_stroke(self.lever, self.swing)

    @property
    def output_mass(self) -> float:
        """m at the output (2.56): the mass, or J/l^2."""
        return self.mass if self.inertia is None else red.arc_mass(self.inertia, self.lever)

    @property
    def output_stiffness(self) -> float:
        """c_c at the output (2.57): the stiffness, or k_t/l^2."""
        if self.torsional_stiffness is None:
            return self.stiffness
        return red.arc_stiffness(self.torsional_stiffness, self.lever)

    @property
    def output_spring_rate(self) -> float:
        """The spring's rate at the output: as given, or a rocker's k/l^2 (N/m)."""
        if self.spring_rate is None:
            return 0.0
        return self.spring_rate / self.lever**2 if self.rocker else self.spring_rate

    @property
    def output_spring_preload(self) -> float | None:
        """The spring's preload at the output: as given, or a rocker's F_0/l (N); None:
        to be sized."""
        if self.spring_preload is None:
            return None
        return self.spring_preload / self.lever if self.rocker else self.spring_preload

    @property
    def rise_angle(self) -> float:
        """beta_m, rad."""
        return math.radians(self.angles[0])

    @property
    def period(self) -> float:
        """T_e = 2 pi (m/c_c)^(1/2) (4.39), s."""
        return 2 * math.pi * math.sqrt(self.output_mass / self.output_stiffness)

    def tau(self, w: float) -> float:
        """tau = T_e/t_m (4.12) at the camshaft speed w (rad/s), t_m = beta_m/w (App. 7 (8))."""
        return self.period * w / self.rise_angle

    def speed_of(self, tau: float) -> float:
        """The camshaft speed (rad/s) at which the rise gives ``tau``."""
        return tau * self.rise_angle / self.period

    @property
    def taus(self) -> tuple[float, float]:
        """The band in tau, lowest speed first."""
        return self.tau(self.speeds[0]), self.tau(self.speeds[1])

    @property
    def has_camshaft(self) -> bool:
        return any(v is not None for v in (self.camshaft_torsional_stiffness,
                                           self.camshaft_bending_stiffness))


# -- reading ----------------------------------------------------------------------------------

def from_dict(data: dict, where: str = "") -> Machine:
    """A machine file's tables, checked: unknown keys refused by name, every missing required
    value named at once, every value by the units rule (:mod:`.units`)."""
    at = f"{where}: " if where else ""
    if not isinstance(data, dict):
        raise CamdynInputError(f"{at}a machine file is a TOML table")
    for key in data:
        if key not in TOP:
            raise CamdynInputError(f"{at}{key} is not a key of a machine file; its keys are "
                                   f"{', '.join(TOP)}")
    if data.get("kind", KIND) != KIND:
        raise CamdynInputError(f"{at}kind = {data.get('kind')!r}: a machine file has kind = "
                               f"\"{KIND}\"")
    tables = {}
    for name, keys in TABLES.items():
        t = data.get(name, {})
        if not isinstance(t, dict):
            raise CamdynInputError(f"{at}[{name}] must be a table")
        for key in t:
            if key not in keys:
                raise CamdynInputError(f"{at}{name}.{key} is not a key of [{name}]; its keys "
                                       f"are {', '.join(keys)}")
        tables[name] = t
    try:
        return _build(tables, str(data.get("title", "machine")), where)
    except CamdynInputError as exc:
        raise CamdynInputError(f"{at}{exc}") from None


def _q(tables, table: str, key: str, default=None):
    t = tables.get(table, {})
    if key not in t:
        return default
    return units.value(t[key], TABLES[table][key], f"{table}.{key}")


def _build(tables: dict, title: str, where: str) -> Machine:
    fol = tables["follower"]
    kind = fol.get("type", "translating-roller")
    if kind not in KINDS:
        raise CamdynInputError(f"follower.type={kind!r}: choose one of {', '.join(KINDS)}")
    mot = tables["motion"]
    angles = angles_of(mot.get("angles"), "motion.angles")
    band_raw = tables["speed"].get("band")
    speeds, unit = (None, "rpm") if band_raw is None else units.band(band_raw, "speed.band")
    spring = tables["spring"]
    rocker = kind.startswith("oscillating")
    rate = spring.get("rate")
    preload = spring.get("preload")
    force_kind, rate_kind = (("torque", "torsional stiffness") if rocker
                             else ("force", "stiffness"))
    if isinstance(preload, str) and preload.strip().lower() == "size":
        preload = None
    values = dict(
        follower=kind, angles=angles, speeds=speeds, speed_unit=unit, title=title,
        base_radius=_q(tables, "cam", "base_radius"),
        stroke=_q(tables, "motion", "stroke"), swing=_q(tables, "motion", "swing"),
        laws=laws_of(mot.get("laws", "all"), "motion.laws"),
        roller_radius=_q(tables, "follower", "roller_radius"),
        roller_width=_q(tables, "follower", "roller_width"),
        offset=_q(tables, "follower", "offset", 0.0),
        pivot_distance=_q(tables, "follower", "pivot_distance"),
        arm_length=_q(tables, "follower", "arm_length"),
        face_offset=_q(tables, "follower", "face_offset", 0.0),
        crown_radius=_q(tables, "follower", "crown_radius"),
        mass=_q(tables, "train", "mass"), inertia=_q(tables, "train", "inertia"),
        stiffness=_q(tables, "train", "stiffness"),
        torsional_stiffness=_q(tables, "train", "torsional_stiffness"),
        damping_ratio=_q(tables, "train", "damping_ratio", 0.0),
        spring_rate=None if rate is None else units.value(rate, rate_kind, "spring.rate"),
        spring_preload=None if preload is None else units.value(preload, force_kind,
                                                                "spring.preload"),
        spring_margin=_q(tables, "spring", "margin", MARGIN),
        cam_width=_q(tables, "cam", "width"),
        materials=materials_of(tables["cam"].get("materials", "steel,steel"), "cam.materials"),
        allowable_stress=_q(tables, "cam", "allowable_stress"),
        max_pressure_angle=_q(tables, "cam", "max_pressure_angle", MAX_PRESSURE_ANGLE),
        camshaft_torsional_stiffness=_q(tables, "camshaft", "torsional_stiffness"),
        camshaft_bending_stiffness=_q(tables, "camshaft", "bending_stiffness"),
        camshaft_inertia=_q(tables, "camshaft", "inertia"),
        speed_fluctuation=_q(tables, "drive", "speed_fluctuation"),
        source=where)
    return check(values, FILE_KEYS)


FILE_KEYS = {"follower": "follower.type", "stroke": "motion.stroke", "swing": "motion.swing",
             "angles": "motion.angles", "speeds": "speed.band", "base_radius": "cam.base_radius",
             "roller_radius": "follower.roller_radius", "roller_width": "follower.roller_width",
             "offset": "follower.offset", "pivot_distance": "follower.pivot_distance",
             "arm_length": "follower.arm_length", "face_offset": "follower.face_offset",
             "crown_radius": "follower.crown_radius", "mass": "train.mass",
             "inertia": "train.inertia", "stiffness": "train.stiffness",
             "torsional_stiffness": "train.torsional_stiffness",
             "damping_ratio": "train.damping_ratio", "spring_rate": "spring.rate",
             "spring_preload": "spring.preload", "spring_margin": "spring.margin",
             "cam_width": "cam.width", "allowable_stress": "cam.allowable_stress",
             "max_pressure_angle": "cam.max_pressure_angle",
             "camshaft_torsional_stiffness": "camshaft.torsional_stiffness",
             "camshaft_bending_stiffness": "camshaft.bending_stiffness",
             "camshaft_inertia": "camshaft.inertia",
             "speed_fluctuation": "drive.speed_fluctuation"}
"""Each field by the key a machine file gives it, for the messages."""

OPTION_KEYS = {"follower": "--follower", "stroke": "--stroke", "swing": "--swing",
               "angles": "--angles", "speeds": "--speed", "base_radius": "--base-radius",
               "roller_radius": "--roller-radius", "roller_width": "--roller-width",
               "offset": "--offset", "pivot_distance": "--pivot-distance",
               "arm_length": "--arm-length", "face_offset": "--face-offset",
               "crown_radius": "--crown-radius", "mass": "--mass",
               "inertia": "--arm-inertia", "stiffness": "--stiffness",
               "torsional_stiffness": "--arm-stiffness", "damping_ratio": "--damping-ratio",
               "spring_rate": "--spring-rate", "spring_preload": "--spring-preload",
               "spring_margin": "--spring-margin", "cam_width": "--cam-width",
               "allowable_stress": "--allowable-stress",
               "max_pressure_angle": "--max-pressure-angle",
               "camshaft_torsional_stiffness": "--camshaft-torsion",
               "camshaft_bending_stiffness": "--camshaft-bending",
               "camshaft_inertia": "--camshaft-inertia",
               "speed_fluctuation": "--speed-fluctuation"}
"""Each field by the option `camdyn design` gives it, for the messages."""

LIMITS = {"stroke": (1e-6, 10.0), "swing": (0.01, 89.0), "base_radius": (1e-6, 100.0),
          "roller_radius": (1e-6, 100.0), "roller_width": (1e-6, 10.0),
          "pivot_distance": (1e-6, 100.0), "arm_length": (1e-6, 100.0),
          "crown_radius": (1e-6, 1e3), "mass": (1e-9, 1e6), "inertia": (1e-12, 1e6),
          "stiffness": (1e-3, 1e12), "torsional_stiffness": (1e-6, 1e12),
          "damping_ratio": (0.0, 0.99), "spring_rate": (0.0, 1e12),
          "spring_preload": (0.0, 1e9), "spring_margin": (0.0, 10.0),
          "cam_width": (1e-6, 10.0), "allowable_stress": (1e3, 1e12),
          "max_pressure_angle": (1.0, 89.0), "camshaft_torsional_stiffness": (1e-3, 1e12),
          "camshaft_bending_stiffness": (1e-3, 1e12), "camshaft_inertia": (1e-12, 1e6),
          "speed_fluctuation": (1e-4, 0.99)}
"""The range each value is taken in (SI, angles in degrees): far beyond any machine, and
where the formulas stay finite."""

SPEED_LIMITS = (1e-3, 1e5)
"""The band's speeds, rad/s (0.01 to a million rpm)."""


def check(values: dict, names: dict) -> Machine:
    """A Machine of ``values`` (SI), every value in its range and every required one given, the
    messages naming them by ``names`` (the file's keys or the options); all the missing ones
    in one message."""
    def name(f):
        return names.get(f, f)

    kind = values["follower"]
    rocker = kind.startswith("oscillating")
    missing = [f for f in ("angles", "speeds", "base_radius") if values.get(f) is None]
    missing += [f for f in (("pivot_distance", "swing") if rocker else ("stroke",))
                if values.get(f) is None]
    if kind == "oscillating-roller" and values.get("arm_length") is None:
        missing.append("arm_length")
    if kind.endswith("roller") and values.get("roller_radius") is None:
        missing.append("roller_radius")
    if values.get("mass") is None and values.get("inertia") is None:
        missing.append("inertia" if rocker else "mass")
    if values.get("stiffness") is None and values.get("torsional_stiffness") is None:
        missing.append("torsional_stiffness" if rocker else "stiffness")
    if missing:
        raise CamdynInputError("missing: " + ", ".join(name(f) for f in missing) + " (" +
                               ("a rocker's swing in deg, pivot distance, arm, inertia about "
                                "the pivot and torsional stiffness" if rocker else
                                "the stroke, the four angles, the speed band, the base circle, "
                                "the train's mass and stiffness") + ")")
    for f, (lo, hi) in LIMITS.items():
        v = values.get(f)
        if v is not None and not (lo <= v <= hi):
            raise CamdynInputError(f"{name(f)}={v:g} is out of range: {lo:g} to {hi:g} "
                                   f"({_unit(f)})")
    if not rocker and values.get("swing") is not None:
        raise CamdynInputError(f"{name('swing')}: a translating follower takes a stroke")
    if rocker and values.get("stroke") is not None:
        raise CamdynInputError(f"{name('stroke')}: a rocker's stroke is its arc; give its swing")
    for given, other in (("mass", "inertia"), ("stiffness", "torsional_stiffness")):
        if values.get(given) is not None and values.get(other) is not None:
            raise CamdynInputError(f"{name(given)} or {name(other)}, not both")
    if not rocker and (values.get("inertia") is not None
                       or values.get("torsional_stiffness") is not None):
        raise CamdynInputError(f"{name('inertia')} and {name('torsional_stiffness')} are a "
                               f"rocker's, about its pivot; a translating follower takes "
                               f"{name('mass')} and {name('stiffness')}")
    lo, hi = values["speeds"]
    if not (SPEED_LIMITS[0] <= lo <= hi <= SPEED_LIMITS[1]):
        raise CamdynInputError(f"{name('speeds')}: the speeds must lie in "
                               f"{SPEED_LIMITS[0]:g} to {SPEED_LIMITS[1]:g} rad/s, the lowest "
                               f"first")
    if not values["materials"]:
        raise CamdynInputError(f"{name('materials')}: two materials, cam and follower")
    m = Machine(**{k: v for k, v in values.items() if v is not None or k in ("spring_rate",
                                                                          "spring_preload")})
    _geometry(m, name)
    return m


def _unit(f: str) -> str:
    return {"swing": "deg", "max_pressure_angle": "deg", "mass": "kg", "inertia": "kg m^2",
            "stiffness": "N/m", "torsional_stiffness": "N m/rad", "damping_ratio": "1",
            "spring_rate": "N/m, or N m/rad at a rocker's pivot",
            "spring_preload": "N, or N m at a rocker's pivot", "spring_margin": "1",
            "allowable_stress": "Pa", "camshaft_torsional_stiffness": "N m/rad",
            "camshaft_bending_stiffness": "N/m", "camshaft_inertia": "kg m^2",
            "speed_fluctuation": "1"}.get(f, "m")


def _geometry(m: Machine, name) -> None:
    """The follower reaches the cam: a rocker's arm from its pivot to the base pitch circle
    (runtime/cam/follower.py arm_reaches), a flat face's line within the pivot distance, a
    roller smaller than the base circle it rolls on."""
    from camdyn.runtime.cam.follower import arm_reaches

    if m.roller and m.roller_radius >= m.base_radius:
        raise CamdynInputError(f"{name('roller_radius')}={m.roller_radius:g} m must be below "
                               f"{name('base_radius')}={m.base_radius:g} m")
    if m.follower == "oscillating-roller" and not arm_reaches(
            m.pivot_distance, m.arm_length, m.base_radius + m.roller_radius):
        raise CamdynInputError(
            f"{name('arm_length')}={m.arm_length:g} m does not reach the base pitch circle "
            f"({m.base_radius + m.roller_radius:g} m) from the pivot "
            f"{m.pivot_distance:g} m away: |a - l| < r_b + r_r < a + l")
    if m.follower == "oscillating-flat" and not abs(m.base_radius - m.face_offset) < \
            m.pivot_distance:
        raise CamdynInputError(f"{name('face_offset')}={m.face_offset:g} m: the face cannot "
                               f"touch the base circle, |r_b - f| < a")


def angles_of(raw, key: str) -> tuple | None:
    """The four cam angles (deg): '120,60,120,60', a list, or strings with units."""
    if raw is None:
        return None
    items = raw.split(",") if isinstance(raw, str) else raw
    if not isinstance(items, (list, tuple)) or len(items) != 4:
        raise CamdynInputError(f"{key}: four angles, rise, outer dwell, return, inner dwell "
                               f"(deg, summing to 360), got {raw!r}")
    ang = tuple(units.value(a.strip() if isinstance(a, str) else a, "angle", key)
                for a in items)
    from camdyn.runtime.core import laws

    try:
        laws.compose("cycloidal", None, ang)        # the turn's own checks
    except CamdynInputError as exc:
        raise CamdynInputError(f"{key}: {exc}") from None
    return ang


def laws_of(raw, key: str) -> tuple:
    """The candidate laws: 'all', a name, a comma list or a list of names and law files."""
    from camdyn.runtime.core import laws, shaped

    items = raw.split(",") if isinstance(raw, str) else raw
    if not isinstance(items, (list, tuple)) or not items:
        raise CamdynInputError(f"{key}: 'all', a law, or a list of laws and law files")
    out = []
    for item in items:
        item = str(item).strip()
        if item == "all" or item in laws.NAMES or shaped.is_law_file(item):
            out.append(item)
        else:
            raise CamdynInputError(f"{key}: unknown cam law {item!r}; 'all', one of "
                                   f"{', '.join(laws.NAMES)}, or a law file (.csv, .toml)")
    if len(set(out)) != len(out):
        raise CamdynInputError(f"{key}: a law given twice in {raw!r}")
    return tuple(out)


def materials_of(raw, key: str) -> tuple:
    """(cam, follower) material names or E:nu pairs."""
    from camdyn.runtime.cam.stress import material

    items = raw.split(",") if isinstance(raw, str) else raw
    if not isinstance(items, (list, tuple)) or len(items) != 2:
        raise CamdynInputError(f"{key}: two materials, cam and follower (one of "
                               f"{', '.join(MATERIALS)}, or E:nu), got {raw!r}")
    pair = tuple(str(m).strip() for m in items)
    for m in pair:
        try:
            material(m)
        except CamdynInputError as exc:
            raise CamdynInputError(f"{key}: {exc}") from None
    return pair


def load(path) -> Machine:
    """A machine file (TOML), read and checked."""
    import tomllib
    from pathlib import Path

    p = Path(path)
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CamdynInputError(f"machine file {path} not found") from None
    except IsADirectoryError:
        raise CamdynInputError(f"machine file {path} is a folder") from None
    except UnicodeDecodeError:
        raise CamdynInputError(f"machine file {path} is not UTF-8 text") from None
    except tomllib.TOMLDecodeError as exc:
        raise CamdynInputError(f"machine file {path}: not TOML ({exc})") from None
    return from_dict(data, str(path))


def is_machine_file(path) -> bool:
    """Whether ``path`` is a TOML file whose kind is "machine" (without raising)."""
    import tomllib
    from pathlib import Path

    p = Path(str(path))
    if p.suffix != ".toml" or not p.is_file():
        return False
    try:
        return tomllib.loads(p.read_text(encoding="utf-8")).get("kind") == KIND
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return False


TEMPLATE = '''\
# A machine for `camdyn design MACHINE.toml --laws all`: the law, the spring and the cam that
# hold over the whole speed band.  Units: a number is SI (m, kg, N/m, N, Pa), but an angle,
# which is in degrees; a string carries its own unit ("25 mm", "2e6 N/m", "300:600 rpm").
kind = "machine"
title = "Packaging station"

[follower]
type = "translating-roller"   # translating-roller, translating-flat, oscillating-roller,
                              # oscillating-flat
roller_radius = "10 mm"       # a roller's
roller_width = "12 mm"        # the contact's length, for the Hertz stress
# offset = "0 mm"             # a translating follower's axis off the cam centre
# pivot_distance = "100 mm"   # a rocker's pivot from the cam centre
# arm_length = "80 mm"        # an oscillating roller's arm, pivot to roller centre
# face_offset = "0 mm"        # an oscillating flat face's line from the pivot

[motion]
stroke = "25 mm"              # a translating follower's; a rocker's: swing = "18 deg"
angles = "120, 60, 120, 60"   # rise, outer dwell, return, inner dwell, deg
laws = "all"                  # or ["cycloidal", "4-5-6-7", "my_law.toml"]

[speed]
band = "300:600 rpm"          # rpm, rad/s or Hz (revolutions per second); one speed as "450 rpm"

[train]                       # the follower train at the follower (a rocker's about its pivot)
mass = "0.8 kg"               # a rocker: inertia = "0.0039 kg m^2"
stiffness = "2e6 N/m"         # a rocker: torsional_stiffness = "12800 N m/rad"
# damping_ratio = 0.02

[spring]                      # at the follower (a rocker's rate and preload at its pivot)
rate = "1000 N/m"
preload = "size"              # or a force, "50 N": "size" finds the least that holds
margin = 0.3                  # the spring's force at least 1.3 times the inertia force

[cam]
base_radius = "40 mm"
materials = "steel, steel"    # cam, follower: steel, cast-iron, bronze, ... or E:nu
allowable_stress = "1200 MPa"
# max_pressure_angle = 30     # deg
# width = "12 mm"             # the plate, for a flat face's contact and the STEP solid

# [camshaft]                  # optional: brings in Fa, Fv and the thesis's larger models
# torsional_stiffness = "2000 N m/rad"
# bending_stiffness = "5e6 N/m"
# inertia = "0.0015 kg m^2"

# [drive]
# speed_fluctuation = 0.05    # size a flywheel for (w_max - w_min)/w_s
'''
"""The commented machine file `camdyn scenes --template machine` writes."""


def as_toml(m: Machine) -> str:
    """The machine as a machine file (units spelled out), which :func:`load` reads back to
    the same machine: the chosen design's export."""
    def q(v, unit, scale=1.0):
        return f'"{v / scale:.10g} {unit}"'

    lines = ["kind = \"machine\"", f"title = {_text(m.title)}", "", "[follower]",
             f"type = \"{m.follower}\""]
    for f, unit in (("roller_radius", "m"), ("roller_width", "m"), ("pivot_distance", "m"),
                    ("arm_length", "m"), ("crown_radius", "m")):
        if getattr(m, f) is not None:
            lines.append(f"{f} = {q(getattr(m, f), unit)}")
    if m.offset:
        lines.append(f"offset = {q(m.offset, 'm')}")
    if m.face_offset:
        lines.append(f"face_offset = {q(m.face_offset, 'm')}")
    lines += ["", "[motion]"]
    lines.append(f"swing = {q(m.swing, 'deg')}" if m.rocker else f"stroke = {q(m.stroke, 'm')}")
    lines.append("angles = [" + ", ".join(f"{a:.10g}" for a in m.angles) + "]")
    lines.append("laws = [" + ", ".join(_text(x) for x in m.laws) + "]")
    lo, hi = (units.speed_in(w, m.speed_unit) for w in m.speeds)
    lines += ["", "[speed]", f"band = \"{lo:.10g}:{hi:.10g} {m.speed_unit}\"", "", "[train]"]
    if m.inertia is not None:
        lines.append(f"inertia = {q(m.inertia, 'kg*m**2')}")
    else:
        lines.append(f"mass = {q(m.mass, 'kg')}")
    if m.torsional_stiffness is not None:
        lines.append(f"torsional_stiffness = {q(m.torsional_stiffness, 'N*m/rad')}")
    else:
        lines.append(f"stiffness = {q(m.stiffness, 'N/m')}")
    if m.damping_ratio:
        lines.append(f"damping_ratio = {m.damping_ratio!r}")
    lines += ["", "[spring]"]
    rate_unit, force_unit = ("N*m/rad", "N*m") if m.rocker else ("N/m", "N")
    if m.spring_rate is not None:
        lines.append(f"rate = {q(m.spring_rate, rate_unit)}")
    lines.append("preload = \"size\"" if m.spring_preload is None
                 else f"preload = {q(m.spring_preload, force_unit)}")
    lines.append(f"margin = {m.spring_margin!r}")
    lines += ["", "[cam]", f"base_radius = {q(m.base_radius, 'm')}",
              f"materials = [{_text(m.materials[0])}, {_text(m.materials[1])}]",
              f"max_pressure_angle = {m.max_pressure_angle!r}"]
    if m.allowable_stress is not None:
        lines.append(f"allowable_stress = {q(m.allowable_stress, 'Pa')}")
    if m.cam_width is not None:
        lines.append(f"width = {q(m.cam_width, 'm')}")
    shaft = [(f, getattr(m, f"camshaft_{f}"), u) for f, u in (
        ("torsional_stiffness", "N*m/rad"), ("bending_stiffness", "N/m"),
        ("inertia", "kg*m**2")) if getattr(m, f"camshaft_{f}") is not None]
    if shaft:
        lines += ["", "[camshaft]"] + [f"{f} = {q(v, u)}" for f, v, u in shaft]
    if m.speed_fluctuation is not None:
        lines += ["", "[drive]", f"speed_fluctuation = {m.speed_fluctuation!r}"]
    return "\n".join(lines) + "\n"


def _text(s: str) -> str:
    import json

    return json.dumps(str(s))


def with_preload(m: Machine, preload_at_output: float) -> Machine:
    """The machine with its spring's preload set (given at the output: a rocker's is turned
    into its torque at the pivot, F_0 l)."""
    return replace(m, spring_preload=preload_at_output * m.lever if m.rocker
                   else preload_at_output)


FIELDS = tuple(f.name for f in fields(Machine))
