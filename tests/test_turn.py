"""Dwell-rise-dwell-return over a full cam turn (runtime.laws.compose, law code TURN of the
generated library) as the cam input of a model: checked against the plain rise law, against
linear superposition of plain rises (an independent construction of the return), against
the profile's own composition (runtime.profile.RDFD) and for its segment boundaries."""
import math

import numpy as np
import pytest

from camdyn.generated import camlaws as lib
from camdyn.runtime.core import laws
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.compiled import load
from camdyn.runtime.cam.motion import RDFD
from camdyn.runtime.core.simulator import simulate, stop_times

TAU = 0.15   # one_dof's T_e/t_m (3.3), the thesis's example value


def test_turn_run_equals_the_plain_rise_over_the_rise():
    """Up to the end of the rise the turn's input is the rise law itself, and the stop times
    in (0, 1] are the same, so one_dof (3.4) gives the same numbers, to 1e-12."""
    turn = laws.compose("modified-sine", "3-4-5", (100, 60, 120, 80), theta=0.2)
    a = simulate("one_dof", {"tau": TAU}, 1.0, "dp54", rtol=1e-10, law=turn)
    b = simulate("one_dof", {"tau": TAU}, 1.0, "dp54", rtol=1e-10, law="modified-sine", theta=0.2)
    assert a.t.shape == b.t.shape
    np.testing.assert_allclose(a.y, b.y, rtol=0, atol=1e-12)


@pytest.mark.parametrize("ret", ["cycloidal", "3-4-5"])
def test_return_is_the_mirrored_law_by_superposition(ret):
    """one_dof is linear and time-invariant in its input H, and the turn's input up to the next
    rise is H_rise(T) - H_ret(T - 1 - up) when the return is as long as the rise.  So the run
    with the turn equals the plain rise run minus the plain return-law run delayed by 1 + up,
    both from rest (independent of the turn code: no mirroring, no offsets).  RK4 with a step
    of 2^-8 puts every breakpoint on the step grid, where the discrete maps superpose to
    rounding: tolerance 1e-11."""
    h = 2.0 ** -8
    turn = laws.compose("cycloidal", ret, (90, 45, 90, 135))    # up 0.5, r 1, low 1.5, P 4
    assert (turn.up, turn.r, turn.period) == (0.5, 1.0, 4.0)
    t_end = 3.5
    kw = dict(step=h)
    X = simulate("one_dof", {"tau": TAU}, t_end, "rk4", law=turn, **kw, exact_segments=False)
    rise = simulate("one_dof", {"tau": TAU}, t_end, "rk4", law="cycloidal", **kw, exact_segments=False)
    back = simulate("one_dof", {"tau": TAU}, t_end - 1.5, "rk4", law=ret, **kw, exact_segments=False)
    T = np.arange(0, int(t_end / h) + 1) * h
    x = X.sample(T)["X"]
    expect = rise.sample(T)["X"]
    late = T >= 1.5
    expect[late] -= back.sample(T[late] - 1.5)["X"]
    np.testing.assert_allclose(x, expect, rtol=0, atol=1e-11)
    # and the input itself: H = 1 - H_ret on the return, derivatives -H_ret^(n)
    u = np.linspace(0, 1, 101, endpoint=False)
    got = turn.evaluate(1.5 + u)
    ref = laws.choose(ret).evaluate(u)
    np.testing.assert_allclose(got[:, 0], 1 - ref[:, 0], atol=1e-14)
    np.testing.assert_allclose(got[:, 1:], -ref[:, 1:], atol=1e-12)


