"""Generated model modules (written by ``camdyn derive``, do not edit).

Each model module exposes ``MODEL`` (a capsule with the C interface used by
the integrators) and ``MANIFEST`` (states, parameters, outputs, source hash).
"""
