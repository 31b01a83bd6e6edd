"""Correlation of a LANDYN time history with a reference: the same treatment of both signals
(CFC filtering, one uniform time base), alignment (touchdown, a given shift, cross-correlation),
and the standard correlation metrics.

Metrics, written from their published definitions (no maintained package fits, see below):

* peak values, times of peak, peak error and rms deviation;
* Sprague & Geers (2004) magnitude M, phase P and comprehensive error C, as presented by
  Schwer (2007), "Validation metrics for response histories: perspectives and case studies",
  Engineering with Computers 23:295-309, eqs. (1)-(5): with the measured (reference) m(t) and
  computed c(t), I_mm = int m^2, I_cc = int c^2, I_mc = int m c (trapezoidal rule),
  M = sqrt(I_cc / I_mm) - 1, P = arccos(I_mc / sqrt(I_mm I_cc)) / pi, C = sqrt(M^2 + P^2);
* ISO/TS 18571:2014 objective rating of a non-ambiguous signal (reference T, comparison C,
  both sampled at 10 kHz on the evaluation interval, N samples):
  corridor rating Z (inner/outer half-widths a0 = 0.05 and b0 = 0.5 times max|T|, exponent
  kz = 2, averaged over the samples); phase rating E_P from the shift n that maximises the
  cross-correlation within eps_p N (eps_p = 0.2; left shifts first, the smallest shift wins a
  tie), E_P = ((eps_p N - n) / (eps_p N))^kp, kp = 1; magnitude rating E_M from the error
  ||C_w - T_w||_1 / ||T_w||_1 of the phase-shifted curves warped by dynamic time warping
  (Sakoe-Chiba band 10 % of N), E_M = ((eps_m - e) / eps_m)^km, eps_m = 0.5, km = 1; slope
  rating E_S from the same error of the derivatives of the shifted curves (central differences
  smoothed by a 9-point moving average, shrinking windows at the ends), E_S = (eps_s - e) / eps_s,
  eps_s = 2; overall R = 0.4 Z + 0.2 E_P + 0.2 E_M + 0.2 E_S; grades: excellent R > 0.94, good
  0.80 < R <= 0.94, fair 0.58 < R <= 0.80, poor R <= 0.58.

Why not a package: PyPI's objective-rating-metrics 1.3 (TU Graz) implements ISO/TS 18571 but
needs dtwalign (last release 2022, which pulls numba, seaborn and networkx) plus pandas, shapely,
jsonschema and pyyaml, against this project's pinned numpy; it also takes only equal-length
10 kHz arrays and builds the full N x N distance matrix (3.2 GB for 2 s at 10 kHz). It serves
here as an independent check: tests/test_correlation.py compares the four ratings with its
values on the same curves. No maintained Python package for Sprague & Geers exists.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .schema import LandynPostError

ISO_RATE = 1.0e4                 #: ISO/TS 18571 sampling rate [Hz]
ISO_GRADES = ((0.94, "excellent"), (0.80, "good"), (0.58, "fair"), (-math.inf, "poor"))
TOUCHDOWN_FRACTION = 0.05        #: touchdown rule: first |y - y(t0)| >= 5 % of its largest value
RESAMPLING = "linear interpolation onto one uniform time base over the common time range"


# ------------------------------------------------------------------------------ resampling and filtering

def common_base(t_a: np.ndarray, t_b: np.ndarray, dt: float | None = None) -> np.ndarray:
    """Uniform time base over the overlap of two time ranges [s]; step dt [s] or, by default, the
    finer of the two median sample intervals."""
    t0, t1 = max(t_a[0], t_b[0]), min(t_a[-1], t_b[-1])
    if not t1 > t0:
        raise LandynPostError(f"the time ranges do not overlap ({t_a[0]:g}..{t_a[-1]:g} s and "
                              f"{t_b[0]:g}..{t_b[-1]:g} s)")
    if dt is None:
        dt = float(min(np.median(np.diff(t_a)), np.median(np.diff(t_b))))
    n = int(round((t1 - t0) / dt)) + 1
    return np.linspace(t0, t1, max(n, 2))


def coverage(t_ref: np.ndarray, t0: float, t1: float) -> float:
    """Share (0..1) of the interval [t0, t1] [s] inside the reference's time range."""
    if not t1 > t0:
        return 1.0
    lo, hi = max(t0, float(t_ref[0])), min(t1, float(t_ref[-1]))
    return max(0.0, hi - lo) / (t1 - t0)


# ------------------------------------------------------------------------------ alignment

def touchdown_time(t: np.ndarray, y: np.ndarray, fraction: float = TOUCHDOWN_FRACTION) -> float:
    """Touchdown instant of a channel [s]: the first time |y - y(t0)| reaches `fraction` of its
    largest value, linearly interpolated between samples. LandynPostError for a flat channel."""
    d = np.abs(np.asarray(y, float) - float(y[0]))
    top = float(np.max(d))
    if not top > 0:
        raise LandynPostError("touchdown alignment: the alignment channel does not change")
    level = fraction * top
    k = int(np.argmax(d >= level))
    if k == 0:
        return float(t[0])
    f = (level - d[k - 1]) / (d[k] - d[k - 1])
    return float(t[k - 1] + f * (t[k] - t[k - 1]))


