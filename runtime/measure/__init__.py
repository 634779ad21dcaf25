"""Figures of finished runs: extremes on the dense output, the residual vibration (thesis
(3.5), (3.6)), envelopes through the maxima, error estimates, the closed forms used as
references, and the answer contract every figure leaves camdyn under."""
