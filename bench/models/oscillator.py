"""A damped oscillator driven through a spring by a cam: README's model file (section "Any
model on demand"), the model file bench/sweep.py sweeps."""
from camdyn.derive.model import Coordinate, Model, Output, Parameter, cam_input, time

t = time("t")
H = cam_input("H")                        # the cam law: rise 0 -> 1 over 0 <= t <= 1
x = Coordinate("x", "m", "follower position")
m = Parameter("m", 1.0, "kg", "mass")
c = Parameter("c", 400.0, "N/m", "spring between cam and follower")
d = Parameter("d", 2.0, "N s/m", "damper to the frame")


def build() -> Model:
    X, h = x(t), H(t)
    return Model(name="oscillator", title="Damped oscillator with a cam input",
                 reference="README", doc=__doc__, time=t, time_unit="s",
                 coordinates=(x,), kinetic=m.symbol * X.diff(t) ** 2 / 2,
                 potential=c.symbol * (h - X) ** 2 / 2,
                 dissipation=d.symbol * X.diff(t) ** 2 / 2,
                 parameters=(m, c, d),
                 outputs=(Output("a", X.diff(t, 2), "m/s^2", "acceleration"),))
