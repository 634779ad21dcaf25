"""The Rayleigh-beam follower's case: what a user varies, its defaults (the paper's data,
sec. 4) and its checks; light enough for the command line to read the defaults for its help
without loading SciPy (the runs are in :mod:`camdyn.runtime.targets.beam`).
"""
from __future__ import annotations

import math
import pkgutil
import re
from dataclasses import dataclass

from camdyn import generated

from ..core.errors import CamdynInputError
from ..core.laws import choose

FORMULATIONS = {"augmented": 0.0, "partitioned": 1.0, "projection": 2.0}
"""How the constraints are solved: the model's parameter ``formulation`` for each name."""

N_MAX = max(int(m.name[4:]) for m in pkgutil.iter_modules(generated.__path__)
            if re.fullmatch(r"beam\d+", m.name))
"""Largest number of assumed modes: the beam<N> modules that camdyn derive generated."""


def _declared_defaults() -> dict:
    """The model's parameter defaults (the paper's data, sec. 4) as its manifest declares
    them: the declaration (camdyn/derive/models/beam.py) is their one home."""
    from importlib import import_module

    manifest = import_module("camdyn.generated.beam1").MANIFEST
    return {p["name"]: p["default"] for p in manifest["parameters"]}


_D = _declared_defaults()

MODE_ATOL = 3e-5
"""`camdyn beam-follower`'s absolute tolerance of the mode amplitudes b_i (``Case.mode_atol``),
as a fraction of the rod's deflection scale S_T Omega^2/w_1^2 (the cam's acceleration over the
square of the lowest frozen frequency w_1: 4.8e-5 m for the paper's data, whose tip deflection
is 2.2e-4 m; 4.8e-11 m for a rod 1e6 times stiffer), 1.4e-9 m there; a rate's is that times
the highest frozen frequency w_N (beam.integrator: the fastest mode's rate held as its
amplitude is).  The default of every other run, 1e-3 rtol of the amplitudes' declared scale
(1e-5 m), holds the higher modes, which ring at 1e-12 m and less, to 1e-17 m at rtol 1e-9:
N = 6 then took 100 times the steps its stability needs (DOP853, one revolution: 952,227
steps at rtol 1e-8), and did not finish with DP54.  With this tolerance DOP853 steps at its
stability limit for w_N at N = 6 (one revolution, rtol 1e-6 or 1e-9: 9,700 steps, max |v_E|
within 5e-8 of itself; rates held to tol Omega instead: 32,000 to 40,000 steps).  The run one
notch tighter of the error estimate takes a tenth of it, so what it leaves shows in the
estimate (N = 3, rtol 1e-9: max |v_E| 1.5e-7 of itself from a tight reference, estimated
1.4e-7)."""


@dataclass(frozen=True)
class Case:
    """One Rayleigh-beam follower run.  Paper data (sec. 4) by default, read from the
    model's manifest; the run's own settings (modes, revolutions, formulation, law, rtol,
    method) are defaults of the case."""

    omega: float = _D["Omega"]      # rad/s, cam speed (paper: 120, 240, 360)
    modes: int = 3                  # N assumed modes (paper: 2, 3, 4; converged at 3)
    rod_radius: float = _D["a_rod"]     # m (paper: 3, 5, 7 mm)
    distance: float = _D["d"]       # m, cam centre to guide exit, d (paper: 102, 112, 122 mm)
    base_radius: float = _D["r_b"]  # m, r_b
    rise: float = _D["S_T"]         # m, S_T (paper: 8, 15, 22 mm)
    revolutions: float = 1.0
    rayleigh: bool = _D["rayleigh"] > 0.5   # rotary inertia of the rod
    roller_inertia: float | None = None   # kg m^2; None: uniform disc m_r r_r^2/2
    formulation: str = "augmented"
    law: str = "cycloidal"
    roller_radius: float = _D["r_r"]    # m, r_r
    roller_mass: float = _D["m_r"]      # kg, m_r
    E: float = _D["E"]              # Pa
    rho: float = _D["rho"]          # kg/m^3
    rtol: float = 1e-9
    method: str = "dp54"            # an adaptive method: dp54, dop853, or rodas4 for stiff rods
    w_B: float = _D["w_B"]          # rad/s, Baumgarte rate (augmented form)
    atol: float | None = None       # absolute tolerance, in the states' tolerance scales
    state_atol: tuple = ()          # (state, absolute tolerance in its units) pairs
    mode_atol: float | None = None  # b_i's absolute tolerance / deflection_scale (MODE_ATOL)

    @property
    def model(self) -> str:
        return f"beam{self.modes}"

    @property
    def J_r(self) -> float:
        if self.roller_inertia is None:
            return self.roller_mass * self.roller_radius**2 / 2
        return self.roller_inertia

    @property
    def period(self) -> float:
        return 2 * math.pi / self.omega

    @property
    def free_length_raised(self) -> float:
        """x_E at the outer dwell, the follower fully raised: d - r_b - r_r - S_T."""
        return self.distance - self.base_radius - self.roller_radius - self.rise


def check(case: Case) -> Case:
    """Refuse a case that cannot run, naming the parameter and its range."""
    positive = ("omega", "rod_radius", "distance", "base_radius", "rise", "revolutions",
                "roller_radius", "roller_mass", "E", "rho", "rtol")
    for name in positive:
        v = getattr(case, name)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
            raise CamdynInputError(f"{name}={v!r}: must be a positive number")
    if isinstance(case.modes, bool) or not isinstance(case.modes, int) or not 1 <= case.modes <= N_MAX:
        raise CamdynInputError(f"modes={case.modes!r}: choose an integer from 1 to {N_MAX}")
    if case.formulation not in FORMULATIONS:
        raise CamdynInputError(f"formulation={case.formulation!r}: choose one of "
                               f"{', '.join(FORMULATIONS)}")
    if case.roller_inertia is not None and not (math.isfinite(case.roller_inertia)
                                                 and case.roller_inertia >= 0):
        raise CamdynInputError(f"roller_inertia={case.roller_inertia!r}: must be >= 0")
    if case.mode_atol is not None and not (isinstance(case.mode_atol, (int, float))
                                           and math.isfinite(case.mode_atol)
                                           and case.mode_atol > 0):
        raise CamdynInputError(f"mode_atol={case.mode_atol!r}: must be a finite number > 0 (a "
                               "fraction of the rod's deflection scale)")
    if not (math.isfinite(case.w_B) and case.w_B >= 0):
        raise CamdynInputError(f"w_B={case.w_B!r}: must be >= 0")
    # the roller (radius r_r about E) must stay clear of the guide when fully raised
    if case.free_length_raised <= case.roller_radius:
        limit = case.distance - 2 * case.roller_radius - case.rise
        raise CamdynInputError(
            f"base_radius={case.base_radius:g} m puts the roller into the guide at the top of the "
            f"stroke (free rod {case.free_length_raised * 1e3:.3g} mm, roller radius "
            f"{case.roller_radius * 1e3:g} mm): with distance={case.distance:g} m and "
            f"rise={case.rise:g} m, base_radius must be below {limit:g} m")
    from ..core.methods import ADAPTIVE  # here, not at the top: the help text loads this module

    if case.method not in ADAPTIVE:
        raise CamdynInputError(f"method={case.method!r}: the beam follower takes an adaptive "
                               f"method: {', '.join(ADAPTIVE)}")
    choose(case.law)
    from ..core.methods import METHODS

    METHODS[case.method](rtol=case.rtol, atol=case.atol, state_atol=case.state_atol)   # checked
    return case
