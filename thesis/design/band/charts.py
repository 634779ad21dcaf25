"""The band design's pictures (matplotlib, Agg), each in physical units with its estimates in
the footnote (runtime/measure/contract.py chart_note):

    svaj.png           lift, velocity, acceleration, jerk against the cam angle at the top
                       speed: the chosen law, the other candidates faint behind it
    residual_band.png  the worst residual against the speed for every law, the band shaded
    contact_force.png  the chosen law's contact force over the turn at the lowest and the top
                       speed, with the spring's force
    jump_margin.png    the least contact force over the turn against the speed
    cam_stress.png     the cam, its pressure angle and Hertz's contact pressure over the turn
"""
from __future__ import annotations

import numpy as np

from camdyn.runtime.core.outdir import writing
from camdyn.runtime.measure.contract import chart_note

from . import answer, units

FILES = ("svaj.png", "residual_band.png", "contact_force.png", "jump_margin.png",
         "cam_stress.png")

DPI = 90
SVAJ_POINTS = 721
"""Samples of the turn for the SVAJ chart (half a degree): the lines, not the figures."""


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def draw(a, folder) -> dict:
    """Every chart of the module doc that ``a`` has the figures for, into ``folder``:
    {name: path}."""
    out = {}
    for name, fn in (("svaj.png", svaj), ("residual_band.png", residual_band),
                     ("contact_force.png", contact_force), ("jump_margin.png", jump_margin),
                     ("cam_stress.png", cam_stress)):
        fig = fn(a)
        if fig is not None:
            out[name] = str(_save(fig, folder / name))
    return out


def _save(fig, path):
    plt = _pyplot()
    with writing(path) as p:
        fig.savefig(p, dpi=DPI)
    plt.close(fig)
    return path


def _footnote(fig, text: str) -> None:
    """The estimates and warnings below the axes (fixed margins: tight_layout measures every
    label, the slowest step of a chart)."""
    lines = text.count("\n") + 1
    height = fig.get_size_inches()[1]
    fig.text(0.01, 0.01, text, fontsize=6.5, va="bottom")
    fig.subplots_adjust(left=0.1, right=0.97, top=0.93,
                        bottom=min(0.4, (0.5 + 0.12 * lines) / height), hspace=0.25,
                        wspace=0.3)


def _speed(a, w):
    return units.speed_in(np.asarray(w, dtype=float), a.machine.speed_unit)


def _band(ax, a, clip: bool = True) -> None:
    """The band shaded (``clip``: the axis the band and a little either side of it)."""
    lo, hi = _speed(a, a.machine.speeds)
    ax.axvspan(lo, hi, color="0.88", lw=0, zorder=0, label="the speed band")
    if clip:
        pad = 0.05 * (hi - lo) if hi > lo else 0.05 * hi
        ax.set_xlim(lo - pad, hi + pad)


# -- SVAJ ----------------------------------------------------------------------------------------

def svaj(a):
    """s (mm), v (m/s), a (m/s^2), j (m/s^3) over the turn at the top speed; the candidates'
    lines clipped to twice the chosen law's range (a law whose acceleration or velocity jumps
    has no finite jerk or acceleration there)."""
    from . import kinematics

    plt = _pyplot()
    m, best = a.machine, a.chosen
    w = m.speeds[1]
    fig, axes = plt.subplots(4, 1, figsize=(8, 8), sharex=True)
    rows = (("s", 1e3, "lift s (mm)"), ("v", 1.0, "velocity (m/s)"),
            ("a", 1.0, "acceleration (m/s^2)"), ("j", 1.0, "jerk (m/s^3)"))
    chosen = kinematics.svaj(m, best.law, w, n=SVAJ_POINTS, theta=best.theta)
    for x in a.laws:
        if x is best or x.residual is None:
            continue
        k = kinematics.svaj(m, x.law, w, n=SVAJ_POINTS, theta=x.theta)
        for ax, (key, f, _) in zip(axes, rows):
            ax.plot(k.theta_deg, np.asarray(getattr(k, key)) * f, lw=0.6, alpha=0.35)
    for ax, (key, f, label) in zip(axes, rows):
        y = np.asarray(getattr(chosen, key), dtype=float) * f
        ax.plot(chosen.theta_deg, y, "k-", lw=1.4, label=best.law)
        top = np.nanmax(np.abs(y[np.isfinite(y)])) if np.any(np.isfinite(y)) else 1.0
        if top > 0:
            ax.set_ylim(-2.1 * top if key != "s" else -0.05 * top, 2.1 * top)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, lw=0.3)
    axes[-1].set_xlabel("cam angle (deg)")
    axes[0].set_title(f"{m.title}: the chosen law ({best.law}) and the candidates at "
                      f"{units.speed_in(w, m.speed_unit):.4g} {m.speed_unit}", fontsize=9)
    axes[0].legend(fontsize=7, loc="upper right")
    p = best.peaks
    est = {}
    if p is not None:
        est["a max (m/s^2)"] = (p.acceleration_max, _e(p, "acceleration_max"))
    _footnote(fig, chart_note(est, best.warnings) + "; lift, velocity and acceleration are the "
                                                    "law's closed forms")
    return fig


