"""One harmonic engine: Fourier coefficients of periodic planar signals.

A complex signal x(θ) sampled at N evenly spaced angles over one revolution is written
x(θ) = Σ_k c_k·e^{ikθ}; c_k (k > 0) is its **forward** part of order k (turning with the
crank) and c_{−k} its **backward** part. The second derivative with respect to time at
constant speed ω multiplies c_k by −(kω)², so a position signal gives the acceleration's
coefficients exactly, with no finite differences.
"""

import warnings

import numpy as np

__all__ = ["SamplingWarning", "fourier", "forward_backward", "check_sampling", "synthesize"]

#: spectral content above a quarter of the samples, relative to the largest, that we accept
_ALIASING_TOLERANCE = 1e-9


class SamplingWarning(UserWarning):
    """The sampling is too coarse for the orders asked for."""


def fourier(signal):
    """Coefficients c_k of ``signal`` (…, N) for k = 0..N−1 (negative k wrap to N−|k|)."""
    return np.fft.fft(signal, axis=-1) / signal.shape[-1]


def forward_backward(coefficients, orders):
    """Forward (c_k) and backward (c_{−k}) coefficients for each k in ``orders``."""
    n = coefficients.shape[-1]
    orders = np.asarray(orders)
    return coefficients[..., orders % n], coefficients[..., (-orders) % n]


def check_sampling(acceleration_coefficients, max_order, label=""):
    """Warn when the highest orders still carry energy, so lower orders may be aliased.

    Parameters
    ----------
    acceleration_coefficients : ndarray, shape (n_masses, N)
        coefficients of each mass's inertia force (any unit). Aliasing is linear, so the
        error of a sum is bounded by the sum of each mass's high-order content; checking
        the masses one by one keeps a well-cancelled resultant from looking under-sampled.
    max_order : int
        highest order the caller reports
    """
    n = acceleration_coefficients.shape[-1]
    magnitude = np.abs(np.atleast_2d(acceleration_coefficients))
    scale = magnitude.max(axis=-1).sum()
    if scale == 0.0:
        return True
    k = np.abs(np.fft.fftfreq(n, 1.0 / n))
    high = magnitude[:, k >= max(n // 4, max_order + 1)].max(axis=-1, initial=0.0).sum()
    if high > _ALIASING_TOLERANCE * scale:
        warnings.warn(
            f"{label}{n} samples are too few: orders above {n // 4} still carry "
            f"{high / scale:.1e} of the largest; raise --samples",
            SamplingWarning,
            stacklevel=3,
        )
        return False
    return True


def synthesize(coefficients, upsample=1):
    """Time signal from coefficients, optionally on a finer grid (zero padding)."""
    n = coefficients.shape[-1]
    if upsample == 1:
        return np.fft.ifft(coefficients * n, axis=-1)
    m = n * upsample
    padded = np.zeros(coefficients.shape[:-1] + (m,), complex)
    half = n // 2
    padded[..., :half] = coefficients[..., :half]
    padded[..., m - half + 1 :] = coefficients[..., half + 1 :]
    # the Nyquist term is split between +N/2 and −N/2 so the padded signal stays exact
    padded[..., half] = padded[..., m - half] = coefficients[..., half] / 2
    return np.fft.ifft(padded * m, axis=-1)
