"""The theory typed in from the thesis: closed forms (chs 3, 4), element equations, assembly and
reduction (ch. 2), chains (sec. 3.7), impact and damping (secs 3.4, 3.6), Rayleigh's method
(sec. 4.6, App. 3), equivalent systems (ch. 5), the foundation (sec. 7.2), motor theory
(App. 5), the measured mechanisms and their worked examples (App. 7) and App. 2's law table.

It is written as the thesis prints it, never derived from the models, so that a comparison of
the two can fail; and it never imports the runtime, so that nothing it says can borrow from
what it is compared with.
"""
