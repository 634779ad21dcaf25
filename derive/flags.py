"""The C compiler's flags for every compiled camdyn module: the package's (setup.py) and the
user's model files (derive/build.py) alike.  No imports: setup.py reads this file before camdyn
is installed.

-fno-math-errno: sqrt becomes an instruction; nothing here reads errno.
--param=inline-unit-growth=400: every model's module holds all the loops (loops.pxi); past
gcc's default unit growth (40 %) it stopped inlining the model's rhs into the RK4 loop, which
then took twice the time of the hand-written loop of bench/ (the call and the cam values no
longer shared between stages).
"""

COMPILE_ARGS = ["-O3", "-fno-math-errno", "--param=inline-unit-growth=400"]
