"""One harmonic engine: Fourier coefficients of periodic planar signals.

A complex signal x(θ) sampled at N evenly spaced angles over one revolution is written
x(θ) = Σ_k c_k·e^{ikθ}; c_k (k > 0) is its **forward** part of order k (turning with the
crank) and c_{−k} its **backward** part. The second derivative with respect to time at
constant speed ω multiplies c_k by −(kω)², so a position signal gives the acceleration's
coefficients exactly, with no finite differences. Any N works, odd or even.
"""

import math
import warnings

import numpy as np

from .errors import SamplingWarning
from .tolerances import ALIASING_TOLERANCE

__all__ = [
    "fourier",
    "orders_of",
    "forward_backward",
    "check_sampling",
    "synthesize",
    "periodic_derivative",
    "accelerations",
    "shifted",
    "resampled",
]


def fourier(signal):
    """Coefficients c_k of ``signal`` (…, N) for k = 0..N−1 (negative k wrap to N−|k|)."""
    return np.fft.fft(signal, axis=-1) / signal.shape[-1]


def orders_of(n):
    """The signed order of each of ``n`` coefficients: 0, 1, …, −2, −1."""
    return np.fft.fftfreq(n, 1.0 / n)


def forward_backward(coefficients, orders):
    """Forward (c_k) and backward (c_{−k}) coefficients for each k in ``orders``."""
    n = coefficients.shape[-1]
    orders = np.asarray(orders)
    return coefficients[..., orders % n], coefficients[..., (-orders) % n]


def check_sampling(position_coefficients, max_order, label=""):
    """Warn when the samples are too few for orders up to ``max_order``; return True if enough.

    Parameters
    ----------
    position_coefficients : ndarray, shape (n_masses, N)
        coefficients of each mass's mass-weighted position (any unit). Content of order j
        aliases onto order k = j − N (or N − j), where it is multiplied by k², never more than
        ``max_order``²; so the error it can cause is at most max_order² times the content
        left at the highest orders (above a quarter of the samples), compared with the largest
        inertia force k²·|c_k|. Rounding noise there stays at about 1e-16 however many samples
        are taken, so more samples never warn. Aliasing is linear, so the masses are checked
        one by one: a well-cancelled resultant does not look under-sampled.
    max_order : int
        highest order the caller reports
    label : str
        put in front of the warning's message (the engine's name)
    """
    magnitude = np.abs(np.atleast_2d(position_coefficients))
    n = magnitude.shape[-1]
    k = np.abs(orders_of(n))
    scale = (magnitude * k**2).max(axis=-1).sum()
    if scale == 0.0:
        return True
    band = max(n // 4, max_order + 1)
    high = magnitude[:, k >= band].max(axis=-1, initial=0.0).sum()
    excess = max_order**2 * high / scale
    if excess > ALIASING_TOLERANCE:
        warning = SamplingWarning(
            f"{label}{n} samples a revolution are too few for orders up to {max_order}: the "
            f"orders from {band} still carry {excess:.1e} of the largest inertia force; "
            "use more samples",
            samples=n,
            excess=excess,
        )
        warnings.warn(warning, stacklevel=3)
        return False
    return True


def synthesize(coefficients, upsample=1):
    """Time signal from coefficients, optionally on a grid ``upsample`` times finer (the
    coefficients padded with zeros: exact for a signal of orders below half the samples)."""
    n = coefficients.shape[-1]
    if upsample == 1:
        return np.fft.ifft(coefficients * n, axis=-1)
    m = n * upsample
    padded = np.zeros(coefficients.shape[:-1] + (m,), complex)
    half = n // 2
    if n % 2:
        padded[..., : half + 1] = coefficients[..., : half + 1]
        padded[..., m - half :] = coefficients[..., n - half :]
    else:
        padded[..., :half] = coefficients[..., :half]
        padded[..., m - half + 1 :] = coefficients[..., half + 1 :]
        # the Nyquist term is split between +N/2 and −N/2 so the padded signal stays exact
        padded[..., half] = padded[..., m - half] = coefficients[..., half] / 2
    return np.fft.ifft(padded * m, axis=-1)


def periodic_derivative(values, period=2 * math.pi):
    """d/dθ of samples of a periodic function over one ``period`` (last axis), spectrally."""
    n = values.shape[-1]
    k = orders_of(n) * (2 * math.pi / period)
    if n % 2 == 0:
        k[n // 2] = 0.0  # the Nyquist term has no sign; its derivative is dropped
    return np.fft.ifft(np.fft.fft(values, axis=-1) * 1j * k, axis=-1)


def accelerations(positions, omega):
    """d²x/dt² at constant speed ``omega`` (rad/s) of positions over one revolution (last
    axis), spectrally: exact for the band-limited motion."""
    k = orders_of(positions.shape[-1]) * omega
    return np.fft.ifft(np.fft.fft(positions, axis=-1) * -(k**2), axis=-1)


def shifted(values, shift_rad):
    """Samples of a real periodic signal (last axis: one revolution, evenly spaced from 0) on
    the same grid moved on by ``shift_rad``: x(θ_j + shift), by the shift theorem (exact for a
    signal of orders below half the samples, to rounding for one resolved by them)."""
    n = values.shape[-1]
    c = np.fft.rfft(values, axis=-1)
    return np.fft.irfft(c * np.exp(1j * np.arange(c.shape[-1]) * shift_rad), n=n, axis=-1)


def resampled(values, samples):
    """A real periodic signal (last axis: one revolution, evenly spaced from 0) on ``samples``
    evenly spaced angles instead: its orders below half the new samples kept (exact for a
    signal resolved by both grids)."""
    n = values.shape[-1]
    c = np.fft.rfft(values, axis=-1) * (samples / n)
    keep = samples // 2 + 1
    if c.shape[-1] < keep:
        c = np.concatenate([c, np.zeros(c.shape[:-1] + (keep - c.shape[-1],), complex)], axis=-1)
    return np.fft.irfft(c[..., :keep], n=samples, axis=-1)
