"""Minimal Box spaces with Gymnasium's shape and behaviour, for when gymnasium is absent.

Debian ships no gymnasium; with it installed, HarvestEnv uses gymnasium.spaces.Box instead.
"""

import numpy as np


class Box:
    """A box in R^n: low <= x <= high elementwise (gymnasium.spaces.Box's subset)."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(int(n) for n in shape)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("Box: low above high")
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        """Uniform where bounded on both sides; normal where unbounded (as gymnasium)."""
        low, high = self.low.astype(np.float64), self.high.astype(np.float64)
        out = np.empty(self.shape, dtype=np.float64)
        bounded = np.isfinite(low) & np.isfinite(high)
        out[bounded] = self._rng.uniform(low[bounded], high[bounded])
        unbounded = ~bounded
        out[unbounded] = self._rng.normal(size=int(unbounded.sum()))
        return out.astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype, "same_kind")
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"