def _e(obj, key):
    """A figure's estimate, None where it has none (chart_note says so)."""
    return getattr(obj, f"{key}_error", None)


# -- the worst residual over the band ------------------------------------------------------------

def residual_band(a):
    """The residual amplitude (um) against the speed for every law, its estimate shaded, the
    worst point of each marked; log scale (the laws' residuals lie decades apart)."""
    plt = _pyplot()
    m = a.machine
    fig, ax = plt.subplots(figsize=(9.5, 5.5))
    _band(ax, a)
    est = {}
    floor = None
    for x in a.laws:
        r = x.residual
        if r is None or len(getattr(r, "curve_speeds", ())) == 0:
            continue
        s = _speed(a, r.curve_speeds)
        v = np.asarray(r.curve_values, dtype=float) * 1e6
        e = np.asarray(r.curve_errors, dtype=float) * 1e6
        positive = v[v > 0]
        if positive.size:
            floor = positive.min() if floor is None else min(floor, positive.min())
        style = dict(lw=2.0, color="k") if x is a.chosen else dict(lw=0.9)
        line, = ax.plot(s, v, label=x.law + ("" if x.passed else " (fails)"), **style)
        ax.fill_between(s, np.maximum(v - e, 0), v + e, color=line.get_color(), alpha=0.2, lw=0)
        ax.plot([_speed(a, r.speed)], [r.value * 1e6], "o", color=line.get_color(), ms=4)
        est[f"{x.law} worst (um)"] = (r.value * 1e6, r.error * 1e6)
    if floor is not None:
        from matplotlib.ticker import FuncFormatter, NullFormatter

        ax.set_yscale("log")
        ax.set_ylim(bottom=floor / 3)
        # plain numbers, no minor labels: the log axis's mathtext labels are slow to lay out
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel(f"camshaft speed ({m.speed_unit})")
    ax.set_ylabel("worst residual amplitude (um)")
    ax.set_title(f"{m.title}: the residual vibration over the band, U0 (3.5) times the stroke "
                 f"({a.ladder.model})", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    _footnote(fig, chart_note(est, answer.all_warnings(a))
              + "\n(bands: the estimates; dots: each law's worst)")
    fig.subplots_adjust(right=0.78)
    return fig


# -- the contact force ---------------------------------------------------------------------------

def contact_force(a):
    """The chosen law's contact force (N) over the turn at the lowest and the top speed (its
    estimate shaded), beside the spring's force k x + F_0 alone."""
    from . import kinematics

    best = a.chosen
    sp = best.spring
    if sp is None:
        return None
    plt = _pyplot()
    m = a.machine
    fig, ax = plt.subplots(figsize=(8, 4.5))
    th = np.asarray(sp.theta_deg, dtype=float)
    est = {}
    for w, key in zip(m.speeds, ("lo", "hi")):
        f = np.asarray(getattr(sp, f"contact_force_{key}"), dtype=float)
        e = getattr(sp, f"contact_force_{key}_error", None)
        label = f"{units.speed_in(w, m.speed_unit):.4g} {m.speed_unit}"
        line, = ax.plot(th, f, lw=1.0 if key == "lo" else 1.4, label=label)
        if e is not None:
            e = np.asarray(e, dtype=float)
            ax.fill_between(th, f - e, f + e, color=line.get_color(), alpha=0.25, lw=0)
        est[f"force at {label} (N)"] = (f, e if e is not None else [None])
    k = kinematics.svaj(m, best.law, m.speeds[1], n=SVAJ_POINTS, theta=best.theta)
    ax.plot(k.theta_deg, m.output_spring_rate * np.asarray(k.s) + sp.preload_used, "k--",
            lw=0.8, label="the spring alone, k x + F0")
    ax.axhline(0.0, color="r", lw=0.6)
    ax.set_xlabel("cam angle (deg)")
    ax.set_ylabel("contact force at the follower (N)")
    ax.set_title(f"{m.title}: {best.law}, preload {sp.preload_used:.4g} N, rate "
                 f"{m.output_spring_rate:.4g} N/m", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="upper right")
    _footnote(fig, chart_note(est, best.warnings))
    return fig


def jump_margin(a):
    """The least contact force over the turn (N) against the speed: where it reaches zero the
    follower leaves the cam (sec. 7.5); the chosen law bold with its estimate shaded, the
    others faint."""
    plt = _pyplot()
    m = a.machine
    fig, ax = plt.subplots(figsize=(9.5, 4.5))
    _band(ax, a, clip=False)          # the margin runs past the band to where it ends
    drawn = False
    est = {}
    left_out = [x.law for x in a.laws if x.velocity_jumps and x is not a.chosen]
    for x in a.laws:
        sp = x.spring
        if sp is None or len(getattr(sp, "jump_margin_speeds", ())) == 0 or x.law in left_out:
            continue
        s, f = _speed(a, sp.jump_margin_speeds), np.asarray(sp.jump_margin, dtype=float)
        if x is a.chosen:
            ax.plot(s, f, lw=2.0, color="k", label=x.law)
            e = getattr(sp, "jump_margin_error", None)
            if e is not None:
                e = np.asarray(e, dtype=float)
                ax.fill_between(s, f - e, f + e, color="k", alpha=0.2, lw=0)
            est[f"{x.law} least force (N)"] = (f, e if e is not None else [None])
        else:
            ax.plot(s, f, lw=0.7, alpha=0.6, label=x.law)
        drawn = True
    if not drawn:
        plt.close(fig)
        return None
    sp = a.chosen.spring
    if sp is not None and sp.jump_speed is not None:
        ax.axvline(_speed(a, sp.jump_speed), color="r", ls="--", lw=0.8,
                   label=f"{a.chosen.law} leaves the cam")
        e = _e(sp, "jump_speed")
        est[f"jump speed ({m.speed_unit})"] = (_speed(a, sp.jump_speed),
                                                None if e is None else _speed(a, e))
    ax.axhline(0.0, color="r", lw=0.6)
    ax.set_xlabel(f"camshaft speed ({m.speed_unit})")
    ax.set_ylabel("least contact force over the turn (N)")
    ax.set_title(f"{m.title}: the jump margin with the spring used", fontsize=9)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    note = chart_note(est, a.chosen.warnings)
    if left_out:       # an impulse at each jump: no spring holds them, and their scale hides
        note += ("\n(left out, their velocity jumps and no spring holds them: "
                 + ", ".join(left_out) + ")")
    _footnote(fig, note)
    fig.subplots_adjust(right=0.78)
    return fig


# -- the cam ---------------------------------------------------------------------------------------

def cam_stress(a):
    """The chosen cam (mm) beside its pressure angle (deg) and Hertz's contact pressure (MPa)
    over the turn, with their limits (the ContactAnswer's arrays)."""
    best = a.chosen
    c = best.contact
    if c is None:
        return None
    plt = _pyplot()
    m = a.machine
    fig = plt.figure(figsize=(10, 5))
    ax0 = fig.add_subplot(1, 2, 1)
    x, y = (np.append(v, v[:1]) * 1e3 for v in (np.asarray(c.x), np.asarray(c.y)))
    ax0.plot(x, y, "k-", lw=1.2)
    t = np.linspace(0, 2 * np.pi, 361)
    ax0.plot(m.base_radius * 1e3 * np.cos(t), m.base_radius * 1e3 * np.sin(t), "b:", lw=0.6,
             label="base circle")
    ax0.set_aspect("equal")
    ax0.set_xlabel("x (mm)")
    ax0.set_ylabel("y (mm)")
    ax0.grid(True, lw=0.3)
    ax0.legend(fontsize=7, loc="upper right")
    ax0.set_title(f"the {best.law} cam", fontsize=9)
    ax1 = fig.add_subplot(2, 2, 2)
    ax1.plot(c.theta_deg, c.pressure_angle_deg, "k-", lw=1.0)
    for sign in (1, -1):
        ax1.axhline(sign * m.max_pressure_angle, color="r", ls="--", lw=0.7)
    ax1.set_ylabel("pressure angle (deg)", fontsize=8)
    ax1.grid(True, lw=0.3)
    ax2 = fig.add_subplot(2, 2, 4, sharex=ax1)
    if c.stress is not None:
        p0 = np.asarray(c.stress, dtype=float) / 1e6
        finite = np.isfinite(p0)
        ax2.plot(np.asarray(c.theta_deg)[finite], p0[finite], "k-", lw=1.0)
    if c.hertz_allowed is not None:
        ax2.axhline(c.hertz_allowed / 1e6, color="r", ls="--", lw=0.7, label="allowable")
        ax2.legend(fontsize=7, loc="lower right")
    ax2.set_ylabel("Hertz pressure (MPa)", fontsize=8)
    ax2.set_xlabel("cam angle (deg)")
    ax2.grid(True, lw=0.3)
    est = {"alpha max (deg)": (c.pressure_angle_max_deg, _e(c, "pressure_angle_max_deg")),
           "rho min (mm)": (c.rho_min * 1e3, _mm(_e(c, "rho_min")))}
    if c.hertz_stress_max is not None:
        est["Hertz max (MPa)"] = (c.hertz_stress_max / 1e6, _scaled(_e(c, "hertz_stress_max"),
                                                                     1e-6))
    _footnote(fig, chart_note(est, best.warnings))
    return fig


def _mm(e):
    return _scaled(e, 1e3)


def _scaled(e, f):
    return None if e is None else e * f
