"""Generated code: equal to the symbolic equations, deterministic, never stale."""
import functools
import os
import shutil
import subprocess
import sys
from pathlib import Path

import jinja2
import numpy as np
import pytest
import sympy as sp

from camdyn.derive import camlaws, emit, generate, render
from camdyn.derive.lagrange import derive
from camdyn.derive.model import CamFunction
from camdyn.derive.models import REGISTRY
from camdyn.runtime.engine import driver
from camdyn.runtime.core import laws as rt_laws
from camdyn.runtime.core.compiled import load

ROOT = Path(__file__).resolve().parents[1]


@functools.lru_cache(maxsize=None)
def _model_functions(model_name: str):
    """dy/dt, the outputs and the cam inputs' arguments of a model by plain lambdify of the
    derived equations, each cam value H^(k)(arg) an argument of its own: derived and solved
    once a model, whatever the law."""
    model = REGISTRY[model_name]()
    eq = derive(model)
    t = model.time
    exprs = [*eq.M, *eq.f, *[st.rate for st in model.first_order], *[o.expr for o in model.outputs]]
    atoms = sorted(set().union(*(sp.sympify(e).atoms(CamFunction) for e in exprs)), key=sp.srepr)
    cams = [sp.Symbol(f"cam{j}", real=True) for j in range(len(atoms))]

    def plain(e):
        return sp.sympify(e).xreplace(dict(zip(atoms, cams)))

    q, z = model.q, model.z
    qs = [sp.Symbol(f"q{i}", real=True) for i in range(len(q))]
    vs = [sp.Symbol(f"v{i}", real=True) for i in range(len(q))]
    zs = [sp.Symbol(f"z{i}", real=True) for i in range(len(z))]
    acc = eq.M.applyfunc(plain).LUsolve(eq.f.applyfunc(plain)) if q else sp.Matrix([])

    def to_syms(e):
        e = plain(e)
        e = e.subs({x.diff(t, 2): acc[i] for i, x in enumerate(q)})
        e = e.subs({x.diff(t): vs[i] for i, x in enumerate(q)})
        e = e.subs({zi.diff(t): plain(st.rate) for zi, st in zip(z, model.first_order)})
        return e.subs({x: qs[i] for i, x in enumerate(q)} | {zi: zs[i] for i, zi in enumerate(z)})

    params = [p.symbol for p in model.parameters]
    modes = [m.symbol for m in model.modes]
    args = [t, *qs, *vs, *zs, *params, *modes]  # in the order of the state vector
    dy = [*vs, *[to_syms(a) for a in acc], *[to_syms(st.rate) for st in model.first_order]]
    f_dy = sp.lambdify(args + cams, dy, "math")
    f_out = sp.lambdify(args + cams, [to_syms(o.expr) for o in model.outputs], "math")
    f_arg = [sp.lambdify(args, to_syms(a.args[0]), "math") for a in atoms]
    return f_dy, f_out, f_arg, [a.order for a in atoms], model


def _lambdified(model_name: str, law_key: str, par):
    """dy/dt and outputs of a model by plain lambdify of the derived equations, the cam
    values from the law's sympy Piecewise (derive/camlaws.py, lambdified on its own)."""
    f_dy, f_out, f_arg, orders, model = _model_functions(model_name)
    law = camlaws.LAWS[law_key]
    value = par if law.parameter else None
    H = {k: law.numeric(k, value) for k in set(orders)}

    def cams(args):
        return [float(H[k](g(*args))) for g, k in zip(f_arg, orders)]

    return (lambda *args: f_dy(*args, *cams(args)), lambda *args: f_out(*args, *cams(args)),
            model)


# the constrained models solve an augmented system: tests/test_beam.py and
# tests/test_pendulum_xy.py check them
_CASES = [(m, law) for m in sorted(REGISTRY) if not m.startswith(("dynacam_", "beam", "pendulum"))
          for law in sorted(camlaws.LAWS)]
