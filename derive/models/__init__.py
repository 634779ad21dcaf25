"""The model registry: every model that ``camdyn derive`` generates.

Each entry maps the generated module name to a function returning the
:class:`~camdyn.derive.model.Model` declaration.
"""
from . import camshaft1, chain3, one_dof

REGISTRY = {
    "one_dof": one_dof.build,
    "camshaft1": camshaft1.build,
    "chain3": chain3.build,
}
