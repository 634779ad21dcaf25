"""Rises shaped by the user (runtime/core/shaped.py, law code SHAPED of the generated library):
blend segments against the library's polynomial laws, B-splines against SciPy's BSpline, a
table against the law it samples, the refusal of a rough table, and runs with them against
runs with the laws they reproduce."""
import json
import pickle
import subprocess
import sys

import numpy as np
import pytest

from camdyn.generated import camlaws as lib
from camdyn.runtime.cli import main
from camdyn.runtime.core import laws, shaped
from camdyn.runtime.core.errors import CamdynInputError

REST = {"H'": 0, "H''": 0}
# right-continuous: at T = 1 a plain law is already in its dwell, so compare on [-0.2, 1)
T = np.linspace(-0.2, 1.0, 601)[:-1]


def _rest(order):
    return {k: 0 for k in shaped.ORDERS[1:order + 1]}


@pytest.mark.parametrize("key,order", [("3-4-5", 2), ("4-5-6-7", 3)])
def test_blend_with_rest_at_both_ends_is_the_polynomial_law(key, order):
    """Rest to H'' (H''') at both ends fixes the degree-5 (7) polynomial: the library's 3-4-5
    (4-5-6-7) law, H = 10 T^3 - 15 T^4 + 6 T^5 (App. 2), to 1e-12 in H .. H'''."""
    rise = shaped.blend([{"T": 0, "H": 0, **_rest(order)}, {"T": 1, "H": 1, **_rest(order)}])
    ref = laws.choose(key).evaluate(T)
    assert np.abs(rise.evaluate(T) - ref).max() < 1e-12 * np.abs(ref).max()
    assert rise.breakpoints() == [0.0, 1.0]
    assert rise.continuity == order


def test_blend_in_two_segments_is_the_parabolic_law():
    """H = 2 T^2, then 1 - 2 (1 - T)^2: the conditions H, H' at T = 0, 1/2, 1 give the
    parabolic law exactly, with its H'' jump at T = 1/2 a segment end."""
    rise = shaped.blend([{"T": 0, "H": 0, "H'": 0}, {"T": 0.5, "H": 0.5, "H'": 2},
                         {"T": 1, "H": 1, "H'": 0}])
    ref = laws.choose("parabolic").evaluate(T)
    assert np.abs(rise.evaluate(T) - ref).max() < 1e-13
    assert rise.breakpoints() == [0.0, 0.5, 1.0]
    assert rise.continuity == 1


def test_match_carries_the_left_segment_on():
    """"match" at an inner point: the right segment starts with the left one's values, so
    H .. H'' are continuous there; the left segment does not depend on what follows."""
    pts = [{"T": 0, "H": 0, **REST}, {"T": 0.3, "H": 0.2, "H'": "match", "H''": "match"},
           {"T": 1, "H": 1, **REST}]
    rise = shaped.blend(pts)
    left = rise.evaluate([0.3 - 1e-9])[0]
    right = rise.evaluate([0.3])[0]
    assert np.allclose(left[:3], right[:3], rtol=0, atol=1e-6)
    # with H' given at 0.3 instead, the first segment changes; with "match" it is the
    # degree-3 polynomial through H(0) = H'(0) = H''(0) = 0 and H(0.3) = 0.2 alone: 0.2 (T/0.3)^3
    x = np.linspace(0.0, 0.29, 30)
    assert np.abs(rise.evaluate(x)[:, 0] - 0.2 * (x / 0.3) ** 3).max() < 1e-14


def test_bspline_equals_scipy():
    """The clamped quintic B-spline through control values 0, 0, 0, 0.2, 0.8, 1, 1, 1 against
    SciPy's BSpline on the same knots, H .. H''' to 1e-12; three equal values at each end
    give H' = H'' = 0 there."""
    from scipy.interpolate import BSpline

    c = np.array([0, 0, 0, 0.2, 0.8, 1, 1, 1.0])
    k = 5
    t = np.r_[np.zeros(k), np.linspace(0, 1, c.size - k + 1), np.ones(k)]
    ref = BSpline(t, c, k)
    rise = shaped.bspline(c, k)
    x = np.linspace(0.0, 1.0, 401)[:-1]
    got = rise.evaluate(x)
    for j in range(4):
        want = ref.derivative(j)(x) if j else ref(x)
        assert np.abs(got[:, j] - want).max() < 1e-12 * max(1.0, np.abs(want).max())
    assert rise.continuity == 2