# the DYNACAM variants are large: one law each, and fewer points (see _POINTS)
# lambdify of the variants with contact modes and squeeze films takes minutes each (the
# nested Piecewise of H(B) inside the solved accelerations); the smooth ones cover the printer
_CASES += [(m, "cycloidal") for m in ("dynacam_radial_ideal_rigidgear_bilateral", "dynacam_radial_ideal_rigidgear_bilateral_shafty_shaftz")]
_POINTS = {"dynacam": 12}


@pytest.mark.parametrize("model_name,law_key", _CASES)
def test_generated_equals_lambdify(model_name, law_key, rng):
    """rhs and outputs of the compiled module equal lambdify of the same equations at
    random states, times and parameters, to 1e-12 relative."""
    par = float(rng.uniform(0.05, 0.45)) if camlaws.LAWS[law_key].parameter else None
    f_dy, f_out, model = _lambdified(model_name, law_key, par)
    cm = load(model_name)
    choice = rt_laws.choose(law_key, par)
    codes = np.array([choice.code], dtype=np.intc)
    pars = np.array([choice.par])
    n = _POINTS.get(model_name.split("_")[0], 200)
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
        # the force elements' modes (contact, stick/slip, ...) drawn at random too
        em = np.array([rng.integers(len(m.values)) for m in model.modes], dtype=np.intc)
        y = Y[k:k + 1]
        tk = t[k:k + 1].copy()
        got_dy.append(driver.eval_rhs(cm.capsule, p, codes, pars, tk, y, element_modes=em)[0])
        got_out.append(driver.eval_outputs(cm.capsule, p, codes, pars, tk, y, element_modes=em)[0])
        args = [t[k], *Y[k], *p, *em]
        ref_dy.append(np.array(f_dy(*args), dtype=float))
        ref_out.append(np.array(f_out(*args), dtype=float))
    # relative to each quantity's scale over the sample: where a result is a small
    # difference of large terms (H' of a polynomial law near T = 1), both evaluations
    # carry the rounding of the terms, not of the result
    for got, ref in ((np.array(got_dy), np.array(ref_dy)), (np.array(got_out), np.array(ref_out))):
        scale = np.abs(ref).max(axis=0)
        assert np.all(np.abs(got - ref) <= 1e-12 * scale), np.max(np.abs(got - ref) / scale)


def test_derive_check_passes_on_this_checkout():
    """`camdyn derive --check` finds generated/ up to date: every file records the derivation
    key of the current declarations and code and is intact (the key-less full comparison is
    `--full`; the tests below show what each catches)."""
    proc = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "derive", "--check"],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr


SMALL = ["camshaft1", "camshaft2", "motor2", "dynacam_radial_ideal_rigidgear_bilateral"]
"""Models cheap enough to regenerate several times in one test run."""


def test_regeneration_is_byte_identical_under_another_hash_seed(tmp_path):
    """Same models, other PYTHONHASHSEED: the same bytes, derivation keys included (no
    set-order leaks into the files or the keys).  The other models are derived under the
    seed of whoever regenerated generated/; bench/derive_seeds.py compares all of them."""
    env = dict(os.environ, PYTHONHASHSEED="12345")
    proc = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "derive", "--out", str(tmp_path),
                           "--only", *SMALL], cwd=ROOT, capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stderr
    for name in ["camlaws.pxd", "camlaws.pyx", "catalog.json"] + [f"{m}.pyx" for m in SMALL]:
        assert (tmp_path / name).read_bytes() == (ROOT / "generated" / name).read_bytes(), name


def _copy_generated(tmp_path, models) -> Path:
    out = tmp_path / "generated"
    out.mkdir()
    for name in ["camlaws.pxd", "camlaws.pyx", "catalog.json"] + [f"{m}.pyx" for m in models]:
        shutil.copyfile(ROOT / "generated" / name, out / name)
    return out


@pytest.fixture
def derived(monkeypatch):
    """Names of the units derived (not merely key-checked) by generate.check/write, which
    run in this process (workers=1) so that the spy and monkeypatched declarations hold."""
    calls = []
    render_model, render_camlaws = render.render_model, render.render_camlaws

    def spy_model(model, source):
        calls.append(model.name)
        return render_model(model, source)

    def spy_camlaws():
        calls.append("camlaws")
        # the same text every time: derived once per test (it takes seconds)
        if not memo:
            memo.append(render_camlaws())
        return dict(memo[0])

    memo = []

    monkeypatch.setattr(render, "render_model", spy_model)
    monkeypatch.setattr(render, "render_camlaws", spy_camlaws)
    return calls


