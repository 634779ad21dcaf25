"""User models guarded before and while they run (README "Any model on demand").

A mass matrix that is not positive definite gave a number with exit 0 (a negative mass
integrated to x = -5.3e14) or a misleading reason (a zero mass that the declared range
admits: "the step size fell below the resolution of the time axis"); initial values off a
constraint were kept for ever in the partitioned formulation; dependent constraints were
derived without a word.  Each case here against what it must give, from the model's own
physics:

* the README's oscillator (m x'' = c (H - x) - d x') with m = -1 or m = 0: refused before a
  step, naming M[x, x] (exit 2);
* a mass m (3/2 - t) that reaches zero at t = 3/2: the run stops there (exit 1), naming it
  (the step collapses first, while M is 1e-14: a pivot below 1e-10 of its value at the
  start counts as singular);
* a potential with (1 - x)^(3/2), whose force is not real once the follower overshoots x = 1:
  the run stops naming the non-finite component and the state, x > 1 (exit 1);
* the pendulum (pendulum_xy) released from x = 0.5 with y left at -L cos(theta0): the run
  starts from y = -(L^2 - x^2)^(1/2), says so, in both formulations, and follows the exact
  pendulum from there (energy conserved to 1e-8), in every formulation;
* two constraints where one is the other doubled: refused when the model is derived;
* a dependent coordinate the constraints do not involve, or one that is not a coordinate:
  refused when the model is declared or derived, naming it.
"""
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parent.parent / "README.md"


def oscillator() -> str:
    text = README.read_text()
    return re.search(r"<!-- user-model: oscillator\.py -->\s*```python\n(.*?)```", text,
                     re.S).group(1)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("guards")


def camdyn(folder, *args):
    env = {**os.environ, "CAMDYN_CACHE_DIR": str(folder / "cache")}
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True, timeout=600, env=env, cwd=folder)


def model_file(folder, name, text) -> str:
    path = folder / f"{name}.py"
    path.write_text(text)
    return str(path)


MASS = 'm = Parameter("m", 1.0, "kg", "mass")'


@pytest.mark.parametrize("declaration, value, words", [
    ('m = Parameter("m", -1.0, "kg", "mass")', None, "M[x, x] = -1 is not positive"),
    ('m = Parameter("m", 1.0, "kg", "mass", low=0.0)', "0", "M[x, x] = 0: the coordinate has "
     "no inertia"),
])
def test_a_mass_matrix_that_is_not_positive_definite_is_refused(folder, declaration, value,
                                                                words):
    path = model_file(folder, f"mass{abs(hash(declaration)) % 1000}",
                      oscillator().replace(MASS, declaration))
    for method in (["--method", "dp54"], ["--method", "rk4", "--step", "0.01"]):
        args = ["integrate", path, "--t-end", "3", *method]
        if value is not None:
            args += ["--set", f"m={value}"]
        p = camdyn(folder, *args)
        assert p.returncode == 2 and p.stdout == "", p.stderr
        last = p.stderr.strip().splitlines()[-1]
        assert last.startswith("camdyn integrate: error: oscillator: the mass matrix is not "
                               "positive definite at t = 0") and words in last, last


def test_a_mass_that_stops_being_positive_stops_the_run_there(folder):
    """M = m (3/2 - t): zero at t = 3/2; the run fails (exit 1) just before it."""
    text = oscillator().replace("kinetic=m.symbol * X.diff(t) ** 2 / 2",
                                "kinetic=m.symbol * (sp.Rational(3, 2) - t) * X.diff(t) ** 2 / 2")
    text = text.replace("from camdyn.derive.model import", "import sympy as sp\nfrom "
                        "camdyn.derive.model import")
    p = camdyn(folder, "integrate", model_file(folder, "fading", text), "--t-end", "3")
    assert p.returncode == 1, p.stderr
    last = p.stderr.strip().splitlines()[-1]
    assert "run failed: oscillator with dp54: the mass matrix becomes singular at t = " in last
    assert "M[x, x] = " in last and "against 1.5 at the start" in last
    t = float(re.search(r"at t = ([0-9.e+-]+)", last).group(1))
    assert 1.49 <= t <= 1.5, last


def test_a_right_hand_side_that_is_not_finite_names_the_state_that_made_it(folder):
    """V = c (H - x)^2/2 + c (1 - x)^(3/2): its force is not real for x > 1, which the
    follower reaches when it overshoots the rise's end (the README's oscillator overshoots:
    its closed-form response exceeds 1 after t = 1)."""
    text = oscillator().replace("potential=c.symbol * (h - X) ** 2 / 2",
                                "potential=c.symbol * (h - X) ** 2 / 2 + c.symbol * (1 - X) ** "
                                "sp.Rational(3, 2)")
    text = text.replace("from camdyn.derive.model import", "import sympy as sp\nfrom "
                        "camdyn.derive.model import")
    p = camdyn(folder, "integrate", model_file(folder, "unreal", text), "--t-end", "3")
    assert p.returncode == 1, p.stderr
    last = p.stderr.strip().splitlines()[-1]
    assert "the right-hand side is not finite at t = " in last and "dxd/dt = nan" in last
    x = float(re.search(r"with the state x = ([0-9.e+-]+)", last).group(1))
    assert x > 1.0, last


