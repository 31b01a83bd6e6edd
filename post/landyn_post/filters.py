"""Channel-frequency-class (CFC) filters of SAE J211-1 / ISO 6487 for acceleration channels.

A CFC filter is a 2-pole Butterworth low-pass run forward and then backward over the signal
(scipy.signal.filtfilt), which makes it phaseless with a 4-pole magnitude response. J211-1
(Appendix C) designs the 2-pole stage with the corner frequency 2.0775 x CFC Hz (bilinear
transform with pre-warping, which scipy.signal.butter with ``fs`` does), so that the cascade is
flat to CFC Hz and -3 dB near 1.65 x CFC. Classes: CFC 60 (structural response, 100 Hz),
CFC 180 (300 Hz) and CFC 600 (1000 Hz).

The sampling rate must put the design frequency below the Nyquist frequency; J211 recommends
sampling at 10 x the -3 dB frequency or faster, which ``cfc_warning`` reports otherwise.
"""
from __future__ import annotations

import numpy as np

from .schema import LandynPostError

CFC_CLASSES = (60, 180, 600)
DESIGN_FACTOR = 2.0775     #: design corner frequency / CFC (SAE J211-1, Appendix C)
F3DB_FACTOR = 1.65         #: approximate -3 dB frequency of the cascade / CFC
DESCRIPTION = "SAE J211-1 / ISO 6487, phaseless 4-pole Butterworth"


def _uniform(t: np.ndarray) -> tuple[np.ndarray, float, bool]:
    dt = float(np.median(np.diff(t)))
    if not dt > 0:
        raise LandynPostError("CFC filter: the time samples are not increasing")
    uniform = bool(np.allclose(np.diff(t), dt, rtol=1e-6, atol=0.0))
    return t, dt, uniform


def cfc_filter(t: np.ndarray, y: np.ndarray, cfc: int) -> np.ndarray:
    """y (samples at times t, along axis 0) filtered with channel frequency class `cfc`.

    Non-uniform samples (e.g. a shorter last interval when the run stops at rest) are filtered on a
    uniform grid of the median interval and interpolated back. Raises LandynPostError for an
    unknown class or a sampling rate too low for it."""
    from scipy import signal

    if cfc not in CFC_CLASSES:
        raise LandynPostError(f"CFC {cfc}: not a channel frequency class (use one of {CFC_CLASSES})")
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    _, dt, uniform = _uniform(t)
    fs = 1.0 / dt
    fd = DESIGN_FACTOR * cfc
    if fd >= 0.5 * fs:
        raise LandynPostError(f"CFC {cfc} needs samples faster than {2 * fd:.0f} Hz (design frequency {fd:.0f} Hz); "
                              f"the result is sampled at {fs:.0f} Hz: lower &output interval below {1 / (2 * fd):.2e} s")
    b, a = signal.butter(2, fd, btype="low", fs=fs)
    if uniform:
        return signal.filtfilt(b, a, y, axis=0)
    tu = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    yu = np.stack([np.interp(tu, t, y[:, k]) for k in range(y.shape[1])], axis=1) if y.ndim == 2 else np.interp(tu, t, y)
    fu = signal.filtfilt(b, a, yu, axis=0)
    if y.ndim == 2:
        return np.stack([np.interp(t, tu, fu[:, k]) for k in range(y.shape[1])], axis=1)
    return np.interp(t, tu, fu)


def cfc_warning(t: np.ndarray, cfc: int) -> str | None:
    """A note when the sampling rate is below J211's recommended 10 x the -3 dB frequency."""
    fs = 1.0 / float(np.median(np.diff(t)))
    need = 10.0 * F3DB_FACTOR * cfc
    if fs < need:
        return (f"sampled at {fs:.0f} Hz, below the {need:.0f} Hz J211 recommends for CFC {cfc} "
                "(peaks may be underestimated)")
    return None


def cfc_label(cfc: int) -> str:
    return f"CFC {cfc} ({DESCRIPTION})"
