"""Generated code: equal to the symbolic equations, deterministic, never stale."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import jinja2
import numpy as np
import pytest
import sympy as sp

from camdyn.derive import camlaws, codegen, generate
from camdyn.derive.lagrange import derive
from camdyn.derive.model import CamFunction
from camdyn.derive.models import REGISTRY
from camdyn.runtime import _integrate
from camdyn.runtime import laws as rt_laws
from camdyn.runtime.models import load

ROOT = Path(__file__).resolve().parents[1]


def _lambdified(model_name: str, law_key: str, par):
    """dy/dt and outputs of a model by plain lambdify of the derived equations, the cam
    input replaced by the law's sympy Piecewise."""
    model = REGISTRY[model_name]()
    eq = derive(model)
    t = model.time
    law = camlaws.LAWS[law_key]
    lsub = {camlaws.theta: par} if law.parameter else {}

    def plain(e):
        e = sp.sympify(e)
        for a in sorted(e.atoms(CamFunction), key=sp.srepr):
            e = e.subs(a, law.piecewise(a.order, a.args[0]).subs(lsub))
        return e

    q, z = model.q, model.z
    qs = [sp.Symbol(f"q{i}") for i in range(len(q))]
    vs = [sp.Symbol(f"v{i}") for i in range(len(q))]
    zs = [sp.Symbol(f"z{i}") for i in range(len(z))]
    acc = eq.M.LUsolve(eq.f).applyfunc(plain) if q else sp.Matrix([])

    def to_syms(e):
        e = plain(e)
        e = e.subs({x.diff(t, 2): acc[i] for i, x in enumerate(q)})
        e = e.subs({x.diff(t): vs[i] for i, x in enumerate(q)})
        e = e.subs({zi.diff(t): plain(st.rate) for zi, st in zip(z, model.first_order)})
        return e.subs({x: qs[i] for i, x in enumerate(q)} | {zi: zs[i] for i, zi in enumerate(z)})

    params = [p.symbol for p in model.parameters]
    args = [t, *qs, *vs, *zs, *params]  # in the order of the state vector
    dy = [*vs, *[to_syms(a) for a in acc], *[to_syms(st.rate) for st in model.first_order]]
    f_dy = sp.lambdify(args, dy, "numpy")
    f_out = sp.lambdify(args, [to_syms(o.expr) for o in model.outputs], "numpy")
    return f_dy, f_out, model


@pytest.mark.parametrize("model_name", sorted(REGISTRY))
@pytest.mark.parametrize("law_key", sorted(camlaws.LAWS))
def test_generated_equals_lambdify(model_name, law_key, rng):
    """rhs and outputs of the compiled module equal lambdify of the same equations at
    random states, times and parameters, to 1e-12 relative."""
    par = float(rng.uniform(0.05, 0.45)) if camlaws.LAWS[law_key].parameter else None
    f_dy, f_out, model = _lambdified(model_name, law_key, par)
    cm = load(model_name)
    choice = rt_laws.choose(law_key, par)
    codes = np.array([choice.code], dtype=np.intc)
    pars = np.array([choice.par])
    n = 200
    ns = len(cm.state_names)
    t = rng.uniform(-0.3, 2.0, n)
    H = choice.evaluate(t)[:, 0]
    # positions kept away from H, so that H - X is not a cancellation
    Y = rng.uniform(-3, 3, (n, ns))
    nq = len(model.coordinates)
    Y[:, :nq] = H[:, None] + rng.choice([-1, 1], (n, nq)) * rng.uniform(1e-2, 1.0, (n, nq))
    got_dy, ref_dy, got_out, ref_out = [], [], [], []
    for k in range(n):
        pvals = {}
        for spec in model.parameters:
            hi = min(spec.high, 0.95 if spec.name == "tau" else 3.0)
            pvals[spec.name] = float(rng.uniform(max(spec.low, 0.0) + 0.02, hi - 0.02))
        p = cm.parameter_vector(pvals)
        y = Y[k:k + 1]
        tk = t[k:k + 1].copy()
        got_dy.append(_integrate.eval_rhs(cm.capsule, p, codes, pars, tk, y)[0])
        got_out.append(_integrate.eval_outputs(cm.capsule, p, codes, pars, tk, y)[0])
        args = [t[k], *Y[k], *p]
        ref_dy.append(np.array(f_dy(*args), dtype=float))
        ref_out.append(np.array(f_out(*args), dtype=float))
    # relative to each quantity's scale over the sample: where a result is a small
    # difference of large terms (H' of a polynomial law near T = 1), both evaluations
    # carry the rounding of the terms, not of the result
    for got, ref in ((np.array(got_dy), np.array(ref_dy)), (np.array(got_out), np.array(ref_out))):
        scale = np.abs(ref).max(axis=0)
        assert np.all(np.abs(got - ref) <= 1e-12 * scale), np.max(np.abs(got - ref) / scale)


