"""The model registry: every model that ``camdyn derive`` generates.

Each entry maps the generated module name to a function returning the
:class:`~camdyn.derive.model.Model` declaration.
"""
from functools import partial

from . import beam, camshaft1, camshaft2, chain3, dynacam, motor, one_dof, roller, pendulum

REGISTRY = {
    "one_dof": one_dof.build,
    "camshaft1": camshaft1.build,
    "camshaft2": camshaft2.build,
    "chain3": chain3.build,
    "motor1": motor.build_first_order,
    "motor2": motor.build_second_order,
    "roller": roller.build,
    # the same held without backlash: smooth, the stiff benchmark case (bench/stiff.py)
    "roller_bilateral": roller.build_bilateral,
    # the second constrained model, a pendulum in dependent coordinates: the constraint layer
    # (dae.py) serves any declaration, not the beam follower only
    "pendulum_xy": pendulum.build,
}

DYNACAM_VARIANTS = (
    # four DOF at constant speed, rigid drive: sec. 8.2 (fig. 8.3), with its 2-DOF reduction
    dynacam.Options(),
    dynacam.Options(shaft_y=False, shaft_z=False),
    # the spring-loaded follower of fig. 7.2 (scenes/spring_loaded.toml), and the same at
    # constant speed (the motor made ideal)
    dynacam.Options(motor="second", roller="contact", spring=True),
    dynacam.Options(roller="contact", spring=True),
    # a spring-held rocker: the designer's oscillating roller follower (sec. 2.4 reduction)
    dynacam.Options(roller="contact", spring=True, rocker=True),
    # the same with a flat face on the arm: the oscillating flat-faced follower
    dynacam.Options(roller="contact", spring=True, rocker=True, flat_face=True),
    # a spring-held flat face, and the roller on a shaft rigid sideways that it equals
    dynacam.Options(roller="contact", spring=True, flat_face=True),
    dynacam.Options(roller="contact", spring=True, shaft_y=False),
    # the same with Coulomb friction on the cam and in the linkage (6.13), (6.43): tests/test_nonsmooth.py
    dynacam.Options(roller="contact", spring=True, cam_friction=True, linkage_friction=True),
    # the indexing mechanism of fig. 7.1 (scenes/indexing.toml): an axial (globoidal) cam at
    # constant (synchronous) speed with backlash in gear and groove (fig. 7.16), and without
    # backlash (fig. 7.15), and with the squeeze film in gear and groove (figs 7.11b, 7.20)
    dynacam.Options(cam="axial", gear="backlash", roller="groove"),
    dynacam.Options(cam="axial"),
    dynacam.Options(cam="axial", gear="squeeze", roller="groove-squeeze"),
)
"""The DYNACAM variants generated: what the scenes ask for, and the reductions the tests
compare them with.  A scene whose options are not here is refused with the list."""

for _opts in DYNACAM_VARIANTS:
    REGISTRY[_opts.name] = partial(dynacam.build, _opts)

for _n in range(1, beam.N_MAX + 1):
    REGISTRY[f"beam{_n}"] = partial(beam.build, _n)
"""The Rayleigh-beam follower with N = 1..6 assumed modes (the paper's rod; the user picks N)."""