@pytest.mark.parametrize("ret", [None, "4-5-6-7"])
def test_turn_equals_the_profile_composition_over_several_turns(rng, ret):
    """runtime.profile.RDFD (the cam profile's rise-dwell-return-dwell, written in NumPy on its
    own) gives S^(k)(phi) = S_T H^(k)(T)/beta^k with T = phi/beta; the turn repeats with
    period 360 deg/beta.  The return mirrors the rise's law, or has a law of its own, both
    ways; 1e-12 relative."""
    ang = (75.0, 40.0, 110.0, 135.0)
    turn = laws.compose("modified-sine", ret, ang, theta=0.15)
    beta = math.radians(ang[0])
    cam = RDFD.of(1.0, 0.05, 0.01, "modified-sine", 0.15, beta_rise=beta,
                  dwell_outer=math.radians(ang[1]), beta_fall=math.radians(ang[2]),
                  fall_law=None if ret is None else laws.choose(ret))
    T = rng.uniform(0, 3 * turn.period, 2000)
    got = turn.evaluate(T)
    S = cam.displacement(beta * T)
    for k in range(4):
        ref = S[k] * beta**k
        np.testing.assert_allclose(got[:, k], ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max())


def test_breakpoints_land_on_segment_boundaries():
    """At every breakpoint of three turns the generated library's segment goes up by exactly
    one (the models' events do `segment += 1`), and nowhere else; the simulator stops there.
    A zero upper dwell leaves no empty segment."""
    for ang in ((90, 90, 90, 90), (120, 0, 100, 140), (100, 80, 180, 0)):
        turn = laws.compose("parabolic", "modified-trapezoid", ang)
        P = turn.period
        bps = turn.breakpoints_between(-1.0, 3 * P + 0.5)
        assert bps[0] == 0.0 and all(np.diff(bps) > 0)
        code, par = turn.code, turn.par
        seg = [lib.segment(code, par, b) for b in bps]
        before = [lib.segment(code, par, np.nextafter(b, -np.inf)) for b in bps]
        assert seg == [s + 1 for s in before], ang
        assert seg == list(range(1, len(bps) + 1))
        # between breakpoints the segment is constant
        for lo, hi in zip(bps[:-1], bps[1:]):
            mid = np.linspace(lo, hi, 7)[1:-1]
            assert {lib.segment(code, par, m) for m in mid} == {lib.segment(code, par, lo)}
    model = load("one_dof")
    stops = stop_times(model, model.parameter_vector({}), {"H": turn}, 0.0, 2 * P)
    assert set(turn.breakpoints_between(0.0, 2 * P)) <= set(stops.tolist())


def test_compose_errors_name_the_argument():
    with pytest.raises(CamdynInputError, match="must sum to 360"):
        laws.compose("cycloidal", None, (90, 90, 90, 80))
    with pytest.raises(CamdynInputError, match=r"turn angle \(return\)=0 is out of range"):
        laws.compose("cycloidal", None, (180, 90, 0, 90))
    with pytest.raises(CamdynInputError, match="four values"):
        laws.compose("cycloidal", None, (180, 180))
    with pytest.raises(CamdynInputError, match="unknown cam law"):
        laws.compose("cycloidal", "sine", (90, 90, 90, 90))


def test_cam_profile_turn_is_the_profile_motion():
    """CamProfile.turn drives a model with the motion the profile command cuts: its H^(k)
    times stroke/beta^k equals the profile's displacement S^(k)(phi), to 1e-12."""
    from camdyn.runtime.cam.profile import CamProfile

    cam = CamProfile(0.02, 0.05, 0.01, angles_deg=(120, 30, 150, 60), law="modified-sine",
                     law_parameter=0.12)
    beta = math.radians(120)
    phi = np.linspace(0, 2 * np.pi, 721, endpoint=False)
    S = cam.cam.displacement(phi)
    H = cam.turn.evaluate(phi / beta)
    for k in range(4):
        np.testing.assert_allclose(0.02 * H[:, k] / beta**k, S[k], rtol=1e-12,
                                   atol=1e-12 * np.abs(S[k]).max())


