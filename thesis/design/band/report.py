"""The band design's report: report.md and report.html, each with the designer's table (every
figure ± its estimate), the reasons each failing law fails, the recommended design, the model
of the thesis's ladder and why, the charts inline (the HTML carries them in itself) and the
warnings."""
from __future__ import annotations

import base64
import html
from pathlib import Path

from camdyn.runtime.core.outdir import write_text

from . import answer

FILES = ("report.md", "report.html")

CAPTIONS = {
    "residual_band.png": "The worst residual vibration against the speed, every law; the band "
                         "shaded, the estimates as bands.",
    "svaj.png": "Lift, velocity, acceleration and jerk over the turn at the top speed: the "
                "chosen law, the candidates behind it.",
    "contact_force.png": "The chosen law's contact force over the turn at the lowest and the "
                         "top speed, with the spring's force.",
    "jump_margin.png": "The least contact force over the turn against the speed: below zero "
                       "the follower leaves the cam (sec. 7.5).",
    "cam_stress.png": "The chosen cam, its pressure angle and Hertz's contact pressure over "
                      "the turn, with their limits.",
}
"""What each chart shows, in the order the report shows them."""


def sections(a) -> dict:
    """The report's parts as text: the title, the machine, the table, the model and why, the
    recommendation, the warnings."""
    m = a.machine
    lines = answer.text(a).split("\n")
    lad = a.ladder
    return {"title": f"{m.title}: the cam law over {_band_text(m)}",
            "table": lines,
            "model": f"{lad.model}: {lad.why}",
            "recommended": (a.recommended if a.recommended is not None else
                            f"none passes every check; the nearest is {a.chosen.law}"),
            "warnings": answer.all_warnings(a)}


def _band_text(m) -> str:
    from . import units

    lo, hi = (units.speed_in(w, m.speed_unit) for w in m.speeds)
    return f"{lo:.4g} to {hi:.4g} {m.speed_unit}"


def markdown(a, figures: dict) -> str:
    s = sections(a)
    L = [f"# {s['title']}", "", f"**Recommended:** {s['recommended']}", "",
         f"**Model** (the thesis's ladder, ch. 8): {s['model']}", "", "```", *s["table"], "```",
         ""]
    for name, caption in CAPTIONS.items():
        if name in figures:
            L += [f"![{caption}]({Path(figures[name]).name})", "", f"*{caption}*", ""]
    L += ["## Warnings", ""]
    L += [f"- {w}" for w in s["warnings"]] or ["none"]
    return "\n".join(L) + "\n"


def html_page(a, figures: dict) -> str:
    s = sections(a)
    e = html.escape
    body = [f"<h1>{e(s['title'])}</h1>",
            f"<p><b>Recommended:</b> {e(s['recommended'])}</p>",
            f"<p><b>Model</b> (the thesis's ladder, ch. 8): {e(s['model'])}</p>",
            "<pre>" + e("\n".join(s["table"])) + "</pre>"]
    for name, caption in CAPTIONS.items():
        if name in figures:
            data = base64.b64encode(Path(figures[name]).read_bytes()).decode("ascii")
            body.append(f'<figure><img alt="{e(caption)}" src="data:image/png;base64,{data}">'
                        f"<figcaption>{e(caption)}</figcaption></figure>")
    body.append("<h2>Warnings</h2>")
    body.append("<ul>" + "".join(f"<li>{e(w)}</li>" for w in s["warnings"]) + "</ul>"
                if s["warnings"] else "<p>none</p>")
    return ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">"
            f"<title>{e(s['title'])}</title><style>body{{font-family:sans-serif;"
            "max-width:70em;margin:auto}pre{font-size:80%;overflow-x:auto}"
            "img{max-width:100%}</style></head><body>\n" + "\n".join(body)
            + "\n</body></html>\n")


def write(a, folder, figures: dict) -> dict:
    """report.md and report.html into ``folder``, the charts ``figures`` ({name: path})
    shown; returns {what: path}."""
    return {"report_md": str(write_text(folder / "report.md", markdown(a, figures))),
            "report_html": str(write_text(folder / "report.html", html_page(a, figures)))}
