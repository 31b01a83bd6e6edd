"""Correlation metrics against published examples, and the alignment rules (no LANDYN run needed).

Sprague & Geers: the analytic wave forms of L. E. Schwer, "Validation metrics for response
histories: perspectives and case studies", Engineering with Computers 23 (2007) 295-309, Sect. 4
("idealized" examples): the measured history m(t) = exp(-(t - tau)) sin(2 pi (t - tau)) for
t >= tau, 0 before, tau = 0.14 s, on 0 <= t <= 2 s; the computed histories shifted by +-0.1 s
(a +-20 % phase error: 36 deg of the 1 s period; tau = 0.24 and 0.04 s) and scaled by 1.2 (a +20 %
magnitude error). Published: for the +20 % magnitude example M = 20 %, P = 0, C = 20 %; for
the phase examples P = C = 19.5 % and |M| well under 1 %, leading and lagging alike.

ISO/TS 18571:2014: the same wave forms, rated by LANDYN's implementation and by the independent
reference implementation on PyPI, objective-rating-metrics 1.3 (VSI, TU Graz; run once outside
this project, because of its dependencies, on the identical arrays, 1 kHz, dt = 1e-3 s); its
values are quoted below with 16 digits and agree with ours to 1e-12. Independently of it, the
phase rating of a shift of n samples is (0.2 N - n) / (0.2 N) by definition, checked exactly.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from landyn_post import correlation as C
from landyn_post.schema import LandynPostError

T = np.arange(0.0, 2.0 + 5e-4, 1e-3)          # 2001 samples, dt = 1 ms


def schwer(tau: float, amp: float = 1.0) -> np.ndarray:
    x = T - tau
    return np.where(x >= 0, amp * np.exp(-x) * np.sin(2 * np.pi * x), 0.0)


M_REF = schwer(0.14)


@pytest.mark.parametrize("name, comp, m_exp, p_exp, c_exp, m_tol", [
    ("magnitude +20 %", schwer(0.14, 1.2), 0.200, 0.000, 0.200, 1e-12),
    ("phase lag 20 %", schwer(0.24), 0.0, 0.195, 0.195, 0.005),
    ("phase lead 20 %", schwer(0.04), 0.0, 0.195, 0.195, 0.005),
])
def test_sprague_geers_schwer_examples(name, comp, m_exp, p_exp, c_exp, m_tol):
    m, p, c = C.sprague_geers(T, comp, M_REF)
    assert m == pytest.approx(m_exp, abs=m_tol), name
    assert p == pytest.approx(p_exp, abs=5e-4), name
    assert c == pytest.approx(c_exp, abs=5e-4), name


def test_sprague_geers_identity_and_sign():
    assert C.sprague_geers(T, M_REF, M_REF) == pytest.approx((0.0, 0.0, 0.0), abs=1e-7)
    m, p, _ = C.sprague_geers(T, 0.8 * M_REF, M_REF)
    assert m == pytest.approx(-0.2, abs=1e-12) and p == pytest.approx(0.0, abs=1e-7)
    m, p, _ = C.sprague_geers(T, -M_REF, M_REF)          # opposite sign: phase error 1
    assert p == pytest.approx(1.0, abs=1e-7)


# objective-rating-metrics 1.3 ISO18571(reference, comparison, dt=1e-3): corridor, phase, magnitude,
# slope, overall (each with ndigits=-1)
TU_GRAZ = {
    "lead": (schwer(0.04), (0.5159775468865692, 0.7501249375312344, 0.9999999999999993, 0.9999999999999974,
                            0.7564160062608739)),
    "lag": (schwer(0.24), (0.5245588808254993, 0.7501249375312344, 0.9999999999999993, 0.9999999999999973,
                           0.759848539836446)),
    "magnitude +20 %": (schwer(0.14, 1.2), (0.8785724791945231, 1.0, 0.8964816566018292, 0.9, 0.9107253229981751)),
    "lag 0.05 s, magnitude -10 %": (schwer(0.19, 0.9), (0.7671611049690776, 0.8750624687656172, 0.950230750611725,
                                                        0.95, 0.8619230858630995)),
}


@pytest.mark.parametrize("name", list(TU_GRAZ))
def test_iso18571_against_reference_implementation(name):
    comp, expected = TU_GRAZ[name]
    r = C.iso18571(1e-3, comp, M_REF)
    got = (r.corridor, r.phase, r.magnitude, r.slope, r.overall)
    assert got == pytest.approx(expected, abs=1e-12), name


def test_iso18571_phase_rating_definition_and_grades():
    n = len(T)
    r = C.iso18571(1e-3, schwer(0.24), M_REF)          # 100 samples late
    assert r.shift == pytest.approx(0.1)
    assert r.phase == pytest.approx((0.2 * n - 100) / (0.2 * n), abs=1e-15)
    same = C.iso18571(1e-3, M_REF, M_REF)
    assert (same.corridor, same.phase, same.magnitude, same.slope, same.overall) == (1.0, 1.0, 1.0, 1.0, 1.0)
    assert same.grade == "excellent"
    assert [C.iso_grade(v) for v in (0.95, 0.94, 0.81, 0.80, 0.59, 0.58, 0.0)] == \
        ["excellent", "good", "good", "fair", "fair", "poor", "poor"]
    assert C.iso18571(1e-3, -M_REF, M_REF).grade == "poor"


def test_iso18571_rejects_a_zero_reference():
    with pytest.raises(LandynPostError, match="zero"):
        C.iso18571(1e-3, M_REF, np.zeros_like(M_REF))


def test_dtw_of_identical_curves_is_the_diagonal():
    x = np.sin(np.linspace(0, 6, 300))
    a, b = C.dtw_warp(x, x.copy())
    assert len(a) == 300 and np.array_equal(a, b)


def test_peak_metrics():
    m = C.metrics(T, 1.1 * schwer(0.15), M_REF, iso=False)
    assert m.peak_ref == pytest.approx(float(np.max(M_REF)))
    assert m.peak_error_pct == pytest.approx(10.0, abs=0.05)
    assert m.peak_time_error == pytest.approx(0.01, abs=1.5e-3)
    assert m.iso is None


def _pulse(t, t_td):
    """A touchdown-like pulse: zero before t_td, a damped rise after."""
    x = np.clip(t - t_td, 0, None)
    return 1e5 * (1 - np.exp(-x / 0.004)) * np.exp(-x / 0.08)


@pytest.mark.parametrize("shift", [0.008, -0.0035, 0.0])
def test_alignment_recovers_a_known_shift_within_one_sample(shift):
    dt = 2e-4                                          # reference samples; LANDYN's at 1e-4 s
    t = np.arange(0, 0.3, 1e-4)
    t_ref = np.arange(0, 0.3, dt)
    y = _pulse(t, 0.010)
    y_ref = _pulse(t_ref, 0.010 + shift)               # the reference touches down `shift` later
    td = C.touchdown_time(t, y) - C.touchdown_time(t_ref, y_ref)
    assert abs(td - (-shift)) <= dt
    xc = C.xcorr_shift(t, y, t_ref, y_ref, max_shift=0.02)
    assert abs(xc - (-shift)) <= dt


def test_touchdown_of_a_flat_channel_is_an_error():
    with pytest.raises(LandynPostError, match="does not change"):
        C.touchdown_time(T, np.ones_like(T))


def test_coverage_and_common_base():
    assert C.coverage(np.array([0.0, 0.003]), 0.0, 1.0) == pytest.approx(0.003)
    assert C.coverage(np.array([-1.0, 2.0]), 0.0, 1.0) == 1.0
    assert C.coverage(np.array([1.5, 2.0]), 0.0, 1.0) == 0.0
    tb = C.common_base(np.linspace(0, 1, 11), np.linspace(0.5, 2, 301))
    assert tb[0] == 0.5 and tb[-1] == 1.0 and math.isclose(tb[1] - tb[0], 0.005)
    with pytest.raises(LandynPostError, match="do not overlap"):
        C.common_base(np.array([0.0, 1.0]), np.array([2.0, 3.0]))