def test_turn_through_events_in_a_dynacam_model():
    """A DYNACAM model's input H(B) with B = (beta - beta_0)/beta_m follows the cam angle, a
    state, so segments change by events (seg += 1).  Over 2.5 turns every breakpoint crossed
    is one event, and the input the model used, H = x/h_m - U (outputs (6.17), (3.4)), is the
    turn's H at the B reached, to 1e-12; up to the return the run equals the plain rise's."""
    m = "dynacam_radial_ideal_rigidgear_bilateral"
    turn = laws.compose("cycloidal", "modified-sine", (25, 95, 40, 200), ret_theta=0.15)
    params = load(m).manifest["parameters"]
    h_m = next(p["default"] for p in params if p["name"] == "h_m")
    w = next(p["default"] for p in params if p["name"] == "omega_s")
    t_end = 2.5 * 2 * math.pi / w
    r = simulate(m, {}, t_end, "dp54", rtol=1e-9, law=turn)
    B = r["B"]
    assert B.max() > 2.4 * turn.period
    np.testing.assert_allclose(r["x"] / h_m - r["U"], turn.evaluate(B)[:, 0], rtol=0, atol=1e-12)
    assert r.stats["n_events"] == len(turn.breakpoints_between(0.0, B.max()))
    plain = simulate(m, {}, t_end, "dp54", rtol=1e-9, law="cycloidal")
    upto = B < 1 + turn.up
    n = int(upto.sum())
    np.testing.assert_allclose(r.y[:n], plain.y[:n], rtol=0, atol=1e-12)


def test_cli_integrate_turn(tmp_path):
    """`camdyn integrate one_dof --turn`: the final state equals the library's run with the
    same Turn (1e-12); bad angles and --return-law without --turn are one line, status 2."""
    import json
    import subprocess
    import sys

    def camdyn(*args):
        return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                              capture_output=True, text=True)

    p = camdyn("integrate", "one_dof", "--t-end", "6", "--law", "3-4-5", "--turn",
               "90,45,90,135", "--return-law", "cycloidal", "--no-error-estimate", "--json")
    assert p.returncode == 0, p.stderr
    got = json.loads(p.stdout)["state"]
    turn = laws.compose("3-4-5", "cycloidal", (90, 45, 90, 135))
    r = simulate("one_dof", {}, 6.0, "dp54", rtol=1e-8, law=turn)
    assert got["X"] == pytest.approx(float(r.y[-1, 0]), rel=1e-12)
    for bad in (["--turn", "90,90,90"], ["--turn", "90,x,90,180"], ["--return-law", "cycloidal"]):
        p = camdyn("integrate", "one_dof", "--t-end", "2", *bad)
        assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, (bad, p.stderr)


def test_cli_integrate_return_theta(capsys):
    """--return-theta sets the return law's shape parameter (it could not be set: --theta
    went to the rise law only): the final state equals the library's run with that Turn
    (1e-12) and differs from the run at the law's default (T = 7, in the lower dwell after
    the second return: the residual vibration depends on the law).  Without --return-law (the
    return then is the rise law with its theta) or without --turn it is refused."""
    import json

    from camdyn.runtime.cli import main

    argv = ["integrate", "one_dof", "--t-end", "7", "--turn", "90,45,90,135", "--return-law",
            "modified-sine", "--no-error-estimate", "--json"]
    assert main(argv + ["--return-theta", "0.3"]) == 0
    got = json.loads(capsys.readouterr().out)["state"]["X"]
    want = simulate("one_dof", {}, 7.0, "dp54", rtol=1e-8,
                    law=laws.compose("cycloidal", "modified-sine", (90, 45, 90, 135), None, 0.3))
    default = simulate("one_dof", {}, 7.0, "dp54", rtol=1e-8,
                       law=laws.compose("cycloidal", "modified-sine", (90, 45, 90, 135)))
    assert got == pytest.approx(float(want.y[-1, 0]), rel=1e-12)
    assert abs(got - float(default.y[-1, 0])) > 1e-6
    with pytest.raises(CamdynInputError, match="return law of its own"):
        laws.compose("modified-sine", None, (90, 90, 90, 90), 0.2, 0.3)
    for bad, word in ((["--turn", "90,90,90,90", "--return-theta", "0.3"], "return"),
                      (["--return-theta", "0.3"], "--return-theta")):
        assert main(["integrate", "one_dof", "--t-end", "2", *bad]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and word in err, err


def test_cli_turn_needs_a_cam_input(capsys):
    """pendulum_xy has no cam input: --turn ran it unchanged; now one line naming --turn."""
    from camdyn.runtime.cli import main

    assert main(["integrate", "pendulum_xy", "--t-end", "1", "--turn", "90,90,90,90"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--turn" in err and "pendulum_xy" in err, err
