"""Spaces of the environments (asperity.envs): Gymnasium's Box where Gymnasium is installed, else
a small class with the same attributes and methods (low, high, shape, dtype, sample, contains,
seed), so that the environments need no Gymnasium and work unchanged with it."""

import numpy as np


class _Box:
    """A box in R^shape: low <= x <= high elementwise (Gymnasium's Box, the parts used here)."""

    def __init__(self, low, high, shape=None, dtype=np.float64, seed=None):
        self.dtype = np.dtype(dtype)
        shape = tuple(shape) if shape is not None else np.shape(low)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("Box: low must be <= high")
        self.shape = shape
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed=None):
        """Reseeds sample(); returns [seed] as Gymnasium does."""
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        """A uniform point of the box (every bound here is finite)."""
        return self.np_random.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x):
        """Whether x has this shape and lies within the bounds."""
        x = np.asarray(x)
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype, "same_kind")
                and bool(np.all(x >= self.low) and np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __eq__(self, other):
        return (isinstance(other, _Box) and self.shape == other.shape
                and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))

    def __repr__(self):
        return "Box(%s, %s, %s, %s)" % (self.low.min(), self.high.max(), self.shape, self.dtype)


try:  # Gymnasium's own class where it is installed: wrappers and checkers then accept ours.
    from gymnasium.spaces import Box  # noqa: F401
except ImportError:
    Box = _Box