def xcorr_shift(t: np.ndarray, y: np.ndarray, t_ref: np.ndarray, y_ref: np.ndarray, max_shift: float) -> float:
    """Shift [s] to add to the reference's time so that it best matches y (largest Pearson
    correlation on y's uniform time base, whole samples, |shift| <= max_shift [s])."""
    dt = float(np.median(np.diff(t)))
    tb = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    a = np.interp(tb, t, y)
    nmax = int(max_shift / dt)
    best, best_k = -math.inf, 0
    for k in sorted(range(-nmax, nmax + 1), key=abs):
        b = np.interp(tb - k * dt, t_ref, y_ref, left=np.nan, right=np.nan)
        ok = np.isfinite(b)
        if ok.sum() < 3 or np.ptp(b[ok]) == 0 or np.ptp(a[ok]) == 0:
            continue
        r = float(np.corrcoef(a[ok], b[ok])[0, 1])
        if r > best + 1e-12:
            best, best_k = r, k
    if best == -math.inf:
        raise LandynPostError("cross-correlation alignment: no overlap with variation within the bound")
    return best_k * dt


# ------------------------------------------------------------------------------ metrics

def peak(t: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """(value of the largest |y| with its sign, its time [s])."""
    k = int(np.argmax(np.abs(y)))
    return float(y[k]), float(t[k])


def sprague_geers(t: np.ndarray, c: np.ndarray, m: np.ndarray) -> tuple[float, float, float]:
    """Sprague & Geers (M, P, C) of the computed c against the measured (reference) m."""
    imm, icc, imc = (float(np.trapezoid(u * v, t)) for u, v in ((m, m), (c, c), (m, c)))
    if not (imm > 0 and icc > 0):
        return (math.nan, math.nan, math.nan)
    mag = math.sqrt(icc / imm) - 1.0
    ph = math.acos(max(-1.0, min(1.0, imc / math.sqrt(imm * icc)))) / math.pi
    return mag, ph, math.hypot(mag, ph)


@dataclass
class IsoRating:
    """ISO/TS 18571 ratings (0..1), the phase shift found [s] and the grade."""
    corridor: float
    phase: float
    magnitude: float
    slope: float
    overall: float
    shift: float
    grade: str


def iso_grade(r: float) -> str:
    return next(name for lim, name in ISO_GRADES if r > lim)


def _iso_corridor(c: np.ndarray, t: np.ndarray, a0=0.05, b0=0.5, kz=2.0) -> float:
    tn = float(np.max(np.abs(t)))
    inner, outer = a0 * tn, b0 * tn
    d = np.abs(c - t)
    z = ((outer - d) / (outer - inner)) ** kz
    z = np.where(d < inner, 1.0, np.where(d > outer, 0.0, z))
    return float(np.mean(z))


def _iso_shift(c: np.ndarray, t: np.ndarray, eps_p: float = 0.2) -> int:
    """Sample shift n (> 0: the comparison is late, compared as c[n:] with t[:-n]) of largest
    cross-correlation within eps_p N; left shifts tried first, the smallest wins a tie."""
    n = len(t)
    best, best_n = np.corrcoef(t, c)[0, 1], 0
    for k in range(1, int(math.floor(n * eps_p)) + 1):
        for sign, (u, v) in ((1, (t[:-k], c[k:])), (-1, (t[k:], c[:-k]))):
            r = np.corrcoef(u, v)[0, 1]
            if r > best:
                best, best_n = r, sign * k
    return best_n


def dtw_warp(x: np.ndarray, y: np.ndarray, window: float = 0.1) -> tuple[np.ndarray, np.ndarray]:
    """x and y warped onto their dynamic-time-warping path (squared distance, steps (1,0), (0,1),
    (1,1) of weight 1, Sakoe-Chiba band of ceil(window * N) - 1 samples). Each row of the band is
    one cumulative minimum: D[i, j] = S[j] + min_{k<=j} (min(D[i-1,k], D[i-1,k-1]) - S[k-1]) with
    S the running sum of the row's costs."""
    n, m = len(x), len(y)
    w = max(int(math.ceil(window * max(n, m))) - 1, abs(n - m))
    inf = math.inf
    prev = np.full(m + 1, inf)           # D[i-1, j-1] at index j (index 0: column -1)
    prev[0] = 0.0
    band_lo = np.empty(n, dtype=np.int64)
    rows = []
    for i in range(n):
        lo, hi = max(0, i - w), min(m - 1, i + w)
        band_lo[i] = lo
        cost = (x[i] - y[lo:hi + 1]) ** 2
        up = prev[lo + 1:hi + 2]                      # D[i-1, j]
        diag = prev[lo:hi + 1]                        # D[i-1, j-1]
        best_prev = np.minimum(up, diag)
        s = np.cumsum(cost)
        s_before = np.concatenate(([0.0], s[:-1]))
        row = s + np.minimum.accumulate(best_prev - s_before)
        cur = np.full(m + 1, inf)
        cur[lo + 1:hi + 2] = row
        left = np.concatenate(([inf], row[:-1]))      # D[i, j-1]
        mv = np.where(diag <= np.minimum(up, left), 0, np.where(up <= left, 1, 2)).astype(np.int8)
        rows.append(mv)
        prev = cur
    i, j, path = n - 1, m - 1, []
    while i >= 0 and j >= 0:
        path.append((i, j))
        mv = rows[i][j - band_lo[i]]
        if mv == 0:
            i, j = i - 1, j - 1
        elif mv == 1:
            i -= 1
        else:
            j -= 1
    p = np.array(path[::-1])
    return x[p[:, 0]], y[p[:, 1]]


def _smoothed_derivative(y: np.ndarray, dt: float) -> np.ndarray:
    d = np.gradient(y, dt)
    n = len(d)
    k = np.arange(n)
    h = np.minimum(4, np.minimum(k, n - 1 - k))
    cs = np.concatenate(([0.0], np.cumsum(d)))
    return (cs[k + h + 1] - cs[k - h]) / (2 * h + 1)


def iso18571(dt: float, cmp: np.ndarray, ref: np.ndarray) -> IsoRating:
    """ISO/TS 18571 rating of `cmp` against `ref`, both uniformly sampled with step dt [s] on the
    evaluation interval (the standard samples at 10 kHz; see iso18571_on)."""
    c, t = np.asarray(cmp, float), np.asarray(ref, float)
    if len(c) != len(t) or len(t) < 10:
        raise LandynPostError("ISO 18571: the curves need the same, and at least 10, samples")
    if not np.max(np.abs(t)) > 0:
        raise LandynPostError("ISO 18571: the reference is zero on the evaluation interval")
    z = _iso_corridor(c, t)
    n_eps = _iso_shift(c, t)
    lim = 0.2 * len(t)
    e_p = 1.0 if n_eps == 0 else (0.0 if abs(n_eps) >= lim else (lim - abs(n_eps)) / lim)
    if n_eps > 0:
        cs, ts = c[n_eps:], t[:-n_eps]
    elif n_eps < 0:
        cs, ts = c[:n_eps], t[-n_eps:]
    else:
        cs, ts = c, t
    cw, tw = dtw_warp(cs, ts)
    e_mag = float(np.sum(np.abs(cw - tw)) / np.sum(np.abs(tw)))
    e_m = 1.0 if e_mag == 0 else max(0.0, (0.5 - e_mag) / 0.5)
    dc, dtr = _smoothed_derivative(cs, dt), _smoothed_derivative(ts, dt)
    e_slope = float(np.sum(np.abs(dc - dtr)) / np.sum(np.abs(dtr))) if np.any(dtr) else math.inf
    e_s = 1.0 if e_slope <= 0 else max(0.0, (2.0 - e_slope) / 2.0)
    r = 0.4 * z + 0.2 * e_p + 0.2 * e_m + 0.2 * e_s
    return IsoRating(z, e_p, e_m, e_s, r, n_eps * dt, iso_grade(r))


def iso18571_on(t: np.ndarray, cmp: np.ndarray, ref: np.ndarray) -> IsoRating:
    """ISO/TS 18571 rating of two signals on the time base t [s], resampled (linearly) at the
    standard's 10 kHz over [t[0], t[-1]]."""
    tb = np.arange(t[0], t[-1] + 0.5 / ISO_RATE, 1.0 / ISO_RATE)
    return iso18571(1.0 / ISO_RATE, np.interp(tb, t, cmp), np.interp(tb, t, ref))


@dataclass
class Metrics:
    """Per-channel metrics in the channel's unit; times in s."""
    peak: float
    t_peak: float
    peak_ref: float
    t_peak_ref: float
    peak_error_pct: float
    peak_time_error: float
    rms: float
    sg_m: float
    sg_p: float
    sg_c: float
    iso: IsoRating | None
    iso_note: str = ""


def metrics(t: np.ndarray, y: np.ndarray, y_ref: np.ndarray, iso: bool = True) -> Metrics:
    """All metrics of y against y_ref on their common time base t [s]."""
    p, tp = peak(t, y)
    pr, tpr = peak(t, y_ref)
    perr = 100.0 * (p - pr) / abs(pr) if pr != 0 else math.nan
    d = y - y_ref
    m, ph, c = sprague_geers(t, y, y_ref)
    rating, note = None, ""
    if iso:
        try:
            rating = iso18571_on(t, y, y_ref)
        except LandynPostError as exc:
            note = str(exc)
    return Metrics(p, tp, pr, tpr, perr, tp - tpr, float(np.sqrt(np.mean(d * d))), m, ph, c, rating, note)
