"""The check run of a design point: one rise and dwell of the least model that is adequate
(the one-DOF model (3.1) when the shaft's flexibility does not show in the envelope, else
CAMSHAFT-1 (4.15)), its U0, U0'', X''min with error estimates beside the envelope values
(runtime/measure/contract.py)."""
from __future__ import annotations

from camdyn.runtime.core.methods import DP54
from camdyn.runtime.measure.contract import answer, tighter_run, unavailable
from camdyn.runtime.measure.residual import FIGURES as RESIDUAL_FIGURES
from camdyn.runtime.targets.model_target import ModelTarget

from .extremes import place_resolution

ONE_DOF_TOLERANCE = 0.02
"""The one-DOF model (3.1) stands in for CAMSHAFT-1 when the envelopes at Fa and at 0 differ
by less than this, relatively (the check run's least adequate model)."""

FIGURES = RESIDUAL_FIGURES
"""What the check run reports of the run (runtime/measure/residual.py), each with its error."""

RTOL = 1e-10
"""Tolerance of the check run (DP54): the thesis's scheme's accuracy and then some."""

MODELS = {"one-dof": "one_dof", "camshaft1": "camshaft1"}
"""The check run's models by the names the answer gives them."""

TWIN_FACTOR = DP54(rtol=RTOL).estimate_factor
"""What the design states as the error of a figure of its runs, DP54 at RTOL: this times
|v - v'| of the run one notch tighter, the answer contract's factor (1.5 with v' at rtol/100,
runtime/core/methods.py).  With v' at rtol/10 and a factor 1 the difference measured
0.88-0.91 of the true error of U0, U0'' and X''min against the closed form of (3.1)."""


def least_model(U0_env_Fa: float, U0_env_0: float, Fa: float,
                tolerance: float = ONE_DOF_TOLERANCE) -> tuple[str, str]:
    """(model, why): the one-DOF model (3.1) when the envelope at Fa and at Fa = 0 differ by
    less than ``tolerance`` (the shaft's flexibility does not show), else CAMSHAFT-1 (4.15).

    Kept small so that a general chooser of the least adequate model can take its place."""
    if Fa == 0:
        return "one-dof", "Fa = 0: a rigid shaft, constant fictitious angular velocity (ch. 3)"
    change = abs(U0_env_Fa / U0_env_0 - 1.0)
    if change < tolerance:
        return "one-dof", (f"Fa = {Fa:.3g} changes the U0 envelope by {100 * change:.2g} % "
                           f"(< {100 * tolerance:g} %) against Fa = 0: the shaft's flexibility "
                           "does not show (ch. 3)")
    return "camshaft1", (f"Fa = {Fa:.3g} changes the U0 envelope by {100 * change:.3g} % against "
                         "Fa = 0: the variable fictitious angular velocity of CAMSHAFT-1 (4.15) is "
                         "needed; the flywheel effect is left out (Fv -> oo, sec. 8.2.5)")


def check_answer(model: str, tau: float, Fa: float, law: str, theta):
    """The check run at (tau, Fa) as the answer contract gives it: figures, errors, warnings,
    the run and the run one notch tighter (runtime/measure/contract.py, Answer)."""
    params = {"tau": tau} if model == "one-dof" else {"tau": tau, "Fa": Fa}
    return answer(ModelTarget.of(MODELS[model], params, method="dp54", rtol=RTOL, law=law,
                                 theta=theta))


def check_run(model: str, tau: float, Fa: float, law: str, theta, a=None) -> dict:
    """U0, U0'', X''min and where it falls, of the run at (tau, Fa), each with its error
    estimate by the answer contract (the run one notch tighter, its difference times
    TWIN_FACTOR, and the sampling error of the scan that found the extreme), and the
    run's warnings; ``a`` the check run's Answer when already made (check_answer)."""
    a = a if a is not None else check_answer(model, tau, Fa, law, theta)
    errors = stated_errors(a)
    if a.result is not None and errors.get("T_at_Xdd_min") is not None:
        # a flat extreme's place: the run's rounding against the curvature of X'' (extremes.py)
        rounding, place = place_resolution(a.result, "Xdd", a.figures["T_at_Xdd_min"])
        errors["T_at_Xdd_min"] += place
        errors["Xdd_min_rise"] += rounding
    out = {k: a.figures[k] for k in FIGURES}
    out.update({f"{k}_error": errors[k] for k in FIGURES})
    out["warnings"] = list(a.warnings)
    return out


def stated_errors(a) -> dict:
    """The errors the design states for the figures of the Answer ``a``: the contract's (its
    discretisation part TWIN_FACTOR |v - v'| already); None where it has no estimate."""
    return dict(a.errors)


def turn_runs(model: str, tau: float, Fa: float, drive, t_end: float) -> tuple:
    """(run, run one notch tighter or None, warnings): the check run's model driven by
    ``drive`` (a whole turn, runtime/core/laws.py Turn) from rest to ``t_end`` (one period),
    at the check run's method and tolerance; the tighter run as the answer contract makes it."""
    params = {"tau": tau} if model == "one-dof" else {"tau": tau, "Fa": Fa}
    target = ModelTarget.of(MODELS[model], params, method="dp54", rtol=RTOL, law=drive,
                            t_end=t_end)
    base = target.run()
    tight, why = tighter_run(target)
    warnings = list(base.warnings) + ([unavailable(why)] if why is not None else [])
    return base.result, None if tight is None else tight.result, warnings
