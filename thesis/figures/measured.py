"""Figures of the thesis that show measurements or need what the models lack: listed so the
index says why they are not drawn, with the numbers read from them that are checked."""
from __future__ import annotations

from .figure import Claim, Figure

MEASURED = "a measurement on the test machines; a model cannot reproduce a recording"


def figures() -> list[Figure]:
    return [
        Figure("7.11", "thesis", "Diagrams of the indexing mechanism at two cam rise times, "
               "recorded and simulated with a velocity-dependent damping", None,
               claims=(Claim("sec7_4_4.gear_impact_T"),),
               not_reproduced="the simulation uses q = q0 exp(b |H' - X'|) (sec. 7.4.5), a "
                              "damping law the generated models do not have; the recorded "
                              "traces are " + MEASURED + ". The backlash run without damping "
                              "is fig. 7.16."),
        Figure("7.17", "thesis", "Measured acceleration of the spring-loaded follower's output "
               "member, decaying over the dwell", None,
               claims=(Claim("eq3_7.eq7_10.follower"),),
               not_reproduced=MEASURED + "; the damping read from it by (7.10) is checked."),
        Figure("7.18", "thesis", "Measured angular acceleration of the cam of the spring-loaded "
               "mechanism", None, claims=(Claim("eq3_7.eq7_10.shaft"),),
               not_reproduced=MEASURED + "; the damping read from it by (7.10) is checked."),
        Figure("8.2", "thesis", "Measured relative positional error against the calculated "
               "tau and Fa", None, not_reproduced=MEASURED + "."),
        Figure("A.5.6", "thesis", "Measured slip of the asynchronous motor over a cam rise", None,
               claims=(Claim("app5.tau_m"),),
               not_reproduced=MEASURED + "; its peak 1.6 % is drawn beside fig. A.5.7."),
    ]