@pytest.mark.parametrize("formulation", ["0", "1", "2"])
def test_initial_values_off_the_constraint_start_on_it(folder, formulation):
    """The pendulum of length 1 with x(0) = 0.5 and y(0) left at -cos(1): y is recovered,
    y = -(1 - 0.25)^(1/2), the run says so in a warning, and its energy stays that of the
    consistent state to 1e-8 (the bob released at rest from x = 0.5: E = -g (3/4)^(1/2))."""
    p = camdyn(folder, "integrate", "pendulum_xy", "--t-end", "2", "--initial", "x=0.5",
               "--set", f"formulation={formulation}", "--rtol", "1e-10", "--json",
               "--out", str(folder / f"pend{formulation}"))
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    (w,) = out["warnings"]
    assert w.startswith("the initial state violated the constraints (|Phi| = 0.458")
    assert f"y = {-math.sqrt(0.75):.6g}" in w
    rows = (folder / f"pend{formulation}" / "pendulum_xy.csv").read_text().splitlines()
    head = rows[0].split(",")
    first = dict(zip(head, map(float, rows[1].split(","))))
    assert first["y"] == pytest.approx(-math.sqrt(0.75), abs=1e-12)
    E = [float(r.split(",")[head.index("E")]) for r in rows[1:]]
    assert max(abs(e + 9.81 * math.sqrt(0.75)) for e in E) < 1e-8 * 9.81


def test_dependent_constraints_are_refused_when_derived():
    """A bob in space (x, y, z) on a rod, with the rod's constraint declared twice (the second
    doubled): Phi_q has rank 1 where 2 are declared, refused with that rank."""
    import sympy as sp

    from camdyn.derive.lagrange import derive
    from camdyn.derive.model import (Constraint, ConstraintSolver, Coordinate, Model, Parameter,
                                     time)

    t = time("t")
    m, L = (Parameter("m", 1.0, "kg", "bob", low=0.0, open_low=True),
            Parameter("L", 1.0, "m", "rod", low=0.0, open_low=True))
    w, form = (Parameter("w_B", 10.0, "rad/s", "Baumgarte rate", low=0.0),
               Parameter("formulation", 0.0, "1", "formulation", low=0.0, high=1.0))
    q = [Coordinate(n, "m", n, initial=v) for n, v in (("x", 0.0), ("y", 0.0), ("z", -1.0))]
    x, y, z = (c(t) for c in q)
    rod = x**2 + y**2 + z**2 - L.symbol**2
    model = Model(name="bob3", title="bob", reference="test", doc="", time=t, time_unit="s",
                  coordinates=tuple(q),
                  kinetic=m.symbol * sum(c.diff(t) ** 2 for c in (x, y, z)) / 2,
                  potential=sp.Integer(0), parameters=(m, L, w, form), outputs=(),
                  constraints=(Constraint("rod", rod, "lam1", "N/m", "rod"),
                               Constraint("rod2", 2 * rod, "lam2", "N/m", "rod again")),
                  solver=ConstraintSolver(baumgarte_rate=w.symbol, formulation=form.symbol))
    with pytest.raises(ValueError, match="dependent or contradict each other .* rank 1 "):
        derive(model)


def _plane_bob(dependent):
    """A bob in a plane on a rod (x, y) with a third coordinate u that the rod does not involve
    (a free mass on a spring), its dependent coordinate chosen by ``dependent``."""
    import sympy as sp

    from camdyn.derive.model import (Constraint, ConstraintSolver, Coordinate, Model, Parameter,
                                     time)

    t = time("t")
    m = Parameter("m", 1.0, "kg", "bob", low=0.0, open_low=True)
    w, form = (Parameter("w_B", 10.0, "rad/s", "Baumgarte rate", low=0.0),
               Parameter("formulation", 0.0, "1", "formulation", low=0.0, high=2.0))
    q = [Coordinate(n, "m", n, initial=v) for n, v in (("x", 0.0), ("y", -1.0), ("u", 0.0))]
    x, y, u = (c(t) for c in q)
    return Model(name="bob_u", title="bob", reference="test", doc="", time=t, time_unit="s",
                 coordinates=tuple(q),
                 kinetic=m.symbol * sum(c.diff(t) ** 2 for c in (x, y, u)) / 2,
                 potential=u**2 / 2, parameters=(m, w, form), outputs=(),
                 constraints=(Constraint("rod", x**2 + y**2 - 1, "lam", "N/m", "rod"),),
                 solver=ConstraintSolver(baumgarte_rate=w.symbol, formulation=form.symbol,
                                         dependent=dependent))


def test_a_dependent_coordinate_the_constraints_cannot_fix_is_refused():
    """u as the dependent coordinate: Phi_u = 0, so the constraint cannot be solved for it;
    refused when derived, naming u.  A name that is no coordinate: refused when declared."""
    from camdyn.derive.dae import constrained_context
    from camdyn.derive.lagrange import derive

    with pytest.raises(ValueError, match=r"cannot be solved for the dependent coordinates u "):
        constrained_context(derive(_plane_bob(("u",))))
    with pytest.raises(ValueError, match=r"dependent=\('z',\) must name 1 distinct "
                                         r"coordinates among x, y, u"):
        _plane_bob(("z",))
    assert constrained_context(derive(_plane_bob(("x",))))["dependent"] == [0]
