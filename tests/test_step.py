"""The cam plate as a STEP solid (runtime/cam/step.py), read back through the same CAD kernel.

The plate's volume is thickness x (the area inside the profile - the bore's): for a cam without
stroke the profile is the base circle and the volume is known in closed form; otherwise the area
comes from the shoelace formula on the exact profile sampled at 20 points a degree, independent
of the arcs that make up the file.  The tolerances are the writer's own volume_error (the arcs'
tolerance times the profile's length and the thickness) or stated per test.
"""
import json
import math
import sys

import numpy as np
import pytest

from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cam.step import read_step, write_step
from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError


def test_a_cam_without_stroke_is_a_disk(tmp_path):
    """stroke 0: the profile is the base circle r_b, the plate pi (r_b^2 - r^2) t; measured
    relative error 1e-15, asserted 1e-9 (the arcs of a circle are the circle)."""
    rb, t, d = 0.04, 0.01, 0.016
    cam = CamProfile(stroke=0.0, base_radius=rb, roller_radius=0.01)
    info = write_step(cam, tmp_path / "disk.step", t, d)
    back = read_step(tmp_path / "disk.step")
    exact = math.pi * (rb**2 - (d / 2) ** 2) * t
    assert back["solids"] == 1
    assert back["volume"] == pytest.approx(exact, rel=1e-9)
    assert info["volume"] == pytest.approx(exact, rel=1e-9)
    # OpenCASCADE widens a bounding box by its own precision, 1e-7 m
    assert np.allclose(back["box"], (-rb, -rb, 0.0, rb, rb, t), atol=2e-7)


CAMS = {
    "translating-roller": dict(stroke=0.02, base_radius=0.05, roller_radius=0.01, offset=0.005),
    "oscillating-roller": dict(follower="oscillating-roller", pivot_distance=0.09,
                               arm_length=0.07, swing_deg=18, base_radius=0.03,
                               roller_radius=0.008),
    "translating-flat": dict(follower="translating-flat", stroke=0.01, base_radius=0.03),
}


@pytest.mark.parametrize("kind", CAMS)
def test_plate_volume_and_extent_against_the_sampled_profile(tmp_path, kind):
    """Volume within the writer's volume_error of t (shoelace area - bore), that error below
    1e-4 of the volume; the solid read back is the one written; its box the profile's extent
    within the arcs' tolerance (plus the kernel's 1e-7 m)."""
    t, d = 0.012, 0.01
    cam = CamProfile(points_per_degree=20, **CAMS[kind])
    info = write_step(cam, tmp_path / "cam.step", t, d)
    back = read_step(tmp_path / "cam.step")
    x, y = cam.table["x_profile"], cam.table["y_profile"]
    area = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    expected = t * (area - math.pi * (d / 2) ** 2)
    assert back["solids"] == 1 and back["faces"] >= info["arcs"] + 2
    assert abs(back["volume"] - info["volume"]) < 1e-12 * info["volume"]
    assert abs(info["volume"] - expected) < info["volume_error"] < 1e-4 * expected
    tol = info["tolerance"] + 2e-7
    assert np.allclose(back["box"], (x.min(), y.min(), 0.0, x.max(), y.max(), t), atol=tol)


def test_cli_writes_the_step_beside_the_others(tmp_path, capsys):
    rc = main(["profile", "--base-radius", "0.05", "--roller-radius", "0.01", "--stroke", "0.02",
               "--step", "--cam-width", "0.012", "--bore", "0.02", "--arcs", "1e-5",
               "--out", str(tmp_path), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out["files"]["step"] == str(tmp_path / "cam.step")
    back = read_step(tmp_path / "cam.step")
    assert out["step"]["tolerance"] == 1e-5 and out["step"]["bore"] == 0.02
    assert back["volume"] == pytest.approx(out["step"]["volume"], rel=1e-12)
    assert json.loads((tmp_path / "cam.json").read_text())["step"] == out["step"]


@pytest.mark.parametrize("argv,names", [
    (["--step"], ["--step", "--cam-width"]),
    (["--bore", "0.01"], ["--bore", "--step"]),
    (["--step", "--cam-width", "0.01", "--bore", "0.2"], ["bore", "0.05"]),
    (["--step", "--cam-width", "2"], ["cam-width", "1"]),
    (["--step", "--cam-width", "0.01", "--groove"], ["open cam"]),
])
def test_cli_refuses_a_plate_in_one_line_and_writes_nothing(tmp_path, capsys, argv, names):
    rc = main(["profile", "--base-radius", "0.05", "--roller-radius", "0.01", "--stroke", "0.02",
               *argv, "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("camdyn profile: error:")
    for n in names:
        assert n in err[0]
    assert not (tmp_path / "o").exists()


def test_without_the_cad_extra_the_plate_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "gmsh", None)
    cam = CamProfile(stroke=0.02, base_radius=0.05, roller_radius=0.01)
    with pytest.raises(CamdynInputError, match=r"camdyn\[cad\]"):
        write_step(cam, tmp_path / "cam.step", 0.01)
    assert not (tmp_path / "cam.step").exists()
