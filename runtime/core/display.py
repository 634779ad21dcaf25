"""How camdyn's results show in a notebook: HTML tables with inline charts, and the tables of
pandas and xarray.

The rich views keep the answer contract (runtime/measure/contract.py) as the text does: a
figure's row carries its error estimate beside it, the run's warnings stand under the table
("no warnings" when there are none), and a chart says in its footnote what the largest
estimate is.  pandas and xarray are optional (``pip install 'camdyn[notebook]'``); a
conversion without them is refused in one line saying what to install.
"""
from __future__ import annotations

import base64
import html
import io
import math

from .errors import CamdynInputError

ROWS = 20
"""Rows of a long table shown inline (the first and last halves); to_pandas() has them all."""


def need(module: str, what: str):
    """Import ``module`` for ``what`` (e.g. "to_pandas()"), or a one-line refusal naming the
    extra that installs it."""
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError:
        raise CamdynInputError(f"{what} needs {module}: pip install 'camdyn[notebook]' "
                               f"(or pip install {module})") from None


def text(value) -> str:
    """A value as a table shows it: numbers to 6 significant digits, None as a dash."""
    if value is None:
        return "\u2013"
    if isinstance(value, float):
        return "NaN" if math.isnan(value) else f"{value:.6g}"
    return str(value)


def plus_minus(value, error) -> str:
    """``value ± error``; "estimate unavailable" where a figure has none (the contract's words)."""
    if error is None or (isinstance(error, float) and math.isnan(error)):
        return f"{text(value)} (estimate unavailable)"
    return f"{text(value)} \u00b1 {text(error)}"


def table(head: list, rows: list, caption: str = "") -> str:
    """An HTML table; rows beyond :data:`ROWS` are elided in the middle, with their count."""
    shown = list(rows)
    cut = len(shown) > ROWS
    if cut:
        half = ROWS // 2
        skipped = len(shown) - 2 * half
        shown = shown[:half] + [None] + shown[-half:]
    out = ['<table class="camdyn">']
    if caption:
        out.append(f"<caption>{html.escape(caption)}</caption>")
    out.append("<thead><tr>" + "".join(f"<th>{html.escape(str(h))}</th>" for h in head)
               + "</tr></thead><tbody>")
    for row in shown:
        if row is None:
            out.append(f'<tr><td colspan="{len(head)}">&hellip; {skipped} rows more '
                       "(to_pandas() has them all) &hellip;</td></tr>")
        else:
            out.append("<tr>" + "".join(f"<td>{html.escape(text(v))}</td>" for v in row) + "</tr>")
    out.append("</tbody></table>")
    return "".join(out)


def warnings_block(warnings) -> str:
    """The run's warnings as a list, or the words that there are none."""
    lines = [w for w in warnings if w]
    if not lines:
        return "<p>no warnings</p>"
    return ("<p>warnings:</p><ul>" + "".join(f"<li>{html.escape(w)}</li>" for w in lines)
            + "</ul>")


def picture(fig) -> str:
    """A matplotlib figure (made without pyplot) as an inline PNG."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90)
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    return f'<img src="data:image/png;base64,{data}" alt="chart"/>'


def page(title: str, *parts: str) -> str:
    """The parts under a heading, as one block of a notebook's output."""
    return f'<div class="camdyn"><p><b>{html.escape(title)}</b></p>{"".join(parts)}</div>'
