"""The answer contract's own pieces (runtime/measure/contract.py), against independent
computations: the error of a quotient against a dense scan of the error box, the warning for
a figure its estimate does not resolve, a chart's footnote."""
import itertools

import numpy as np
import pytest

from camdyn.runtime.measure import contract


@pytest.mark.parametrize("a, ea, b, eb", [(0.0257, 0.0096, 0.0064, 0.0054),
                                          (16.0, 0.1, 2.0, 0.05), (-3.0, 0.5, 1.5, 0.2),
                                          (2.0, 0.0, -4.0, 1.0)])
def test_quotient_error_is_the_largest_distance_over_the_box(a, ea, b, eb):
    """Against 201 x 201 points of [a - ea, a + ea] x [b - eb, b + eb]: the largest |q - a/b|
    equals the corners' (a/b is monotonic in each argument while b keeps its sign), to
    1e-12 relative."""
    r, e = contract.quotient(a, ea, b, eb)
    A, B = np.meshgrid(np.linspace(a - ea, a + ea, 201), np.linspace(b - eb, b + eb, 201))
    assert r == a / b
    assert e == pytest.approx(np.max(np.abs(A / B - a / b)), rel=1e-12)


def test_the_coarse_study_ratio_covers_the_answer():
    """camdyn run at rtol 1e-2: U0(Fa = 2) = 0.02567 ± 0.0096, U0(Fa = 0) = 0.006416 ± 0.0054
    (the report's figures); the ratio 4.0 carries an error that covers the answer 16.88
    (U0 at rtol 1e-9: 0.0160644/0.000951783); first-order propagation gave 4 ± 4.9."""
    r, e = contract.quotient(0.02567, 0.0096, 0.006416, 0.0054)
    assert r == pytest.approx(4.0, abs=0.01)
    assert abs(0.0160644 / 0.000951783 - r) <= e
    assert contract.quotient(1.0, 0.1, 0.01, 0.01)[1] == float("inf")


def test_a_figure_its_estimate_does_not_resolve_warns():
    """Above half of |figure| (+ its scale) the estimate leaves the figure unknown to a factor
    of two: a warning naming it; below, or for a state judged against its scale, none."""
    w = contract.unresolved({"U0": 0.0064, "U0dd": 11.3, "X": 1e-8},
                            {"U0": 0.0054, "U0dd": 1.0, "X": 3e-8}, {"X": 1.0})
    assert len(w) == 1 and w[0].startswith("U0 = 0.0064 ± 0.0054")
    assert contract.unresolved({"X": 1e-8}, {"X": 3e-8}) != []
    assert contract.unresolved({"U0": 0.0064}, {"U0": None}) == []


def test_chart_note_states_the_largest_estimate_and_the_warnings():
    values, errors = np.array([1e-3, 2e-3, 4e-3]), np.array([1e-10, 3e-10, 1e-10])
    note = contract.chart_note({"U0": (values, errors)}, ["", "x", ""], points=3)
    assert "U0 ± up to 3e-10 (7.5e-08 of its largest |value|)" in note
    assert "1 of 3 points warned" in note
    note = contract.chart_note({"U0": (values, [1e-10, None, 1e-10])}, [])
    assert "U0: no error estimate at some points" in note and "no warnings" in note
    one = contract.chart_note({"tip": (0.02, 1e-12)}, ["a", "b"])
    assert "tip ± 1e-12 (5e-11 relative)" in one and one.endswith("2 warnings: a")


def test_a_failed_estimate_leaves_the_answer_with_its_reason():
    """The run one notch tighter fails (a step budget, a collapse): the figures stand, their
    estimates are None and a warning says why; the command does not fail."""
    from camdyn.runtime.core.errors import SimulationError
    from camdyn.runtime.core.methods import make
    from camdyn.runtime.targets.base import Figure, Outcome, Target

    class Twin(Target):
        name, kind = "twin", "test"

        def __init__(self, tight=False):
            self.tight = tight

        def figures(self):
            return (Figure("U0"),)

        def method(self):
            return make("dp54", rtol=1e-6)

        def window(self):
            return None

        def tighter(self):
            return Twin(tight=True)

        def run(self, progress=None):
            if self.tight:
                raise SimulationError("twin with dp54: the step budget (max_steps) was used up")
            return Outcome({"U0": 0.25}, record={"U0": 0.25})

    a = contract.answer(Twin())
    assert a.figures == {"U0": 0.25} and a.errors == {"U0": None}
    (w,) = a.warnings
    assert w.startswith("estimate unavailable: the run one notch tighter failed (twin with dp54: "
                        "the step budget")
    assert a.as_dict()["U0_error"] is None
    assert a.as_dict()["estimate_unavailable"].startswith("the run one notch tighter failed")
