"""Cam-law characteristics (App. 2): the table against independent computations."""
import json

import numpy as np
import pytest

from camdyn.derive import camlaws
from camdyn.thesis.theory.lawtable import properties
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import simulate


@pytest.mark.parametrize("key", sorted(camlaws.LAWS))
def test_peaks_against_a_fine_numerical_scan(key):
    """H'max, H''max/min and max H'H'' of the table against the law sampled on 200001 points."""
    law, pr = camlaws.LAWS[key], properties(key)
    T = np.linspace(0.0, 1.0, 200001)[1:-1]
    H1, H2 = law.numeric(1)(T), law.numeric(2)(T)
    assert pr.H1_max == pytest.approx(H1.max(), abs=1e-8)
    if law.amplitude is not None:
        assert pr.H2_max == pytest.approx(H2.max(), abs=1e-6)
        assert pr.H2_min == pytest.approx(H2.min(), abs=1e-6)
        assert pr.torque_max == pytest.approx((H1 * H2).max(), rel=2e-5)  # scan spacing 5e-6
        assert pr.T_torque_max == pytest.approx(T[np.argmax(H1 * H2)], abs=1e-4)


@pytest.mark.parametrize("key,window,tol", [
    ("cycloidal", (0.05, 0.15), 0.03), ("3-4-5", (0.05, 0.15), 0.03),
    ("simple-harmonic", (0.05, 0.15), 0.03), ("parabolic", (0.05, 0.15), 0.03),
    ("4-5-6-7", (0.05, 0.15), 0.03), ("uniform", (0.05, 0.15), 0.03),
    # interior jumps of H'''' make the next order large at these laws: smaller tau
    ("modified-sine", (0.025, 0.04), 0.12), ("modified-trapezoid", (0.025, 0.04), 0.12),
])
def test_residual_envelope_against_simulation(key, window, tol):
    """The one-DOF residual amplitude of the compiled model stays below C tau^p and reaches
    it where the jumps' phases add (the envelope is a tau -> 0 limit: the next order is
    allowed for in ``tol``)."""
    pr = properties(key)
    taus = np.linspace(*window, 120)
    U0 = np.array([residual(simulate("one_dof", {"tau": t}, 1.5, "dp54", rtol=1e-11, law=key)).U0
                   for t in taus])
    ratio = U0 / (pr.residual_coeff * taus**pr.residual_order)
    assert ratio.max() == pytest.approx(1.0, abs=tol)


def test_jerk_is_an_impulse_where_the_acceleration_jumps():
    assert properties("parabolic").jerk_half is None
    assert properties("simple-harmonic").jerk_0 is None and properties("simple-harmonic").jerk_half is not None
    assert properties("uniform").torque_max is None


def test_theta_is_checked():
    with pytest.raises(ValueError, match="theta=0.7 is outside"):
        properties("modified-sine", 0.7)
    with pytest.raises(ValueError, match="no shape parameter"):
        properties("cycloidal", 0.2)


def test_json_has_no_infinity():
    """The uniform law's H'' is an impulse at both ends (H''max = inf in the table); its JSON
    row printed the token Infinity, which is not JSON.  Every row dumps with allow_nan=False,
    the impulse as null."""
    for key in sorted(camlaws.LAWS):
        json.dumps(properties(key).as_dict(), allow_nan=False)
    d = properties("uniform").as_dict()
    assert d["H2_max"] is None and d["H2_min"] is None and d["H1_max"] == 1.0


# The characteristic values of the motion laws as VDI 2143 Blatt 1 tabulates them (and the
# cam handbooks after it, e.g. Norton, Cam Design and Manufacturing Handbook): C_v = H'max,
# C_a = |H''|max, C_j = |H'''|max (None: an impulse, the acceleration jumps), C_Mdyn =
# max H'H''.  Printed to 3-4 figures; the modified sine at its usual theta = 1/8.
VDI_2143 = {
    "parabolic": (2.0, 4.0, None, 8.0),
    "simple-harmonic": (1.571, 4.935, None, 3.876),
    "cycloidal": (2.0, 6.283, 39.48, 8.162),
    "3-4-5": (1.875, 5.774, 60.0, 6.694),
    "4-5-6-7": (2.188, 7.513, 52.5, 10.75),
    "modified-trapezoid": (2.0, 4.888, 61.43, 8.09),
    "modified-sine": (1.760, 5.528, 69.47, None),
}


@pytest.mark.parametrize("key", sorted(VDI_2143))
def test_characteristic_values_of_vdi_2143(key):
    """C_v, C_a, C_j and C_Mdyn of `camdyn laws` against VDI 2143's table, to the last figure
    printed there (relative 5e-4)."""
    cv, ca, cj, cm = VDI_2143[key]
    pr = properties(key, 0.125 if key == "modified-sine" else None)
    assert pr.H1_max == pytest.approx(cv, rel=5e-4)
    assert max(pr.H2_max, -pr.H2_min) == pytest.approx(ca, rel=5e-4)
    jerks = [pr.jerk_0, pr.jerk_half, pr.jerk_1]
    if cj is None:
        assert None in jerks
    else:
        assert max(abs(j) for j in jerks) == pytest.approx(cj, rel=5e-4)
    if cm is not None:
        assert pr.torque_max == pytest.approx(cm, rel=5e-4)
