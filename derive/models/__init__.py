"""The model registry: every model that ``camdyn derive`` generates.

Each entry maps the generated module name to a function returning the
:class:`~camdyn.derive.model.Model` declaration.
"""
from . import camshaft1, camshaft2, chain3, motor, one_dof

REGISTRY = {
    "one_dof": one_dof.build,
    "camshaft1": camshaft1.build,
    "camshaft2": camshaft2.build,
    "chain3": chain3.build,
    "motor1": motor.build_first_order,
    "motor2": motor.build_second_order,
}