def test_check_trusts_current_files_and_finds_a_hand_edit(tmp_path, derived):
    """Files that record the current key and are intact are not derived again; a hand edit
    anywhere in a file (its body, or its recorded key) changes its text hash, and the check
    derives that file and shows the diff."""
    only = ["camshaft1", "one_dof"]
    out = _copy_generated(tmp_path, only)
    assert generate.check(out, only, workers=1) == []
    assert derived == []
    f = out / "camshaft1.pyx"
    f.write_text(f.read_text().replace("_k0", "_k9", 1))
    problems = generate.check(out, only, workers=1)
    assert problems[0] == "stale: camshaft1.pyx: edited after generation (its text hash differs)"
    assert any(line.strip().startswith("-") and "_k9" in line for line in problems)
    assert derived == ["camshaft1"]
    # a recorded key edited to match other inputs is an edit as well
    key, _ = generate.read_stamp((ROOT / "generated" / "camshaft1.pyx").read_text())
    f.write_text((ROOT / "generated" / "camshaft1.pyx").read_text().replace(key, "sha256:" + "0" * 64))
    assert generate.read_stamp(f.read_text()) == ("sha256:" + "0" * 64, False)
    assert generate.check(out, only, workers=1)[0].startswith("stale: camshaft1.pyx: edited")
    # a file without the stamp (hand-written, or from before the keys)
    lines = (ROOT / "generated" / "one_dof.pyx").read_text().splitlines(keepends=True)
    (out / "one_dof.pyx").write_text("".join(l for l in lines if not l.startswith(
        ("# Derivation key:", "# Text hash:"))))
    assert "stale: one_dof.pyx: no derivation key (written by hand or by an older camdyn)" in \
        generate.check(out, only, workers=1)


def test_check_reports_missing_and_write_repairs(tmp_path):
    only = ["camshaft1", "one_dof"]
    out = _copy_generated(tmp_path, only)
    f = out / "camshaft1.pyx"
    f.write_text(f.read_text().replace("_k0", "_k9", 1))
    (out / "one_dof.pyx").unlink()
    assert generate.check(out, only) == ["missing: one_dof.pyx"]
    assert generate.write(out, only) == ["camshaft1.pyx", "one_dof.pyx"]
    assert generate.check(out, only) == []
    for name in ("camshaft1.pyx", "one_dof.pyx"):
        assert (out / name).read_bytes() == (ROOT / "generated" / name).read_bytes()
    # a check over the whole registry reports the missing files without deriving anything
    (out / "orphan.pyx").write_text("# not from any model\n")
    assert any(p.startswith("missing: dynacam_") for p in generate.check(out))


def test_editing_a_declaration_rederives_that_model_only(tmp_path, derived, monkeypatch):
    """A changed declaration changes its model's key: check reports that file stale, write
    derives it (and nothing else) and records the new key."""
    import dataclasses

    only = ["camshaft1", "one_dof"]
    out = _copy_generated(tmp_path, only)
    build = REGISTRY["camshaft1"]
    monkeypatch.setitem(REGISTRY, "camshaft1", lambda: dataclasses.replace(
        build(), title=build().title + " (edited)"))
    problems = generate.check(out, only, workers=1)
    assert problems[0] == ("stale: camshaft1.pyx: derived from other inputs than the current "
                           "ones (derivation key differs)")
    assert any("(edited)" in line for line in problems)
    assert derived == ["camshaft1"]
    derived.clear()
    assert generate.write(out, only, workers=1) == ["camshaft1.pyx"]
    assert derived == ["camshaft1"]
    derived.clear()
    assert generate.check(out, only, workers=1) == []
    assert derived == []