def _cycloidal_table(n, stroke=0.02, digits=None):
    deg = np.linspace(0.0, 120.0, n)
    lift = laws.choose("cycloidal").evaluate(deg / 120.0)[:, 0] * stroke
    return deg, (lift if digits is None else np.round(lift, digits))


def test_table_reproduces_the_law_it_samples_within_its_estimate():
    """121 points of the cycloidal law (1 deg apart over a 120 deg rise, in mm-like units):
    the quintic spline's H .. H''' against (A.2.8)-(A.2.11), each error below the estimate the
    rise carries (the spline through every second point), and the estimate small."""
    deg, lift = _cycloidal_table(121)
    rise = shaped.table(deg, lift, name="cycloidal.csv")
    x = np.linspace(0.0, 1.0, 2001)[:-1]
    ref = laws.choose("cycloidal").evaluate(x)
    got = rise.evaluate(x)
    for k in range(4):
        err = np.abs(got[:, k] - ref[:, k]).max() / np.abs(ref[:, k]).max()
        assert err <= rise.errors[k], (k, err, rise.errors[k])
    assert rise.errors[2] < 1e-6
    assert rise.breakpoints() == [0.0, 1.0]      # one segment: the spline is C4 inside


def test_a_rough_table_is_refused_by_name():
    """Lifts of a 20 mm rise rounded to 0.01 mm: H'' is not fixed by the table (the two
    splines differ by far more than 1 %), so a model that uses H'' refuses it, naming the
    file and the derivative; a model that uses H only takes it."""
    deg, lift = _cycloidal_table(121, stroke=20.0, digits=2)
    rise = shaped.table(deg, lift, name="rough.csv")
    assert rise.errors[2] > 0.05
    with pytest.raises(CamdynInputError, match=r"rough\.csv: too rough for camshaft1, which uses H''"):
        rise.check_for("camshaft1", 2)
    rise.check_for("a model of H", 0)


@pytest.mark.parametrize("points,message", [
    ([{"T": 0, "H": 0}], "at least two points"),
    ([{"T": 0, "H": 0}, {"T": 0.5, "H": 1}], "rise from 0 to 1"),
    ([{"T": 0, "H": 0}, {"T": 1, "H": 1, "J": 0}], "a point takes T and"),
    ([{"T": 0, "H": 0}, {"T": 1, "H": "x"}], "must be a number or \"match\""),
    ([{"T": 0, "H''": 0}, {"T": 1, "H''": 0}], "do not fix one polynomial"),
    ([{"T": 0, "H": 0, **REST}, {"T": 1, "H": 2, **REST}], "from H = 0 at T = 0 to H = 1"),
])
def test_blend_refusals(points, message):
    with pytest.raises(CamdynInputError, match=message):
        shaped.blend(points)


def test_table_and_file_refusals(tmp_path):
    with pytest.raises(CamdynInputError, match="angles must increase; row 3"):
        shaped.table([0, 1, 1, 2, 3, 4, 5, 6], np.arange(8.0))
    with pytest.raises(CamdynInputError, match="at least 8 points"):
        shaped.table([0, 1, 2], [0, 1, 2])
    with pytest.raises(CamdynInputError, match="not found"):
        laws.choose(str(tmp_path / "missing.csv"))
    bad = tmp_path / "bad.toml"
    bad.write_text("[[point]]\nT = 0\n[bspline]\ncontrol = [0, 1]\n")
    with pytest.raises(CamdynInputError, match="either"):
        laws.choose(str(bad))
    with pytest.raises(CamdynInputError, match="no shape parameter"):
        laws.choose(str(bad), 0.2)


