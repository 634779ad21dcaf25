"""The cam plate as a solid in a STEP file (ISO 10303, AP214): the profile extruded to the
plate's thickness, less its bore, through the OpenCASCADE kernel of gmsh (the optional extra
``camdyn[cad]``), for CAD programs and CAM software that take solids rather than DXF curves.

The profile enters as its chain of tangent arcs (runtime/cam/biarc.py), exact circles in the
B-rep, within the arc tolerance of the exact profile (1e-6 m unless the cam states its own),
so the file's geometry errs by no more than that anywhere; the plate lies on z = 0 to its
thickness, the cam's centre at the origin, in metres.
"""
from __future__ import annotations

import contextlib
import os
import sys

import numpy as np

from ..core.errors import CamdynInputError
from ..core.outdir import writing
from .checks import MIN_WIDTH, in_range

EXTRA = "pip install 'camdyn[cad]'"

PROFILE_CHECKS = ("undercut", "cusp")
"""The checks whose failure says the profile is no closed simple curve: a roller's profile
that cusps (undercut, a velocity jump's corner), a flat face's envelope that cusps."""


class StepError(RuntimeError):
    """No plate for this cam: its profile is no closed simple curve, or the CAD kernel
    refused the solid; the message says which, in one line."""


def profile_refusal(cam) -> str | None:
    """Why the profile of ``cam`` cannot bound a solid, from its own checks (a cusp, an
    undercut, a corner of a velocity jump), or None: such a profile reaches no CAD kernel."""
    failed = [c for c in cam.checks if c.name in PROFILE_CHECKS and not c.ok]
    if not failed:
        return None
    c = failed[0]
    return (f"a STEP solid needs a closed simple profile, and this one fails its {c.name} "
            f"check (at cam angle {c.worst_deg:.2f} deg; the check says why)")


def _gmsh():
    try:
        import gmsh
    except ImportError:
        raise CamdynInputError(f"a STEP file needs the CAD kernel of the optional extra: "
                               f"{EXTRA}") from None
    return gmsh


@contextlib.contextmanager
def _quiet_stdout():
    """OpenCASCADE's STEP translator prints its transfer statistics on the process's own
    standard output, past Python: the descriptor is pointed at /dev/null meanwhile."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 1)
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


@contextlib.contextmanager
def _session():
    gmsh = _gmsh()
    gmsh.initialize(readConfigFiles=False, interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        yield gmsh
    finally:
        gmsh.finalize()


def plate_checks(cam, thickness: float, bore: float,
                 thickness_name: str = "thickness") -> tuple[float, float]:
    """(thickness, bore) checked against the cam: a plate of 1e-6 <= thickness < 1 m whose bore
    (a diameter, 0 for none) leaves wall inside the profile's least radius; a refusal names
    the thickness ``thickness_name``."""
    thickness = in_range(thickness_name, thickness, MIN_WIDTH, high=1.0, high_open=True)
    bore = in_range("bore", bore, high=1.0, high_open=True)
    if 0 < bore < MIN_WIDTH:
        raise CamdynInputError(f"bore={bore:g} is out of range: 0 for none, or a diameter >= "
                               f"{MIN_WIDTH:g} m")
    _gmsh()                         # the optional extra, before any file is written
    if cam.groove:
        raise CamdynInputError("a STEP plate goes with an open cam: a groove cam's walls are in "
                               "the DXF (layers PROFILE, PROFILE_OUTER)")
    tab = cam.table
    least = float(np.hypot(tab["x_profile"], tab["y_profile"]).min())
    if bore >= 2.0 * least:
        raise CamdynInputError(f"bore={bore:g} is out of range: the bore's diameter must be "
                               f"below twice the profile's least radius, 2 x {least:g} m")
    return thickness, bore


def write_step(cam, path, thickness: float, bore: float = 0.0) -> dict:
    """Write the plate of ``cam`` (a :class:`camdyn.runtime.cam.profile.CamProfile`) to
    ``path``; returns what the file holds: its arcs, the plate's volume (m^3, OpenCASCADE's)
    and how far that may be from the exact profile's (volume_error: the arcs' tolerance times
    the profile's length and the thickness), the tolerance (m).  A profile that is no closed
    simple curve (:func:`profile_refusal`), or a solid the kernel refuses, is a
    :class:`StepError` and no file."""
    thickness, bore = plate_checks(cam, thickness, bore)
    why = profile_refusal(cam)
    if why is not None:
        raise StepError(why)
    arcs = cam.arcs("PROFILE")
    with _session() as gmsh:
        try:
            solid, curves = _plate(gmsh, arcs, thickness, bore)
            occ = gmsh.model.occ
            volume = sum(occ.getMass(3, tag) for _, tag in solid)
            length = sum(occ.getMass(1, c) for c in curves)
        except Exception as exc:   # noqa: BLE001 (gmsh raises a bare Exception, its last error)
            raise StepError(f"the CAD kernel (gmsh's OpenCASCADE) could not build the plate "
                            f"from the profile's {len(arcs)} arcs: {exc}") from None
        with writing(path) as p, _quiet_stdout():
            try:
                gmsh.write(str(p))
            except Exception as exc:   # noqa: BLE001 (the same bare Exception)
                raise StepError(f"the CAD kernel could not write {path}: {exc}") from None
    tol = cam.arc_tolerance_used
    # the arcs stray from the profile by at most tol along its whole length
    return {"arcs": len(arcs), "volume": volume, "volume_error": tol * length * thickness,
            "thickness": thickness, "bore": bore, "tolerance": tol}


def _plate(gmsh, arcs, thickness: float, bore: float):
    """(the solid's dimension-tags, the profile's curve tags): the arcs' curve loop as a plane
    face, extruded to the thickness, less the bore."""
    occ = gmsh.model.occ
    starts = [occ.addPoint(a.start[0], a.start[1], 0.0) for a in arcs]
    curves = []
    for k, arc in enumerate(arcs):
        p, q = starts[k], starts[(k + 1) % len(arcs)]
        cr = arc.centre_radius()
        if cr is None:
            curves.append(occ.addLine(p, q))
        else:
            # a bi-arc spans far less than half a turn, so its centre fixes the arc
            c = occ.addPoint(cr[0][0], cr[0][1], 0.0)
            curves.append(occ.addCircleArc(p, c, q))
    face = occ.addPlaneSurface([occ.addCurveLoop(curves)])
    solid = [d for d in occ.extrude([(2, face)], 0.0, 0.0, thickness) if d[0] == 3]
    if bore > 0.0:
        hole = occ.addCylinder(0.0, 0.0, -thickness, 0.0, 0.0, 3.0 * thickness, bore / 2.0)
        solid, _ = occ.cut(solid, [(3, hole)])
    occ.synchronize()
    return solid, curves


def read_step(path) -> dict:
    """What a STEP file holds, read back through the same kernel: its solids, their volume
    (m^3) and bounding box (xmin, ymin, zmin, xmax, ymax, zmax; m)."""
    with _session() as gmsh:
        occ = gmsh.model.occ
        with _quiet_stdout():
            shapes = occ.importShapes(str(path))
        occ.synchronize()
        solids = [tag for dim, tag in shapes if dim == 3]
        box = [gmsh.model.getBoundingBox(3, tag) for tag in solids]
        return {"solids": len(solids), "volume": sum(occ.getMass(3, t) for t in solids),
                "box": tuple(min(b[i] for b in box) if i < 3 else max(b[i] for b in box)
                             for i in range(6)) if box else None,
                "faces": len(gmsh.model.getEntities(2))}
