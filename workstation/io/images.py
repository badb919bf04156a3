"""Photos of a reconstruction's images as arrays."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError


def read_image(image, root=None) -> np.ndarray:
    """Pixels of an oriented image (a :class:`workstation.core.products.Image`) in RGB order.

    The file is ``image.path`` (else ``image.name``), relative to ``root`` unless absolute. It
    is read unchanged in bit depth: (h, w, 3) for a grey image (its channel repeated), a colour
    image's channels reversed from OpenCV's BGR(A) to RGB, an alpha channel dropped.

    Raises
    ------
    InvalidInputError
        The file does not exist or cannot be decoded.
    """
    p = Path(image.path) if image.path else Path(image.name)
    if root is not None and not p.is_absolute():
        p = Path(root) / p
    if not p.exists():
        raise InvalidInputError("image file not found", "give the image folder (--images)", path=p)
    import cv2

    a = cv2.imread(str(p), cv2.IMREAD_UNCHANGED)
    if a is None:
        raise InvalidInputError("could not read image", path=p)
    if a.ndim == 2:
        a = np.repeat(a[:, :, None], 3, axis=2)
    return a[:, :, 2::-1] if a.shape[2] >= 3 else a


__all__ = ["read_image"]