def test_full_derives_everything_and_sees_what_the_key_does_not(tmp_path, derived, monkeypatch):
    """--full derives every file whatever its key: a change the key cannot see (here the
    printer replaced behind its back) passes the keyed check and fails the full one."""
    only = ["camshaft1"]
    out = _copy_generated(tmp_path, only)
    assert generate.check(out, only, full=True, workers=1) == []
    assert sorted(derived) == ["camlaws", "camshaft1"]
    render_model = render.render_model
    monkeypatch.setattr(render, "render_model", lambda m, s: render_model(m, s).replace("_k0", "_k9"))
    assert generate.check(out, only, workers=1) == []
    assert generate.check(out, only, full=True, workers=1)[0] == (
        "stale: camshaft1.pyx: differs from a fresh derivation of the same inputs")


def test_derivation_key_covers_code_templates_and_declaration(monkeypatch, tmp_path):
    """The key changes with the declaration, its source file, with every file of the derive code that prints
    the model, and with the SymPy version; not with the hash seed (the byte-identity test)."""
    model, here = REGISTRY["camshaft1"](), "camdyn/derive/models/camshaft1.py"
    key = generate.model_key(model, here)
    assert generate.model_key(REGISTRY["camshaft1"](), here) == key
    assert generate.model_key(REGISTRY["one_dof"](), "camdyn/derive/models/one_dof.py") != key
    # the provenance line is part of the text: a declaration moved to another file re-derives
    assert generate.model_key(model, "camdyn/derive/models/other.py") != key
    digest = generate._code_digest("model")
    assert set(digest["code"]) >= {"codegen.py", "lagrange.py", "printer.py", "optimize.py", "model.py",
                                   "templates/model.pyx.j2", "templates/preamble.j2"}
    assert digest["sympy"] == sp.__version__
    assert "dae.py" in generate._code_digest("constrained")["code"]
    assert "camlaws.py" in generate._code_digest("camlaws")["code"]
    derive_dir = tmp_path / "derive"
    shutil.copytree(generate.DERIVE, derive_dir, ignore=shutil.ignore_patterns("__pycache__", "models"))
    (derive_dir / "printer.py").write_text((derive_dir / "printer.py").read_text() + "\n# edited\n")
    monkeypatch.setattr(generate, "DERIVE", derive_dir)
    generate._code_digest.cache_clear()
    try:
        assert generate.model_key(model, here) != key
    finally:
        generate._code_digest.cache_clear()


def test_check_names_files_no_model_generates(tmp_path):
    """A check over the whole registry reports a stray file, and write removes it (all files
    current: nothing is derived, only keyed)."""
    out = tmp_path / "generated"
    shutil.copytree(ROOT / "generated", out, ignore=shutil.ignore_patterns("*.so", "*.c", "__pycache__"))
    (out / "orphan.pyx").write_text("# not from any model\n")
    assert generate.check(out) == ["not generated by any model: orphan.pyx"]
    assert generate.write(out) == ["orphan.pyx (removed)"]
    assert not (out / "orphan.pyx").exists()


def test_templates_are_strict():
    env = emit.environment()
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
    # order: the highest derivative of H its equations and outputs use (the output Hdd)
    assert m["cam_instances"] == [{"argument": "T", "family": "H", "time_affine": True,
                                   "order": 2}]
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


@pytest.mark.parametrize("n", [5, 6, 7, 13, 14, 31, 32, -5, -14])
def test_integer_powers_print_as_squares(n, rng):
    """x^n of a symbol, 4 < |n| <= 32, prints as products of repeated squares (no libm pow) and
    equals x**n to a few units in the last place (independent: Python's float power)."""
    from camdyn.derive.printer import CythonPrinter

    x = sp.Symbol("x")
    code = CythonPrinter().doprint(x ** n)
    assert "pow" not in code
    for v in rng.uniform(0.5, 2.0, 50):
        assert eval(code, {"x": float(v)}) == pytest.approx(float(v) ** n, rel=8 * 2.0 ** -52)


def test_powers_beyond_the_squarings_stay_pow():
    from camdyn.derive.printer import MAX_SQUARING, CythonPrinter

    x, y = sp.symbols("x y")
    assert CythonPrinter().doprint(x ** (MAX_SQUARING + 1)).startswith("pow(")
    # a compound base is not written out several times
    assert CythonPrinter().doprint((x + y) ** 7).startswith("pow(")
