"""The campaign (tests/test_campaign.py) over the design page's inputs, through the function
the page calls on every change: ``camdyn.runtime.cli.page.evaluate(Inputs(...))`` (and
``verdict``, the design rules it shows next).  Whatever the widgets hold, it returns finite
figures with their estimates, or raises CamdynInputError (bad input) or SimulationError (a
run that failed) with a one-line message, which the page prints above its greyed-out charts;
never another exception.

Drawn: the mechanism (a model, a built-in scene, a scene file good or broken in every way a
file can be: missing, a folder, a device, a pipe, over 1 MB, not UTF-8, not TOML, no kind,
another kind, parameters missing or out of range), the law, tau, Fa, Fv, the scene's
parameters, the follower and its cam's fields, the contact force, the width, the rise time,
the accuracy and the tau range.
"""
from __future__ import annotations

import math
import os
import tomllib
from dataclasses import fields

import numpy as np
import pytest
from hypothesis import given, strategies as st

from camdyn.runtime.targets import scene_files

from .test_campaign import (FINDINGS, LONG, NUMBERS, QUICK, _dump, campaign_session,  # noqa: F401
                            carries_estimates, few, finite_figures, many, tally)

MECHANISMS_GOOD = ["camshaft1", "one_dof", "camshaft2", "spring_loaded", "rocker", "fig8_1a",
                   "@good.toml", "indexing", "@turn.toml"]
MECHANISMS_BAD = ["nope", "", "@missing.toml", "@folder.toml", "/dev/zero", "@pipe.toml",
                  "@big.toml", "@latin1.toml", "@notoml.toml", "@nokind.toml", "beam_paper",
                  "rocker_study", "default", "@beam.toml", "@study.toml", "@noparams.toml",
                  "@range.toml", "@binary.toml", "@empty.toml", "@nan.toml"]
LAWS_GOOD = ["cycloidal", "modified-sine", "3-4-5", "4-5-6-7", "5-6-7-8-9",
             "modified-trapezoid", "simple-harmonic"]
LAWS_BAD = ["nope", "", "polydyne", "sine-constant-cosine", "uniform", "parabolic",
            "@law_blend.toml", "@law_binary.csv", "@missing.csv"]
FOLLOWERS = ["translating-roller", "oscillating-roller", "translating-flat", "oscillating-flat"]
ABSURD = [0.0, -1.0, float("nan"), float("inf"), float("-inf"), 1e300, 1e-300, -0.0]


@pytest.fixture(scope="session")
def page_files(tmp_path_factory):
    """The scene files the mechanism box may be given."""
    folder = tmp_path_factory.mktemp("page")
    rocker = scene_files.builtin("rocker").read_text()
    (folder / "good.toml").write_text(rocker)
    turn = tomllib.loads(scene_files.builtin("spring_loaded").read_text())
    turn["turn"] = {"upper_dwell": 60.0, "return": 40.0}
    (folder / "turn.toml").write_text(_dump(turn))
    (folder / "folder.toml").mkdir()
    os.mkfifo(folder / "pipe.toml")
    (folder / "big.toml").write_text(rocker + "#" * (1 << 20) + "\n")
    (folder / "latin1.toml").write_bytes(rocker.encode() + "# \xe9\n".encode("latin-1"))
    (folder / "notoml.toml").write_text("this is not toml [\n")
    (folder / "nokind.toml").write_text(rocker.replace('kind = "dynacam"', ""))
    (folder / "beam.toml").write_text(scene_files.builtin("beam_paper").read_text())
    (folder / "study.toml").write_text(scene_files.builtin("rocker_study").read_text())
    (folder / "noparams.toml").write_text(rocker.replace("k = 2000.0", ""))
    (folder / "range.toml").write_text(rocker.replace("c_x = 2.0e6", "c_x = -2.0e6"))
    (folder / "nan.toml").write_text(rocker.replace("m_x = 0.609", "m_x = nan"))
    (folder / "binary.toml").write_bytes(bytes(range(256)) * 8)
    (folder / "empty.toml").write_text("")
    (folder / "law_blend.toml").write_text("[bspline]\ncontrol = [0, 0, 0, 0.5, 1, 1, 1]\n")
    (folder / "law_binary.csv").write_bytes(bytes(range(256)))
    return folder


def _at(folder, name: str) -> str:
    return str(folder / name[1:]) if name.startswith("@") else name


def either(good, bad):
    return st.one_of(st.sampled_from(good), st.sampled_from(bad))


def numbers(*good):
    return st.one_of(st.sampled_from(list(good)), st.sampled_from(ABSURD), NUMBERS)


SCENE_KEYS = ["h_m", "beta_m", "R_b", "l_a", "d_p", "m_x", "c_x", "omega_s", "nope", "q_x"]


def scene_parameters():
    """{} mostly; else one or two of a scene's parameters set to a drawn value, an unknown
    key among them, or the classic troubles: beta_m >= pi without [turn], h_m/l_a >= 90 deg,
    an arm too short, R_b within the roller."""
    classic = st.sampled_from([{"beta_m": math.pi}, {"beta_m": 4.0}, {"h_m": 0.2, "l_a": 0.08},
                               {"l_a": 0.001}, {"R_b": 0.005}, {"R_b": 0.008},
                               {"h_m": float("nan")}, {"beta_m": 2.0}, {"m_x": 1.0}])
    drawn = st.dictionaries(st.sampled_from(SCENE_KEYS), numbers(0.05, 1.5), max_size=2)
    return st.one_of(st.just({}), st.just({}), classic, drawn)


