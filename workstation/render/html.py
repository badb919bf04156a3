"""Pieces of self-contained HTML pages: images inlined as base64 PNG, escaped values, tables.

Used by the work-folder report (:mod:`workstation.render.report`) and the QC report
(:mod:`workstation.qc.report`).
"""

from __future__ import annotations

import base64
import html
import io
import json

import numpy as np


def png_b64(img: np.ndarray) -> str:
    """An (h, w[, 3|4]) uint8 image as base64 PNG text."""
    from PIL import Image as PILImage

    buf = io.BytesIO()
    PILImage.fromarray(np.asarray(img, dtype=np.uint8)).save(buf, format="PNG", optimize=True)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def fig_b64(fig) -> str:
    """A matplotlib figure as base64 PNG text (the figure is closed)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    import matplotlib.pyplot as plt

    plt.close(fig)
    return base64.b64encode(buf.getvalue()).decode("ascii")


def img(b64: str, alt: str) -> str:
    """A figure element showing base64 PNG ``b64`` with ``alt`` as caption."""
    return f'<figure><img alt="{html.escape(alt)}" src="data:image/png;base64,{b64}"><figcaption>{html.escape(alt)}</figcaption></figure>'


def fmt(v) -> str:
    """A value as short escaped HTML text (floats to 6 significant digits, long lists cut)."""
    if isinstance(v, float):
        return f"{v:.6g}"
    if isinstance(v, (list, tuple)) and len(v) > 8:
        return html.escape(json.dumps(v[:8])[:-1] + ", ...]")
    if isinstance(v, (dict, list, tuple)):
        s = json.dumps(v, default=str)
        return html.escape(s if len(s) < 300 else s[:300] + "...")
    return html.escape(str(v))


def table(rows, header=("", "")) -> str:
    """An HTML table of ``rows`` (sequences of values) under ``header``."""
    h = "".join(f"<th>{html.escape(str(c))}</th>" for c in header)
    body = "".join("<tr>" + "".join(f"<td>{fmt(c)}</td>" for c in r) + "</tr>" for r in rows)
    return f"<table><thead><tr>{h}</tr></thead><tbody>{body}</tbody></table>"
