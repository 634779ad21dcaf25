"""The design tools: questions a designer asks, answered by the thesis's method with runs of the
compiled models.

`camdyn design` (:mod:`.method`: the machine's figures, the envelopes of fig. 4.11, the limits
a requirement sets, the rules of sec. 8.5, the motor of sec. 8.3, a check run), the choice of
a cam law by the criteria of sec. 9.2.2 (:mod:`.selection`, `camdyn laws --tau`) and a law's
shape parameter swept on a scene as in fig. 8.8 (:mod:`.shape_sweep`, `camdyn laws --sweep`).
Unlike the theory, these run the runtime; unlike the checks, they answer a question rather
than compare with a printed value.
"""
