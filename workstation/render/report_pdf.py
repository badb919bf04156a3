"""The report as PDF: the HTML page printed by headless Chromium (``--print-to-pdf``).

Chromium is found on the PATH (``chromium``, ``chromium-browser``, ``google-chrome``,
``google-chrome-stable``) or at the path in the ``WS_CHROMIUM`` environment variable. It prints
with a throw-away profile, no header or footer, and the page's own print styles (A4, the
summary alone on its first page).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from workstation.core.errors import MissingDependencyError, StageError

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
INSTALL_HINT = ("install Chromium (Debian/Ubuntu: apt-get install -y chromium; `make test` installs it as root) "
                "or set WS_CHROMIUM to the browser's executable; or write the report as .html")


def find_chromium() -> str | None:
    """The Chromium executable: ``WS_CHROMIUM`` when it names an executable file, else the
    first of :data:`BROWSERS` on the PATH; None when there is none."""
    env = os.environ.get("WS_CHROMIUM")
    if env and Path(env).is_file() and os.access(env, os.X_OK):
        return env
    return next((shutil.which(b) for b in BROWSERS if shutil.which(b)), None)


def require_chromium() -> str:
    """:func:`find_chromium`, or a clear error naming what to install."""
    exe = find_chromium()
    if exe is None:
        raise MissingDependencyError("chromium", "writing the report as PDF", INSTALL_HINT)
    return exe


def print_to_pdf(html_path, pdf_path, timeout_s: float = 300.0) -> Path:
    """Print the page ``html_path`` to ``pdf_path`` with headless Chromium.

    Raises
    ------
    MissingDependencyError
        When no Chromium is found.
    StageError
        When Chromium fails, times out or writes no PDF.
    """
    exe = require_chromium()
    pdf = Path(pdf_path).absolute()
    with tempfile.TemporaryDirectory(prefix="ws-chromium-") as profile:
        cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
               f"--user-data-dir={profile}", "--no-pdf-header-footer", f"--print-to-pdf={pdf}",
               Path(html_path).absolute().as_uri()]
        try:
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            raise StageError("report", f"{exe} did not print the PDF within {timeout_s:.0f} s") from None
    if r.returncode != 0 or not pdf.is_file() or pdf.read_bytes()[:5] != b"%PDF-":
        tail = (r.stderr or "").strip().splitlines()[-3:]
        raise StageError("report", f"{exe} wrote no PDF (exit status {r.returncode})", " | ".join(tail) or None)
    return pdf
