"""Progress in a real Jupyter kernel: a rich bar drawn as a widget, not lines on stderr.

A notebook of two cells runs in an IPython kernel started from this interpreter (a kernel spec
written to a temporary folder, so no installed kernel is needed) and executed by nbclient,
which stands in for the browser's widget manager: what rich draws into its
``ipywidgets.Output`` ends up in the notebook's widget state. The first cell filters ground
tile by tile (:func:`workstation.ground.tiles.ground_tiled`, one progress step a tile); the
second does it again with ``ipywidgets`` made unimportable, where rich cannot draw a bar.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

REPO = Path(__file__).resolve().parents[2]
DESCRIPTION = "ground (lowest) tile by tile"

SETUP = """
import numpy as np
from workstation.core import progress
from workstation.core.cloud import Cloud
from workstation.ground.methods import ground_filter
from workstation.ground.tiles import TileParams

rng = np.random.default_rng(0)
xy = rng.uniform(0, 150, (10000, 2))
cloud = Cloud(np.column_stack([xy, 0.05 * xy[:, 0] + rng.normal(0, 0.05, len(xy))]), crs="EPSG:32632")

def run():
    out = ground_filter(cloud, "lowest", tiles=TileParams(tile_points=1000, buffer=5.0))
    print("mode", progress.progress_mode(), "tiles", out.history[-1].params["tiles"],
          "ground", int((np.asarray(out.attrs["classification"]) == 2).sum()))
"""

NO_WIDGETS = """
import sys
sys.modules["ipywidgets"] = None  # import ipywidgets now raises ImportError
run()
"""


@pytest.fixture(scope="module")
def notebook(tmp_path_factory):
    """The executed notebook: cell 0 defines ``run``, cell 1 runs it, cell 2 runs it without
    ipywidgets."""
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import KernelManager

    tmp = tmp_path_factory.mktemp("kernel")
    spec = tmp / "kernels" / "ws-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "workstation test", "language": "python"}))
    km = KernelManager(kernel_name="ws-test", kernel_spec_manager=KernelSpecManager(kernel_dirs=[str(spec.parent)]))
    env = {k: v for k, v in os.environ.items() if k != "WS_PROGRESS"}  # the kernel chooses for itself
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO), env.get("PYTHONPATH")]))
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in (SETUP, "run()", NO_WIDGETS)])
    nbclient.NotebookClient(nb, km=km, timeout=60, store_widget_state=True).execute(cwd=str(tmp), env=env)
    return nb


def _stream(cell, name: str) -> str:
    return "".join(o["text"] for o in cell.outputs if o["output_type"] == "stream" and o["name"] == name)


def _widget_views(cell) -> list[str]:
    return [o["data"]["application/vnd.jupyter.widget-view+json"]["model_id"] for o in cell.outputs
            if o["output_type"] == "display_data" and "application/vnd.jupyter.widget-view+json" in o["data"]]


def test_a_rich_bar_widget_in_a_notebook(notebook):
    cell = notebook.cells[1]
    out = _stream(cell, "stdout")
    assert out.startswith("mode rich tiles ") and int(out.split()[3]) > 1, out
    views = _widget_views(cell)
    assert len(views) == 1, cell.outputs  # one bar, drawn in one Output widget
    state = notebook.metadata["widgets"]["application/vnd.jupyter.widget-state+json"]["state"][views[0]]
    assert state["model_name"] == "OutputModel"
    drawn = state["state"]["outputs"]
    assert len(drawn) == 1  # redrawn in place, not appended
    html = drawn[0]["data"]["text/html"]
    assert DESCRIPTION in html and "━" in html  # the label and the bar's line characters
    assert "100.0%" in drawn[0]["data"]["text/plain"]  # left finished, not at its last timed redraw
    assert DESCRIPTION not in _stream(cell, "stderr")


def test_plain_progress_without_ipywidgets(notebook):
    cell = notebook.cells[2]
    assert _stream(cell, "stdout").startswith("mode plain tiles "), cell.outputs
    assert _widget_views(cell) == []
    assert "ipywidgets" not in _stream(cell, "stderr")  # no warning from rich asking for it
