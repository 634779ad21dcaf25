"""The generated cam-law library (``camlaws.pxd``, ``camlaws.pyx``) from the laws of
:mod:`camdyn.derive.camlaws` (thesis App. 2 and the usual industrial laws).

Each law is printed segment by segment, H and its first three derivatives with common
subexpressions eliminated (and the fourth apart, ``camlaw_d4``); compiled models cimport the .pxd and evaluate their cam inputs
through it.
"""
from __future__ import annotations

import json

from . import camlaws
from .emit import render
from .printer import CythonPrinter, cse_block


LAW_TRIG = {"sin": "camlaw_sin", "cos": "camlaw_cos"}
"""The laws' sine and cosine: the template's own, reduced for the laws' arguments (camlaws.pxd)."""


def camlaws_context() -> dict:
    """Everything the two cam-law templates need, printed as Cython strings."""
    laws = []
    for law in sorted(camlaws.LAWS.values(), key=lambda l: l.code):
        names = {camlaws.T: "T"}
        if law.parameter is not None:
            names[law.parameter.symbol] = "par"
        printer = CythonPrinter(names)
        segs = []
        for k in range(law.n_segments):
            exprs = [law.segment_exprs(order)[k] for order in range(4)]
            lines, code, _ = cse_block(exprs, names, prefix="c", functions=LAW_TRIG)
            # the fourth derivative on its own: only the exact Jacobian of a constrained
            # model whose equations carry H''' asks for it (camlaw_d4)
            lines4, code4, _ = cse_block([law.segment_exprs(4)[k]], names, prefix="c",
                                         functions=LAW_TRIG)
            segs.append({"index": k, "lines": lines, "code": code, "lines4": lines4,
                         "code4": code4[0]})
        laws.append({
            "key": law.key,
            "code": law.code,
            "title": law.title,
            "reference": law.reference,
            "bounds": [printer.doprint(b) for b in law.bounds],
            "segments": segs,
            "parameter": None if law.parameter is None else {
                "name": law.parameter.symbol.name, "default": law.parameter.default,
                "low": law.parameter.low, "high": law.parameter.high,
                "doc": law.parameter.doc},
            "amplitude": str(law.amplitude),
        })
    info = [{k: v for k, v in law.items() if k not in ("segments",)} for law in laws]
    turn = {"code": camlaws.TURN_CODE, "slots": camlaws.TURN_SLOTS, "width": 13}
    shaped = {"code": camlaws.SHAPED_CODE, "slots": camlaws.SHAPED_SLOTS,
              "pool": camlaws.SHAPED_POOL}
    return {"laws": laws, "laws_json": json.dumps(info, indent=1, sort_keys=True), "turn": turn,
            "shaped": shaped}


def render_camlaws() -> dict[str, str]:
    """File name -> text of the two files of the library."""
    ctx = camlaws_context()
    return {"camlaws.pxd": render("camlaws.pxd.j2", **ctx),
            "camlaws.pyx": render("camlaws.pyx.j2", **ctx)}
