"""The thesis room: M.P. Koster's thesis in camdyn, by job.

:mod:`.theory`   the theory typed in from the thesis (closed forms, element equations,
                 assembly and reduction, motor theory, equivalent systems, impact, Rayleigh's
                 method, App. 2's law table, the worked examples of App. 7); it never imports
                 the runtime
:mod:`.design`   the design tools, which run the compiled models to answer a designer's
                 question (`camdyn design`, `camdyn laws --tau`, `camdyn laws --sweep`)
:mod:`.checks`   every comparison with a value or formula the thesis prints (`camdyn check`)
:mod:`.figures`  the figures the models determine and their index (`camdyn figures`)
:mod:`.registry` the one registry of checks and figures

Why a room of its own: these modules check the pipeline from outside.  They may import both
sides of it (SymPy and :mod:`camdyn.derive`, the simulations of :mod:`camdyn.runtime`), and
nothing in the pipeline imports them, but for the command line handing its four commands over
inside their run(); so derive -> generated -> runtime stays a one-way street and a simulation
never loads SymPy.
"""
