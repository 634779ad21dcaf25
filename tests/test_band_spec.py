"""A machine described once (thesis/design/band/spec.py, units.py): the units rule against
hand conversions, every missing value named at once, the template read back, a machine
written and read back to itself."""
import math
import tomllib

import pytest

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.thesis.design.band import spec, units


@pytest.mark.parametrize("raw, kind, si", [
    ("25 mm", "length", 0.025), (0.025, "length", 0.025), ("2 N/mm", "stiffness", 2000.0),
    ("1200 MPa", "stress", 1.2e9), ("0.0039 kg m^2", "inertia", 0.0039),
    ("6.4 N m/rad", "torsional stiffness", 6.4), ("120 deg", "angle", 120.0),
    (120, "angle", 120.0), ("2.0943951023931953 rad", "angle", 120.0),
    ("300 rpm", "speed", 10 * math.pi), ("5 Hz", "speed", 10 * math.pi),
    ("31.4 rad/s", "speed", 31.4)])
def test_a_value_is_si_or_carries_its_unit(raw, kind, si):
    """A number is SI (an angle in degrees), a string carries its unit; 5 Hz is five
    revolutions a second (300 rpm), not 5 rad/s."""
    assert units.value(raw, kind, "key") == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize("raw, words", [
    ("12 kg", "kg is no unit of length"), ("abc", "not a number with a unit"),
    (True, "must be a number"), ("nan", "not a finite number"), ([1], "must be a number")])
def test_a_bad_value_is_named(raw, words):
    with pytest.raises(CamdynInputError, match=words):
        units.value(raw, "length", "cam.base_radius")


@pytest.mark.parametrize("raw, rad_s, unit", [
    ("300:600 rpm", (10 * math.pi, 20 * math.pi), "rpm"),
    ("300:600rpm", (10 * math.pi, 20 * math.pi), "rpm"),
    ("5:10 Hz", (10 * math.pi, 20 * math.pi), "Hz"), ("31.4:62.8", (31.4, 62.8), "rad/s"),
    ("450 rpm", (15 * math.pi, 15 * math.pi), "rpm"), ([31.4, 62.8], (31.4, 62.8), "rad/s")])
def test_a_speed_band(raw, rad_s, unit):
    (lo, hi), shown = units.band(raw)
    assert (lo, hi) == pytest.approx(rad_s, rel=1e-12) and shown == unit


@pytest.mark.parametrize("raw", ["600:300 rpm", "x:y", "300:600 kg", "0:600 rpm", "-1:2"])
def test_a_bad_band_is_refused(raw):
    with pytest.raises(CamdynInputError, match="speed"):
        units.band(raw, "speed")


def test_the_template_is_a_machine_and_reads_back():
    """The commented template is a valid machine (the packaging station: 25 mm in 120 deg,
    0.8 kg at 2e6 N/m, 300-600 rpm: tau = T_e w/beta_m from 0.0596 to 0.119); written out
    with its units it reads back to itself."""
    m = spec.from_dict(tomllib.loads(spec.TEMPLATE), "template")
    T_e = 2 * math.pi * math.sqrt(0.8 / 2e6)
    assert m.taus == pytest.approx((T_e * 10 * math.pi / math.radians(120),
                                    T_e * 20 * math.pi / math.radians(120)), rel=1e-12)
    back = spec.from_dict(tomllib.loads(spec.as_toml(m)), "template")
    assert back == m


def test_every_missing_value_is_named_at_once():
    with pytest.raises(CamdynInputError) as exc:
        spec.from_dict({"kind": "machine", "follower": {"type": "oscillating-roller"}}, "m.toml")
    text = str(exc.value)
    for key in ("motion.angles", "speed.band", "cam.base_radius", "follower.pivot_distance",
                "motion.swing", "follower.arm_length", "follower.roller_radius",
                "train.inertia", "train.torsional_stiffness"):
        assert key in text
    assert text.startswith("m.toml: missing:") and "\n" not in text


def test_a_rocker_is_reduced_to_its_roller():
    """(2.55)-(2.57): stroke l Phi, mass J/l^2, stiffness k_t/l^2; its spring's rate and
    preload at the pivot are k/l^2 and F_0/l at the roller."""
    text = spec.TEMPLATE.replace('type = "translating-roller"', 'type = "oscillating-roller"')
    data = tomllib.loads(text)
    data["follower"].update(pivot_distance="100 mm", arm_length="80 mm")
    data["motion"] = {"swing": "18 deg", "angles": "120, 60, 120, 60"}
    data["train"] = {"inertia": "0.0039 kg m^2", "torsional_stiffness": "12800 N m/rad"}
    data["spring"] = {"rate": "6.4 N m/rad", "preload": "0.8 N m"}
    m = spec.from_dict(data)
    assert m.output_stroke == pytest.approx(0.08 * math.radians(18), rel=1e-15)
    assert m.output_mass == pytest.approx(0.0039 / 0.08**2, rel=1e-15)
    assert m.output_stiffness == pytest.approx(12800 / 0.08**2, rel=1e-15)
    assert m.output_spring_rate == pytest.approx(6.4 / 0.08**2, rel=1e-15)
    assert m.output_spring_preload == pytest.approx(0.8 / 0.08, rel=1e-15)


@pytest.mark.parametrize("change, words", [
    (("cam", "base_radius", "1e-9 m"), "cam.base_radius=1e-09 is out of range"),
    (("follower", "roller_radius", "50 mm"), "must be below cam.base_radius"),
    (("motion", "angles", "120, 60, 100, 60"), "motion.angles"),
    (("train", "torsional_stiffness", "10 N m/rad"), "train.torsional_stiffness"),
    (("cam", "materials", "steel"), "two materials"),
    (("motion", "laws", "nope"), "unknown cam law 'nope'"),
    (("speed", "band", "0.0001:1 rpm"), "the speeds must lie in"),
    (("follower", "colour", "red"), "follower.colour is not a key of [follower]")])
def test_a_bad_machine_is_refused_in_one_line(change, words):
    data = tomllib.loads(spec.TEMPLATE)
    table, key, value = change
    data[table][key] = value
    with pytest.raises(CamdynInputError, match=words.replace("[", r"\[").replace("]", r"\]")) as exc:
        spec.from_dict(data, "m.toml")
    assert "\n" not in str(exc.value)
