"""The index page of ``camdyn figures``: out_dir/index.html, each picture beside the figure's
number, caption and the statements it reproduces (computed value, with its error estimate,
against the printed one)."""
from __future__ import annotations

import os
import re
from pathlib import Path

from jinja2 import Environment
from markupsafe import Markup, escape

from camdyn.runtime.core.outdir import write_text

from .figure import GROUPS

TEMPLATE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<title>camdyn figures</title>
<style>
body { font-family: sans-serif; margin: 1.5em; max-width: 1400px; color: #222; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; border-bottom: 1px solid #ccc; margin-top: 2em; }
.fig { display: flex; gap: 1.2em; padding: 0.8em 0; border-bottom: 1px solid #eee; }
.pics { flex: 0 0 520px; } .pics img { width: 520px; border: 1px solid #ddd; margin-bottom: 4px; }
.text { flex: 1; } .num { font-size: 1.2em; font-weight: bold; }
table { border-collapse: collapse; font-size: 0.85em; margin-top: 0.5em; }
td, th { border: 1px solid #ddd; padding: 2px 6px; text-align: left; vertical-align: top; }
.pass, .errata { color: #1b5e20; } .FAIL, .ERROR { color: #b71c1c; font-weight: bold; }
.missing { color: #777; font-style: italic; } .note { color: #555; font-size: 0.85em; }
.wide { color: #e65100; font-size: 0.85em; }
</style></head><body>
<h1>camdyn figures</h1>
<p>{{ n_built }} figures drawn, {{ n_missing }} not reproduced; {{ n_claims }} statements
computed now against the printed values: {{ n_passed }} reproduced{% if n_failed %},
<span class="FAIL">{{ n_failed }} not</span>{% endif %}. Built in {{ seconds }} s{% if quick %}
(<b>--quick</b>: coarser grids){% endif %}.{% if chosen > n_listed %}
<b>This page lists {{ n_listed }} of the {{ chosen }} figures chosen: it was written before
the others were drawn (the build was stopped, or is still running).</b>{% endif %} "errata": the printed value is a misprint and the
value the thesis's own formulas give is reproduced (see <code>camdyn check</code>).</p>
<p>Every computed value carries its error estimate, "value ± e": e = |v - v'|, v' the same
value computed again with every run one notch tighter (rtol/10, or half the step and
Richardson's factor 2^p/(2^p - 1)); closed forms and parameters are marked exact. Whether a
statement is reproduced is judged on v, as <code>camdyn check</code> judges it.{% if n_wide %}
<span class="wide">{{ n_wide }} statement{{ "s" if n_wide > 1 }} carr{{ "y" if n_wide > 1 else "ies" }} an
estimate larger than the tolerance of its rule: there the runs do not resolve the
agreement (marked below).</span>{% endif %}</p>
{% for key, heading, items in groups %}{% if items %}
<h2>{{ heading }}</h2>
{% for b in items %}<div class="fig" id="{{ b.figure.slug }}">
<div class="pics">{% for p in b.pics %}<a href="{{ p }}"><img src="{{ p }}" alt="{{ b.figure.id }}"></a>
{% endfor %}{% if not b.pics %}<p class="missing">{% if b.figure.not_reproduced %}not reproduced: {{ b.figure.not_reproduced }}{% else %}build failed: {{ b.error }}{% endif %}</p>{% endif %}</div>
<div class="text"><div class="num">{% if b.figure.group == "thesis" %}Fig. {{ b.figure.id }}{% elif b.figure.group == "paper" %}Paper, fig. {{ b.figure.id.split()[-1] }}{% else %}{{ b.figure.id }}{% endif %}</div>
<p>{{ b.figure.caption|code }}</p>
{% if b.error %}<p class="ERROR">build failed: {{ b.error }}</p>{% endif %}
{% if b.claims %}<table><tr><th>statement reproduced</th><th>source</th><th>printed</th><th>computed</th><th>tolerance</th><th></th></tr>
{% for c in b.claims %}<tr><td>{{ c.text }}{% if c.note %}<br><span class="note">{{ c.note }}</span>{% endif %}</td><td>{{ c.reference }}</td><td>{{ c.printed }}</td><td>{{ c.shown }}{% if c.wide %}<br><span class="wide">estimate larger than the tolerance {{ "%.2g"|format(c.tolerance) }}</span>{% endif %}</td><td>{{ c.rule }}</td><td class="{{ c.status.split()[0] }}">{{ c.status }}</td></tr>
{% endfor %}</table>{% endif %}
{% if b.figure.note %}<p class="note">{{ b.figure.note|code }}</p>{% endif %}
{% if b.pics %}<p class="note">{{ "%.1f"|format(b.seconds) }} s</p>{% endif %}
</div></div>
{% endfor %}{% endif %}{% endfor %}
</body></html>
"""


def _code(text: str) -> Markup:
    """Escape, then show `command` spans as code."""
    return Markup(re.sub(r"`([^`]+)`", r"<code>\1</code>", str(escape(text))))


def write(built: list, out_dir, seconds: float, quick: bool, chosen: int | None = None) -> str:
    """Write out_dir/index.html for ``built`` (figures.build's list, the first of ``chosen``
    figures while a build is under way); returns its path."""
    out_dir = Path(out_dir)
    for b in built:
        b.pics = [os.path.relpath(p, out_dir) for p in b.pngs]
    claims = [c for b in built for c in b.claims]
    env = Environment(autoescape=True)
    env.filters["code"] = _code
    html = env.from_string(TEMPLATE).render(
        groups=[(k, h, [b for b in built if b.figure.group == k]) for k, h in GROUPS],
        n_built=sum(bool(b.pngs) for b in built),
        n_missing=sum(not b.pngs for b in built),
        n_claims=len(claims), n_passed=sum(c.passed for c in claims),
        n_failed=sum(not c.passed for c in claims), n_wide=sum(c.wide for c in claims),
        seconds=f"{seconds:.0f}", quick=quick, n_listed=len(built),
        chosen=len(built) if chosen is None else chosen)
    return str(write_text(out_dir / "index.html", html))
