"""The thesis room: the hand-derived theory of M.P. Koster's thesis and every comparison with it.

Closed forms (ch. 3, 4), element energies, assembly and reduction (ch. 2), chains and modal
contributions (sec. 3.7), impact and damping (secs 3.4, 3.6), Rayleigh's method (sec. 4.6,
App. 3), equivalent masses (ch. 5), the foundation (sec. 7.2), motor theory (App. 5), the
measured mechanisms and their App. 7 numbers, App. 2's law table, and the registry of
comparisons (:mod:`camdyn.thesis.checks`, run by `camdyn check` and the tests).

Why a room of its own: these modules check the pipeline from outside.  They may import both
sides of it (SymPy and :mod:`camdyn.derive`, the simulations of :mod:`camdyn.runtime`), and
nothing in the pipeline imports them, so derive -> generated -> runtime stays a one-way street
and a simulation never loads SymPy.
"""
