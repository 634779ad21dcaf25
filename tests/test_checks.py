"""The registry behind `camdyn check`: every comparison with the thesis must pass.

Each check carries its thesis reference and tolerance (camdyn/thesis/checks/);
printed values shown to be misprints pass only while they are *not* reproduced.
"""
import json
import subprocess
import sys

import pytest

from camdyn.thesis.checks import check as checks
from camdyn.thesis.checks import suite

REGISTRY = suite.registry()


@pytest.mark.parametrize("check", REGISTRY, ids=[c.key for c in REGISTRY])
def test_check(check):
    outcome = checks.run(check)
    assert not outcome.error, outcome.error
    assert outcome.passed, (f"{check.item} ({check.reference}): printed {check.printed}, "
                            f"derived {outcome.derived}, rule {check.rule}")


def test_matches_printed_rounding_and_truncation():
    assert checks.matches_printed(39.478, "39.4")      # truncated, as the thesis does
    assert checks.matches_printed(39.46, "39.5")       # rounded
    assert not checks.matches_printed(39.6, "39.4")
    assert checks.matches_printed(-21.23, "-21.2")
    assert checks.matches_printed(3.7542e-4, "3.75e-4")
    assert not checks.matches_printed(3.7155e-4, "3.75e-4")


def test_an_estimate_wider_than_the_band_is_flagged():
    """The estimate is |v - v'| with v' computed inside tightened(): a value that moves by more
    than the band its rule accepts when the runs are tightened is not resolved by them."""
    from camdyn.runtime.core import methods

    moving = checks.Check("x", "x", "x", "2", lambda: 2.0 + 0.5 * methods.notches(),
                          rule="rel:0.1")
    out = checks.run(moving, estimate=True)
    assert out.passed and out.estimate == pytest.approx(0.5) and out.wide
    still = checks.Check("x", "x", "x", "2", lambda: 2.0 + 0.01 * methods.notches(),
                         rule="rel:0.1")
    out = checks.run(still, estimate=True)
    assert out.estimate == pytest.approx(0.01) and not out.wide
    exact = checks.Check("x", "x", "x", "2", lambda: 2.0 + methods.notches(), exact=True)
    assert checks.run(exact, estimate=True).estimate == 0.0
    assert checks.run(still).estimate is None


def test_an_estimate_that_cannot_be_made_says_why(capsys):
    """A value whose tighter run fails keeps its value; the estimate is None and the reason
    is carried to the JSON and to a warning under the table."""
    from camdyn.runtime.cli import check as cli_check
    from camdyn.runtime.core import methods

    def value():
        if methods.notches():
            raise RuntimeError("max_steps=10 reached at T = 0.25\nsecond line")
        return 2.0

    c = checks.Check("fails-tighter", "x", "x", "2", value, rule="rel:0.1")
    out = checks.run(c, estimate=True)
    assert out.passed and out.estimate is None
    assert out.estimate_why == "max_steps=10 reached at T = 0.25"
    assert out.as_dict()["estimate_unavailable"] == "max_steps=10 reached at T = 0.25"
    assert "estimate_unavailable" not in checks.run(c).as_dict()
    cli_check._print_table([out])
    text = capsys.readouterr().out
    assert "2 (estimate unavailable)" in text
    assert ("warning fails-tighter: estimate unavailable: max_steps=10 reached at T = 0.25; "
            "the figures are the run's, without an error estimate") in text


def test_rules():
    c = checks.Check("x", "x", "x", "2", lambda: 2.1, rule="rel:0.1")
    assert checks.run(c).passed
    c = checks.Check("x", "x", "x", "2", lambda: 4.5, rule="factor:2")
    assert not checks.run(c).passed
    c = checks.Check("x", "x", "x", "2", lambda: float("nan"), rule="rel:0.1")
    assert not checks.run(c).passed
    c = checks.Check("x", "x", "x", "2", lambda: 1 / 0)
    out = checks.run(c)
    assert not out.passed and "ZeroDivisionError" in out.error


ERRATA = [c for c in REGISTRY if c.errata]


def test_errata_state_their_derived_value():
    """Every errata check carries the value the thesis's own formulas give and a tolerance; a
    check without them, or whose derived value would itself reproduce the misprint, is refused."""
    assert len(ERRATA) == 7
    for c in ERRATA:
        assert c.expected is not None and c.expected_rule.startswith("rel:")
        assert float(c.expected_rule.partition(":")[2]) <= 1e-5
    with pytest.raises(ValueError, match="expected"):
        checks.Check("x", "x", "x", "2", lambda: 3.0, errata=True)
    with pytest.raises(ValueError, match="reproduce the misprint"):
        checks.Check("x", "x", "x", "2", lambda: 3.0, errata=True, expected="2.04",
                     expected_rule="rel:1e-6", rule="rel:0.05")


@pytest.mark.parametrize("check", ERRATA, ids=[c.key for c in ERRATA])
def test_errata_cannot_pass_by_accident(check):
    """An errata check passes for its derived value only: NaN, infinity, zero, a value ten times
    off, one just outside the derived value's tolerance and the misprint itself all fail."""
    from dataclasses import replace

    expected = float(check.expected)
    tol = float(check.expected_rule.partition(":")[2])
    assert checks.run(replace(check, compute=lambda: expected)).passed
    for wrong in (float("nan"), float("inf"), 0.0, 10 * expected, expected * (1 + 3 * tol),
                  float(check.printed)):
        out = checks.run(replace(check, compute=lambda w=wrong: w))
        assert not out.passed, (check.key, wrong)
        assert out.status.startswith("FAIL")


def test_camdyn_check_command_json_and_exit_code():
    p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "check", "--json", "-k", "table3I"],
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["passed"] and len(out["checks"]) == 10
    assert {c["status"] for c in out["checks"]} == {"pass", "errata"}
    # every derived value leaves with its error estimate; checked against the closed forms
    # (3.5), (3.6) at the tau = 2/(2k + 1) the rows stand for: the true error lies within ten
    # times the estimate (plus the last bits of the closed form)
    from camdyn.runtime.measure import references

    for c in out["checks"]:
        _, fig, k = c["key"].split(".", 2)
        tau = {"0.105": 2 / 19, "0.222": 2 / 9, "0.286": 2 / 7, "0.4": 2 / 5, "0.66": 2 / 3}[k]
        exact = getattr(references, fig)(tau)
        assert 0 < c["derived_error"] < 1e-7 * exact, c["key"]
        assert abs(c["derived"] - exact) <= 10 * c["derived_error"] + 1e-14 * exact, c["key"]
    p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "check", "--topic", "nope"],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and "unknown topic" in p.stderr