FIELDS = {
    "base_radius": (0.04, 0.06), "roller_radius": (0.008, 0.01), "stroke": (0.02, 0.01),
    "swing_deg": (18.0, 45.0, 89.0, 90.0), "pivot_distance": (0.1,), "arm_length": (0.08,),
    "face_offset": (0.0, 0.01), "rise_deg": (120.0, 90.0, 0.0, 180.0, 200.0),
    "contact_force": (500.0, 100.0), "width": (0.01, 1e12), "rise_time": (0.1, 0.05),
    "accuracy": (1e-4, 20e-6), "tau": (0.15, 0.3, 0.9, 1.5), "Fa": (0.5, 0.0, 13.0),
    "Fv": (10.0, 2.5), "tau_min": (0.05, 0.1), "tau_max": (0.8, 0.5, 0.05),
}


@st.composite
def inputs(draw):
    """An Inputs: the mechanism, law and follower drawn, and the fields: all ordinary, or one
    or a few of them drawn from the ordinary, absurd and any numbers."""
    from camdyn.runtime.cli.page import Inputs

    kw = {"mechanism": draw(either(MECHANISMS_GOOD, MECHANISMS_BAD)),
          "law": draw(either(LAWS_GOOD, LAWS_BAD)),
          "follower": draw(either(FOLLOWERS, ["nope", ""])),
          "scene_parameters": draw(scene_parameters())}
    odd = draw(st.lists(st.sampled_from(sorted(FIELDS)), max_size=draw(st.sampled_from(
        [0, 0, 1, 1, 2, 4])), unique=True))
    for name, good in FIELDS.items():
        kw[name] = draw(numbers(*good) if name in odd else st.sampled_from(good[:2]))
    assert {f.name for f in fields(Inputs)} == set(kw)
    return kw


def _finite_arrays(out: dict) -> None:
    """The charts' series: finite where they carry a figure (the response, the residual
    sweep and its estimates, the envelope, the cam)."""
    for key in ("T", "Xdd", "tau_axis", "U0dd", "env_tau", "env_value", "x", "y", "alpha_deg"):
        v = out.get(key)
        if v is not None:
            assert np.all(np.isfinite(np.asarray(v, dtype=float))), key
    if out.get("p0") is not None:
        # Hertz's p0 is unbounded where the profile cusps or is undercut: +inf there, and then
        # no largest stress is given (None) and the profile's check warns
        p0 = np.asarray(out["p0"], dtype=float)
        assert not np.isnan(p0).any(), "p0 has NaN"
        if not np.all(np.isfinite(p0)):
            assert out["stress"]["hertz_stress_max"] is None and out["profile_warnings"], \
                "p0 infinite where no check warns"
    err = out.get("U0dd_error")
    if err is not None:
        e = np.asarray(err, dtype=float)
        assert np.all(np.isfinite(e) & (e >= 0)), "U0dd_error"


def page_case(kw: dict, folder) -> str:
    """evaluate() and verdict() on ``kw``: the verdict under the feature "page"."""
    from camdyn.runtime.cli.page import Inputs, evaluate, verdict
    from camdyn.runtime.core.errors import CamdynInputError, SimulationError

    kw = {**kw, "mechanism": _at(folder, kw["mechanism"]), "law": _at(folder, kw["law"])}
    said = [f"{k}={v!r}" for k, v in kw.items()]
    try:
        out = evaluate(Inputs(**kw))
        finite_figures(out["answer"].as_dict(), "answer")
        carries_estimates("simulate" if out["contact_force"] is not None else "residual",
                          out["answer"].as_dict())
        finite_figures({k: out[k] for k in ("design", "extremes", "stress", "contact_force")
                        if out.get(k) is not None}, "page")
        _finite_arrays(out)
        rules = verdict(out["inputs"], out["design"])
        finite_figures(rules, "verdict")
    except CamdynInputError as exc:
        verdict_ = "refused" if "\n" not in str(exc).strip() else "wrong answer"
    except SimulationError as exc:
        verdict_ = "run failed" if "\n" not in str(exc).strip() else "wrong answer"
    except AssertionError as exc:
        tally("page", "wrong answer", said)
        raise AssertionError(("wrong answer", said, str(exc))) from None
    except Exception as exc:        # noqa: BLE001 - anything else is the finding
        tally("page", "traceback", said)
        raise AssertionError(("traceback", said, f"{type(exc).__name__}: {exc}")) from exc
    else:
        verdict_ = "answered"
    tally("page", verdict_, said)
    assert verdict_ not in FINDINGS, (verdict_, said)
    return verdict_


@few(30)
@given(kw=inputs())
def test_quick_campaign_over_the_design_page(kw, page_files):
    page_case(kw, page_files)


@pytest.mark.slow
@many(150)
@given(kw=inputs())
def test_campaign_over_the_design_page(kw, page_files):
    page_case(kw, page_files)
