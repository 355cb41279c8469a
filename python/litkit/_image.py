# SPDX-License-Identifier: MIT
"""litkit.Image: the rendered picture, a NumPy array that shows itself.

An ndarray subclass, so that everything NumPy does with the (height, width, 3)
uint8 array still works, plus ``_repr_png_`` so that Jupyter and IPython
display it inline as a picture.
"""

import numpy as np

from . import _litkit


class Image(np.ndarray):
    """Row-major 8-bit RGB, row 0 at the top: ``img[y, x]`` is ``(r, g, b)``."""

    def _repr_png_(self):
        # Only what is still a picture shows as one: a slice of a row or an
        # arithmetic result in float falls back to the array's text.
        if self.dtype != np.uint8 or self.ndim != 3 or self.shape[2] != 3 or 0 in self.shape:
            return None
        return _litkit.encode_png(np.ascontiguousarray(self))

    def to_png(self):
        """The PNG file bytes of the picture (the same encoder as ``litkit render``)."""
        return _litkit.encode_png(np.ascontiguousarray(self, dtype=np.uint8))

    def save(self, path):
        """Writes the picture as a PNG file."""
        data = self.to_png()
        with open(path, "wb") as file:
            file.write(data)
