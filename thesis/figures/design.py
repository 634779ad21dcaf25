"""Design charts of issue 14 (items 2-6): the envelopes of the response graphs, the cam-law
selection chart, the cam profile; and the places for the charts still to come.

To add a chart: one Figure below with a builder ``(out_dir, quick) -> [png paths]`` that calls
the command's own function (as the three here do), or, until it exists, ``build=None`` with
``not_reproduced`` saying what is missing."""
from __future__ import annotations

import shutil
from pathlib import Path

from . import Figure


def _envelopes(out_dir, quick):
    from .ch4 import study

    data = study(str(out_dir), quick)
    path = Path(out_dir) / "envelopes.png"
    shutil.copyfile(Path(data["folder"]) / "graphs.png", path)
    return [str(path)]


def _laws(out_dir, quick):
    from .. import selection

    rows = selection.table(0.15, 0.5)
    return [selection.chart(rows, Path(out_dir) / "laws_selection.png")]


def _profile(out_dir, quick):
    from camdyn.runtime.cam_profile import CamProfile

    cam = CamProfile(stroke=0.015, base_radius=0.026, roller_radius=0.005)
    return [str(cam.write_png(Path(out_dir) / "cam_profile.png"))]


def figures() -> list[Figure]:
    later = "to be added with its command (issue 14, item {}); the lead fills this entry"
    return [
        Figure("envelopes", "design", "CAMSHAFT-1 response graphs with the envelopes through "
               "the maxima, as a designer reads them (item 2; `camdyn run`)", _envelopes,
               note="the graphs.png of `camdyn run`; data in camshaft1_study/envelopes.csv"),
        Figure("laws", "design", "Cam-law selection at tau = 0.15, Fa = 0.5: envelopes, impact "
               "sensitivity and peaks of every law (item 4; `camdyn laws --tau 0.15 --fa 0.5`)",
               _laws),
        Figure("profile", "design", "Disk cam for a translating roller follower: cycloidal rise "
               "15 mm, base circle 26 mm, roller 5 mm (item 6; `camdyn profile`)", _profile),
        Figure("sweep", "design", "Parameter sweep chart (item 3)", None,
               not_reproduced=later.format(3)),
        Figure("design", "design", "Design chart: the mechanism that meets a positional-error "
               "target (item 5)", None, not_reproduced=later.format(5)),
        Figure("least model", "design", "Least model that reproduces a richer one (item 5)",
               None, not_reproduced=later.format(5)),
    ]