def test_derive_check_passes_on_this_checkout():
    """`camdyn derive --check` regenerates in memory and finds generated/ up to date."""
    proc = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "derive", "--check"],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr


def test_regeneration_is_byte_identical_under_another_hash_seed(tmp_path):
    """Same model, other PYTHONHASHSEED: the same bytes (no set-order leaks into the files)."""
    env = dict(os.environ, PYTHONHASHSEED="12345")
    proc = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "derive", "--out", str(tmp_path)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stderr
    for f in sorted((ROOT / "generated").glob("*.py[xd]")):
        assert (tmp_path / f.name).read_bytes() == f.read_bytes(), f.name


def test_check_reports_stale_missing_and_extra_files(tmp_path):
    out = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", out, ignore=shutil.ignore_patterns("*.so", "*.c", "__pycache__"))
    assert generate.check(out) == []
    f = out / "camshaft1.pyx"
    f.write_text(f.read_text().replace("(2.0*M_PI", "(3.0*M_PI", 1) + "\n")
    (out / "one_dof.pyx").unlink()
    (out / "orphan.pyx").write_text("# not from any model\n")
    problems = generate.check(out)
    assert "stale: camshaft1.pyx" in problems
    assert "missing: one_dof.pyx" in problems
    assert "not generated by any model: orphan.pyx" in problems
    # writing repairs it and removes the orphan
    generate.write(out)
    assert generate.check(out) == []
    assert not (out / "orphan.pyx").exists()


def test_templates_are_strict():
    env = codegen._env()
    with pytest.raises(jinja2.UndefinedError):
        env.get_template("model.pyx.j2").render(name="x")


def test_generated_files_say_so_and_carry_the_hash():
    for name in REGISTRY:
        text = (ROOT / "generated" / f"{name}.pyx").read_text()
        assert "GENERATED FILE - DO NOT EDIT" in text
        manifest = load(name).manifest
        assert manifest["source_hash"].startswith("sha256:")
        assert f"Source hash: {manifest['source_hash']}" in text


def test_manifest_describes_the_model():
    m = load("camshaft1").manifest
    assert [s["name"] for s in m["states"]] == ["X", "Xd"]
    assert [p["name"] for p in m["parameters"]] == ["tau", "Fa"]
    assert {o["name"] for o in m["outputs"]} >= {"Xdd", "U", "H", "Hd", "Hdd", "c_rel"}
    assert m["cam_instances"] == [{"argument": "T", "family": "H", "time_affine": True}]
    assert m["parameters"][1]["range"] == "0 <= Fa <= 100"
    assert m["time"] == {"name": "T", "unit": "t_m"}


def test_common_subexpressions_are_shared():
    """The stiffness denominator 1 + Fa H'^2 is computed once in CAMSHAFT-1's rhs, the
    parameter-only factor (2 pi/tau)^2 once per run in prepare(), and the dwell variant
    has no division left."""
    text = (ROOT / "generated" / "camshaft1.pyx").read_text()
    rhs = text.split("cdef inline void rhs")[1].split("cdef void outputs")[0]
    general, dwell = rhs.split("if _v == 0:")[1].split("elif _v == 1:")
    assert general.count("Fa*") == 1
    assert "tau" not in general and "tau" not in dwell
    assert "/" not in dwell
    prepare = text.split("cdef void prepare")[1].split("cdef inline void rhs")[0]
    assert "(tau*tau)" in prepare