def test_the_library_takes_the_slot_again_in_another_process():
    """A rise sent to another process (a Dask worker) registers itself there on first use."""
    rise = shaped.blend([{"T": 0, "H": 0, **REST}, {"T": 1, "H": 1, **REST}])
    code = ("import pickle, sys, numpy as np; r = pickle.loads(sys.stdin.buffer.read()); "
            "print(repr(float(r.evaluate([0.3])[0, 2])))")
    out = subprocess.run([sys.executable, "-c", code], input=pickle.dumps(rise),
                         capture_output=True, check=True)
    assert float(out.stdout) == pytest.approx(float(rise.evaluate([0.3])[0, 2]), rel=1e-15)


def test_a_turn_takes_a_shaped_rise(tmp_path):
    """compose() with a blend file as the rise: over the rise the turn is the blend, and over
    the return the mirrored blend (H = 1 - H_ret)."""
    f = tmp_path / "rise.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                 '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    turn = laws.compose(str(f), angles_deg=(90, 90, 90, 90))
    ref = laws.compose("3-4-5", angles_deg=(90, 90, 90, 90))
    x = np.linspace(-0.1, 3.9, 801)
    assert np.abs(turn.evaluate(x) - ref.evaluate(x)).max() < 1e-11


def test_runs_with_a_blend_equal_runs_with_the_law(tmp_path, capsys):
    """camdyn residual on CAMSHAFT-1 (tau 0.15, Fa 2): the blend that is the 3-4-5 law gives
    the 3-4-5 law's U0 and U0'' to 1e-9 relative; a 121-point table of the cycloidal law
    gives the cycloidal law's to 1e-6, and its warning says how well the table is known."""
    f = tmp_path / "b345.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                 '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    deg, lift = _cycloidal_table(121)
    csv = tmp_path / "cycloidal.csv"
    csv.write_text("angle_deg,lift_m\n" + "".join(f"{float(a)!r},{float(b)!r}\n" for a, b in zip(deg, lift)))

    def residual(law):
        assert main(["residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                     "--law", law, "--json"]) == 0
        return json.loads(capsys.readouterr().out)

    for mine, theirs, tol in ((str(f), "3-4-5", 1e-9), (str(csv), "cycloidal", 1e-6)):
        a, b = residual(mine), residual(theirs)
        for fig in ("U0", "U0dd"):
            assert a[fig] == pytest.approx(b[fig], rel=tol), (mine, fig)
    assert any("cycloidal.csv: the table fixes H" in w for w in residual(str(csv))["warnings"])


def test_library_slots_are_shared_and_bounded():
    rise = shaped.blend([{"T": 0, "H": 0, **REST}, {"T": 1, "H": 1, **REST}])
    assert rise.par == shaped.blend([{"T": 0, "H": 0, **REST}, {"T": 1, "H": 1, **REST}]).par
    assert lib.SHAPED not in {law["code"] for law in lib.LAWS}


def test_table_files(tmp_path):
    """A whitespace-separated table with a comment and a header reads as the CSV one; a line
    that is not two numbers after the data is refused by its number."""
    deg, lift = _cycloidal_table(41)
    a = tmp_path / "rise.txt"
    a.write_text("# cam of station 3\nangle lift\n" + "".join(f"{float(x)!r} {float(y)!r}\n"
                                                           for x, y in zip(deg, lift)))
    b = tmp_path / "rise.csv"
    b.write_text("".join(f"{float(x)!r},{float(y)!r}\n" for x, y in zip(deg, lift)))
    assert laws.choose(str(a)).coefs == laws.choose(str(b)).coefs
    b.write_text(b.read_text() + "end,of table\n")
    with pytest.raises(CamdynInputError, match="line 42 is not two numbers"):
        laws.choose(str(b))


def test_a_scene_names_a_law_file_beside_it(tmp_path, capsys):
    """The spring_loaded DYNACAM scene with law = "rise.toml" (read beside the scene file, not
    from the working folder) and the blend that is the 3-4-5 law: its figures equal the scene
    with law = "3-4-5" to 1e-9 relative."""
    from camdyn.runtime.targets.scene_files import builtin

    text = builtin("spring_loaded").read_text()
    (tmp_path / "rise.toml").write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                                        '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    mine, theirs = tmp_path / "mine.toml", tmp_path / "theirs.toml"
    mine.write_text(text.replace('law = "cycloidal"', 'law = "rise.toml"'))
    theirs.write_text(text.replace('law = "cycloidal"', 'law = "3-4-5"'))
    out = []
    for scene in (mine, theirs):
        assert main(["simulate", str(scene), "--json"]) == 0
        out.append(json.loads(capsys.readouterr().out))
    for fig in ("U0", "U0dd", "Xdd_min_rise"):
        assert out[0][fig] == pytest.approx(out[1][fig], rel=1e-9), fig


def test_a_profile_of_a_shaped_rise(tmp_path):
    """camdyn profile's cam with the blend that is the 3-4-5 law has the 3-4-5 cam's largest
    pressure angle and least radius of curvature (to 1e-9); a rough table is refused for its
    curvature, naming the file."""
    from camdyn.runtime.cam.profile import CamProfile

    f = tmp_path / "b345.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                 '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    kw = dict(stroke=0.015, base_radius=0.04, roller_radius=0.01)
    a = CamProfile(law=str(f), **kw).summary()
    b = CamProfile(law="3-4-5", **kw).summary()
    for key in ("max_abs_pressure_angle_deg", "min_rho_pitch"):
        assert a[key] == pytest.approx(b[key], rel=1e-9), key
    deg, lift = _cycloidal_table(121, stroke=20.0, digits=2)
    rough = tmp_path / "rough.csv"
    rough.write_text("".join(f"{float(x)!r},{float(y)!r}\n" for x, y in zip(deg, lift)))
    with pytest.raises(CamdynInputError, match="rough.csv: too rough for the cam profile"):
        CamProfile(law=str(rough), **kw).summary()


def test_characteristic_values_of_a_shaped_rise(tmp_path, capsys):
    """camdyn laws --rise: the blend that is the 3-4-5 law has VDI 2143's C_v, C_a, C_j,
    C_Mdyn of the 3-4-5 polynomial (1.875, 5.774, 60, 6.694, and as the App. 2 table derives
    them to 1e-10); the two-segment parabolic blend has no C_j (H'' jumps); a 121-point
    table of the cycloidal law has (A.2.8)-(A.2.11)'s 2, 2 pi, 4 pi^2 within its errors."""
    from camdyn.thesis.theory.lawtable import properties

    f = tmp_path / "b345.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                 '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    assert main(["laws", "--rise", str(f), "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    ref = properties("3-4-5")
    for key, want in (("C_v", ref.H1_max), ("C_a", ref.H2_max), ("C_j", ref.jerk_0),
                      ("C_Mdyn", ref.torque_max)):
        assert got[key]["value"] == pytest.approx(want, rel=1e-10), key
    assert got["C_Mdyn"]["at_T"] == pytest.approx(ref.T_torque_max, abs=1e-9)
    par = shaped.blend([{"T": 0, "H": 0, "H'": 0}, {"T": 0.5, "H": 0.5, "H'": 2},
                        {"T": 1, "H": 1, "H'": 0}]).characteristics()
    assert par["C_a"]["value"] == pytest.approx(4.0, rel=1e-12) and par["C_j"]["value"] is None
    deg, lift = _cycloidal_table(121)
    table = shaped.table(deg, lift).characteristics()
    for key, want in (("C_v", 2.0), ("C_a", 2 * np.pi), ("C_j", 4 * np.pi ** 2)):
        assert abs(table[key]["value"] - want) <= table[key]["error"], key


@pytest.mark.parametrize("extra, flag", [(["--tau", "0.1"], "--tau"), (["--n", "5"], "--n"),
                                         (["--roller-radius", "0.01"], "--roller-radius"),
                                         (["--no-error-estimate"], "--no-error-estimate")])
def test_laws_rise_refuses_the_other_modes_options_by_name(tmp_path, capsys, extra, flag):
    """An option of another mode of `camdyn laws` beside --rise would be dropped unread: one
    line naming it."""
    f = tmp_path / "b345.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n[[point]]\nT = 1\nH = 1\n"H\'" = 0\n')
    assert main(["laws", "--rise", str(f), *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"camdyn laws: error: argument {flag}: not with --rise"
