"""The quality report of a work folder: one self-contained HTML page (or its PDF) a client reads.

Everything is inlined (images as base64 PNG, no scripts, no external files), so the page can
be mailed or archived. Sections, in order:

* summary (:mod:`.report_summary`): the ``ws qc`` verdict when the folder holds one, what was
  processed, the key accuracies found in the records, the list of sections and figures;
* previews: rasters (ortho in colour, hillshades in grey, elevations as hillshades with a
  tint, density, slope, aspect, error maps) and the PNG images already in the folder;
* photogrammetry (:mod:`.report_sfm`): per SfM work folder the reprojection-error histogram
  and the cameras over the sparse cloud; GCP and check point residuals;
* registration (:mod:`.report_checks`): residuals of each registration record;
* ground: ground share of each ground-classified cloud and the points a filter changed
  against the cloud it came from, ground evaluations, confusion matrices found in JSON files;
* clouds (top view, with a legend of the classes present beside the image, not over it, and
  the class histogram) and meshes (iso view);
* steps: the work folder's stage records of ``ws sfm``, ``dense``, ``mesh``, ``colorize``,
  ``ortho``, in the order they ran, with their inputs and outputs;
* appendix, collapsed: the products, the stages and figures of ``run.json`` and the other JSON
  records, the clouds' ``history`` and the rasters' own metadata (so a folder of plain ``ws``
  outputs without any JSON still has its stages).

:func:`write_report` writes the page, or prints it to PDF with headless Chromium
(:mod:`.report_pdf`).
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.jsonutil import flatten
from workstation.core.log import get_logger
from workstation.io.textfile import read_text

from .html import fig_b64 as _fig_b64
from .html import fmt as _fmt
from .html import img as _img
from .html import png_b64 as _png_b64
from .html import table as _table
from .report_rasters import plot_raster, preview_rasters, raster_metas

log = get_logger(__name__)

CLOUD_EXT = (".las", ".laz", ".ply", ".pcd", ".xyz", ".txt", ".csv", ".pts", ".e57")
MESH_EXT = (".obj", ".glb", ".gltf", ".off")
RASTER_EXT = (".tif", ".tiff")


@dataclass(frozen=True)
class ReportParams:
    """Report settings.

    Attributes
    ----------
    render_size : (int, int)
        Size of each render in pixels.
    max_points : int
        Points drawn per cloud render (seeded random subset above; count).
    max_files : int
        Clouds, meshes and rasters rendered at most, each (count).
    max_depth : int
        Folder levels searched below the work folder (count).
    """

    render_size: tuple[int, int] = (640, 480)
    max_points: int = 2_000_000
    max_files: int = 12
    max_depth: int = 3


# Work-folder parts that hold tool internals, not products (COLMAP text models, depth maps).
_INTERNAL_DIRS = {"sparse", "stereo", "georef", "depth_maps", "normal_maps"}


def _find(root: Path, exts, max_depth: int) -> list[Path]:
    found = []
    for p in sorted(root.rglob("*")):
        if not p.is_file() or p.name.startswith("."):
            continue
        if _INTERNAL_DIRS & set(p.relative_to(root).parts[:-1]):
            continue
        if len(p.relative_to(root).parts) - 1 > max_depth:
            continue
        if p.suffix.lower() in exts:
            found.append(p)
    return found


def _stage_rows(doc) -> list[tuple]:
    """(stage, seconds, parameters, summary) rows from a run.json-like document."""
    rows = []
    stages = None
    if isinstance(doc, dict):
        for key in ("stages", "steps", "history"):
            if isinstance(doc.get(key), list):
                stages = doc[key]
                break
        if stages is None and isinstance(doc.get("stages"), dict):
            stages = [{"name": k, **(v if isinstance(v, dict) else {"value": v})} for k, v in doc["stages"].items()]
    elif isinstance(doc, list):
        stages = doc
    for s in stages or []:
        if not isinstance(s, dict):
            continue
        name = s.get("name") or s.get("stage") or "?"
        secs = s.get("seconds", s.get("time_s", s.get("duration")))
        params = s.get("params", s.get("parameters", {}))
        summary = s.get("summary", s.get("outputs", s.get("result", {})))
        rows.append((name, secs if secs is not None else "", params, summary))
    return rows


def work_steps(docs: dict, root: Path) -> list[tuple]:
    """Rows (stage, finished, seconds, record, inputs, outputs) of the stage records among
    ``docs`` (path -> parsed JSON; a record has a ``stage`` name and ``finished`` time, as
    :func:`workstation.io.reconstruction.stage_record` writes), in the order they finished.
    Paths inside ``root`` are shown relative to it.

    Examples
    --------
    >>> from pathlib import Path
    >>> docs = {Path("/w/dense/summary.json"): {"stage": "dense", "finished": "2026-01-02T10:00:00+00:00",
    ...          "seconds": 5.0, "inputs": {"image_dir": "/photos"}, "outputs": ["/w/dense/fused.ply"]},
    ...         Path("/w/summary.json"): {"stage": "sfm", "finished": "2026-01-02T09:00:00+00:00", "seconds": 2.0,
    ...          "inputs": {"image_dir": "/photos", "camera": None}, "outputs": []},
    ...         Path("/w/other.json"): {"points": 3}}
    >>> [(r[0], r[3], r[5]) for r in work_steps(docs, Path("/w"))]
    [('sfm', 'summary.json', ''), ('dense', 'dense/summary.json', 'dense/fused.ply')]
    """
    def rel(v) -> str:
        try:
            return str(Path(v).relative_to(root.absolute()))
        except (TypeError, ValueError):
            return str(v)

    rows = []
    for p, doc in docs.items():
        if not (isinstance(doc, dict) and isinstance(doc.get("stage"), str) and doc.get("finished")):
            continue
        ins = doc.get("inputs") if isinstance(doc.get("inputs"), dict) else {}
        outs = doc.get("outputs") if isinstance(doc.get("outputs"), list) else []
        rows.append((doc["stage"], str(doc["finished"]), doc.get("seconds", ""), rel(p.absolute()),
                     "; ".join(f"{k} {rel(v)}" for k, v in ins.items() if v is not None),
                     ", ".join(rel(o) for o in outs)))
    return sorted(rows, key=lambda r: r[1])


def _confusion(doc):
    """(matrix, labels) of the first confusion matrix found in a JSON document, or None."""
    stack = [doc]
    while stack:
        d = stack.pop()
        if isinstance(d, dict):
            for k, v in d.items():
                if "confusion" in str(k).lower() and isinstance(v, (list, dict)):
                    m = v.get("matrix") if isinstance(v, dict) else v
                    try:
                        a = np.asarray(m, dtype=float)
                    except (TypeError, ValueError):
                        a = None
                    if a is not None and a.ndim == 2 and a.shape[0] == a.shape[1] and a.shape[0] > 1:
                        labels = (v.get("labels") or v.get("classes")) if isinstance(v, dict) else None
                        labels = labels or d.get("labels") or d.get("classes")
                        if not isinstance(labels, list) or len(labels) != a.shape[0]:
                            labels = [str(i) for i in range(a.shape[0])]
                        return a, [str(x) for x in labels]
                stack.append(v)
        elif isinstance(d, list):
            stack.extend(x for x in d if isinstance(x, (dict, list)))
    return None


def _plot_confusion(m: np.ndarray, labels, title: str) -> str:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(1.2 + 0.8 * len(labels), 1 + 0.7 * len(labels)))
    ax.imshow(m, cmap="Blues")
    for i in range(m.shape[0]):
        for j in range(m.shape[1]):
            ax.text(j, i, f"{m[i, j]:.4g}", ha="center", va="center",
                    color="white" if m[i, j] > 0.6 * m.max() else "black", fontsize=9)
    ax.set_xticks(range(len(labels)), labels, rotation=45, ha="right")
    ax.set_yticks(range(len(labels)), labels)
    ax.set_xlabel("predicted")
    ax.set_ylabel("reference")
    ax.set_title(title)
    return _fig_b64(fig)


def _plot_class_histogram(codes: np.ndarray, title: str) -> str:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from workstation.core.classes import CLASS_COLORS, class_name

    k, n = np.unique(np.asarray(codes), return_counts=True)
    fig, ax = plt.subplots(figsize=(6, 0.5 + 0.35 * len(k)))
    cols = [np.array(CLASS_COLORS.get(int(c), (128, 128, 128))) / 255 for c in k]
    ax.barh([f"{int(c)} {class_name(int(c))}" for c in k], n, color=cols, edgecolor="black")
    for y, v in enumerate(n):
        ax.text(v, y, f" {v:,} ({100 * v / n.sum():.1f} %)", va="center", fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("points")
    ax.set_title(title)
    ax.margins(x=0.3)
    return _fig_b64(fig)


def _class_legend_figure(img: np.ndarray, codes: np.ndarray, title: str) -> str:
    """The render ``img`` with a legend of the classes present in ``codes`` (with their point
    counts) beside it, outside the image, so it never covers the cloud."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch

    from workstation.core.classes import CLASS_COLORS, class_name

    k, n = np.unique(np.asarray(codes), return_counts=True)
    handles = [Patch(facecolor=np.array(CLASS_COLORS.get(int(c), (128, 128, 128))) / 255, edgecolor="black",
                     label=f"{int(c)} {class_name(int(c))} ({v:,})") for c, v in zip(k, n) if v > 0]
    h, w = img.shape[:2]
    fig, ax = plt.subplots(figsize=(w / 100, h / 100))
    ax.imshow(img)
    ax.set_axis_off()
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, frameon=False,
              fontsize=8, title="classes", title_fontsize=9)
    return _fig_b64(fig)


def _same_points(a, b) -> bool:
    """Same coordinates (a filter's output against its input): counts and a sample of xyz."""
    if a.n != b.n or a.n == 0:
        return False
    idx = np.linspace(0, a.n - 1, min(a.n, 1000)).astype(np.int64)
    return bool(np.array_equal(a.xyz[idx], b.xyz[idx]))


def _ground_rows(items, root: Path) -> list[tuple]:
    """Rows of the ground section: each cloud with ground points (class 2) that is a ground
    result (a ground stage in its history, "ground" in its name, or the same points as another
    cloud with other classes), with its figures and, when its input is in the folder, what the
    filter changed."""
    from workstation.core.classes import ASPRSClass

    rows = []
    for p, c in items:
        if "classification" not in c.attrs:
            continue
        cls = np.asarray(c.attrs["classification"])
        n_ground = int(np.count_nonzero(cls == ASPRSClass.GROUND))
        # its input: the same points with other classes, written before it
        src = next(((q, d) for q, d in items if q != p and q.stat().st_mtime < p.stat().st_mtime
                    and "classification" in d.attrs and _same_points(c, d)
                    and not np.array_equal(np.asarray(d.attrs["classification"]), cls)), None)
        by_history = any("ground" in str(h.stage).lower() for h in c.history)
        if n_ground == 0 or not (by_history or "ground" in p.stem.lower() or src is not None):
            continue
        method = next((h.stage for h in reversed(c.history) if "ground" in str(h.stage).lower()), "")
        changed, before = "", ""
        if src is not None:
            scls = np.asarray(src[1].attrs["classification"])
            changed = f"{int(np.count_nonzero(scls != cls)):,} points vs {src[0].relative_to(root)}"
            before = f"{100.0 * np.count_nonzero(scls == ASPRSClass.GROUND) / c.n:.1f} %"
        rows.append((str(p.relative_to(root)), f"{c.n:,}", f"{n_ground:,}", f"{100.0 * n_ground / c.n:.1f} %",
                     f"{int(np.count_nonzero(cls == ASPRSClass.UNCLASSIFIED)):,}", before, changed, method))
    return rows


CSS = """
body{font-family:system-ui,sans-serif;margin:2em auto;max-width:1100px;color:#222}
h1{font-size:1.6em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}
table{border-collapse:collapse;margin:.5em 0;font-size:.85em}td,th{border:1px solid #ddd;padding:.25em .5em;
text-align:left;vertical-align:top;max-width:520px;overflow-wrap:anywhere}th{background:#f3f3f3}
figure{display:inline-block;margin:.5em;vertical-align:top}figcaption{font-size:.85em;color:#555}
img{max-width:100%;border:1px solid #ddd}.note{color:#777;font-size:.85em}
.verdict{font-size:1.2em}.pass{color:#060;font-weight:bold}.fail{color:#b00;font-weight:bold}
.toc{font-size:.9em}.toc ul{color:#555}details{margin:.4em 0}summary{cursor:pointer;font-weight:600}
@page{size:A4;margin:14mm}
@media print{body{margin:0;max-width:none}section.summary{break-after:page}figure,table{break-inside:avoid}
h2{break-after:avoid}img{max-width:100%}}
"""


@dataclass
class _Gathered:
    """What the report reads of a work folder once: files found, records parsed, clouds read,
    SfM models read; ``raster_meta(path)`` gives a raster's ``ws`` metadata, each file read
    once (:func:`~.report_rasters.raster_metas`)."""

    root: Path
    jsons: list
    clouds: list
    meshes: list
    rasters: list
    docs: dict
    notes: list
    steps: list
    prod_rows: list
    cloud_cache: dict
    sfm: list
    raster_meta: Callable[[Path], dict]


def _gather(root: Path, params: ReportParams) -> _Gathered:
    """Find the products, parse the JSON records, read the clouds and the SfM models."""
    from workstation.render.load import is_mesh_file

    jsons = _find(root, (".json",), params.max_depth)
    clouds = [p for p in _find(root, CLOUD_EXT, params.max_depth) if not is_mesh_file(p)]
    meshes = [p for p in _find(root, CLOUD_EXT + MESH_EXT, params.max_depth) if is_mesh_file(p)]
    rasters = _find(root, RASTER_EXT, params.max_depth)
    docs, notes = _read_records(jsons)
    meta_of = raster_metas()
    prod_rows, cloud_cache = _product_records(rasters[: params.max_files], clouds[: params.max_files], root,
                                              meta_of)
    return _Gathered(root, jsons, clouds, meshes, rasters, docs, notes, work_steps(docs, root), prod_rows,
                     cloud_cache, _sfm_models(root, docs, params), meta_of)


def _sfm_models(root: Path, docs: dict, params: ReportParams) -> list:
    """The SfM work folders' models (:class:`~workstation.render.report_sfm.SfMModel`), or
    (folder, exception) for a model that cannot be read."""
    from .report_sfm import find_sfm_folders, read_sfm_model

    out = []
    for folder in find_sfm_folders(root, params.max_depth)[: params.max_files]:
        rec = docs.get(folder / "summary.json")
        try:
            out.append(read_sfm_model(folder, rec if isinstance(rec, dict) and rec.get("stage") == "sfm" else None))
        except Exception as e:  # noqa: BLE001 - a report lists what it cannot read and goes on
            out.append((folder, e))
    return out


def build_report(workdir, params: ReportParams = ReportParams()) -> str:
    """The HTML text of the report of ``workdir`` (see the module docstring).

    Raises
    ------
    InvalidInputError
        When ``workdir`` is not a folder.
    """
    from .report_summary import summary_section

    root = Path(workdir)
    if not root.is_dir():
        raise InvalidInputError("not a folder", "give the work folder of a run", path=root)
    g = _gather(root, params)
    sections = _sections(g, params)
    summary = summary_section(g, sections, lambda p: g.raster_meta(p).get("kind", ""))
    name = html.escape(root.resolve().name)
    head = (f"<h1>Quality report: {name}</h1>"
            f'<p class="note">{html.escape(str(root.resolve()))} — generated '
            f'{_dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}</p>')
    body = "\n".join(f'<section id="{a}"><h2>{html.escape(t)}</h2>{h}</section>' for a, t, h in sections)
    return ("<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>Quality report: {name}</title><style>{CSS}</style></head><body>"
            + head + summary + body + "</body></html>\n")


def _sections(g: _Gathered, params: ReportParams) -> list[tuple[str, str, str]]:
    """(anchor, title, html) of the report's sections after the summary, the empty ones left
    out: previews, photogrammetry, registration, ground, clouds, meshes, the steps (the stage
    records in the order they ran), then the appendix."""
    from .report_checks import find_all, registration_html
    from .report_sfm import georef_html, sfm_html

    root = g.root
    ground = _ground_section(g)
    out = [("previews", "Previews", "".join(_previews_html(root, g.rasters, params, g.raster_meta))),
           ("photogrammetry", "Photogrammetry", "".join(sfm_html(g.sfm, root) + georef_html(g.docs, root))),
           ("registration", "Registration", "".join(registration_html(find_all(g.docs, "registration"), root))),
           ("ground", "Ground", ground),
           ("clouds", "Clouds", "".join(_clouds_html(g.clouds[: params.max_files], g.cloud_cache, root, params))),
           ("meshes", "Meshes", "".join(_meshes_html(g.meshes[: params.max_files], root, params))),
           ("steps", "Steps", _table(g.steps, ("stage", "finished", "seconds", "record", "inputs", "outputs"))
            if g.steps else "")]
    out = [s for s in out if s[2]]
    return out + [("appendix", "Appendix: records", _appendix_html(g))]


def _ground_section(g: _Gathered) -> str:
    """The ground results (each ground-classified cloud), the ground evaluations and the
    confusion matrices of the other records."""
    from .report_checks import find_all, ground_eval_html

    def confusion_html(doc, where: str) -> str:
        cm = _confusion(doc)
        return "" if cm is None else _img(_plot_confusion(cm[0], cm[1], f"Confusion matrix ({where})"),
                                          f"Confusion matrix from {where}")

    rows = _ground_rows([(p, c) for p, c in g.cloud_cache.items() if not isinstance(c, Exception)], g.root)
    parts = [_table(rows, ("cloud", "points", "ground points", "ground", "unclassified (1)", "ground before",
                           "class changed", "stage"))] if rows else []
    evals = find_all(g.docs, "ground_eval")
    if evals:
        parts.append("<h3>Evaluation against a reference</h3>")
        parts += ground_eval_html(evals, g.root, confusion_html)
    done = {p for p, _, _ in evals}
    parts += [confusion_html(doc, str(p.relative_to(g.root))) for p, doc in g.docs.items() if p not in done]
    return "".join(parts)


def _appendix_html(g: _Gathered) -> str:
    """The records, collapsed: products, the JSON records' stage tables and figures, the
    products' own records."""
    root = g.root
    rows = [(str(p.relative_to(root)), kind, f"{p.stat().st_size / 1e6:.2f} MB")
            for kind, lst in (("cloud", g.clouds), ("mesh", g.meshes), ("raster", g.rasters), ("record", g.jsons))
            for p in lst]

    def fold(title: str, body: str) -> str:
        return f"<details><summary>{html.escape(title)}</summary>{body}</details>"

    parts = [fold(f"Products ({len(rows)} files)", _table(rows, ("file", "kind", "size")) if rows
                  else "<p>No products found.</p>")]
    recs = g.notes + _records_html(g.docs, root)
    if g.prod_rows:
        recs.append("<h3>Records in the products</h3>" + _table(g.prod_rows, ("file", "stage", "seconds",
                                                                                "parameters and figures")))
    parts.append(fold(f"Stages and figures ({len(g.docs)} JSON records)", "".join(recs) or
                      "<p>No records found: no run.json or other JSON in the folder, and no product carries its "
                      "stage's metadata or history.</p>"))
    return "".join(parts)


def _read_records(jsons: list[Path]) -> tuple[dict, list[str]]:
    """The JSON records parsed ({path: document}) and a note for each unreadable one."""
    docs, notes = {}, []
    for p in jsons:
        try:
            docs[p] = json.loads(read_text(p))
        except (OSError, ValueError) as e:
            notes.append(f'<p class="note">{html.escape(p.name)}: unreadable ({html.escape(str(e))})</p>')
    return docs, notes


def _records_html(docs: dict, root: Path) -> list[str]:
    """Per JSON record: its stage rows and its other figures (flattened, folded)."""
    out = []
    for p, doc in docs.items():
        srows = _stage_rows(doc)
        title = f"<h3>{html.escape(str(p.relative_to(root)))}</h3>"
        if srows:
            out.append(title + _table(srows, ("stage", "seconds", "parameters", "summary")))
        rest = {k: v for k, v in doc.items() if k not in ("stages", "steps", "history")} if isinstance(doc, dict) else doc
        flat = [(k, v) for k, v in flatten(rest) if not isinstance(v, (dict,))]
        if flat:
            out.append(title + f"<details><summary>{len(flat)} figures</summary>"
                       + _table(flat, ("figure", "value")) + "</details>")
    return out


def _product_records(rasters: list[Path], clouds: list[Path], root: Path, meta_of) -> tuple[list[tuple], dict]:
    """The products' own records: a folder of plain ws outputs has no JSON, but its rasters
    carry their stage's metadata (``meta_of(path)``) and its clouds their history. Returns the
    rows (file, stage, seconds, figures) and the clouds read ({path: Cloud, or the exception
    that reading raised})."""
    from workstation.io import read_cloud

    prod_rows = []
    for p in rasters:
        m = meta_of(p)
        if m.get("kind"):
            figs = {k: v for k, v in m.items() if k not in ("kind", "source", "params", "seconds", "units")}
            prod_rows.append((str(p.relative_to(root)), m["kind"], m.get("seconds", ""), figs))
    cloud_cache: dict = {}
    for p in clouds:
        try:
            cloud_cache[p] = read_cloud(p)
        except Exception as e:  # noqa: BLE001 - a report lists what it cannot read and goes on
            cloud_cache[p] = e
            continue
        for h in cloud_cache[p].history:
            prod_rows.append((str(p.relative_to(root)), h.stage, h.seconds if h.seconds is not None else "",
                              dict(h.params)))
    return prod_rows, cloud_cache


def _clouds_html(clouds: list[Path], cloud_cache: dict, root: Path, params: ReportParams) -> list[str]:
    """One block per cloud (summary, history, top render, class histogram); a note for an
    unreadable cloud and for the same points as a cloud already shown (a ground filter's
    output with other attributes is a product of its own, so attributes count as different)."""
    out = []
    seen: dict = {}
    for p in clouds:
        c = cloud_cache.get(p)
        if isinstance(c, Exception):
            out.append(f'<p class="note">{html.escape(p.name)}: not readable here ({html.escape(str(c))})</p>')
            continue
        sig = (c.n, tuple(np.round(c.xyz[:3].ravel(), 6)),
               tuple((k, hash(np.ascontiguousarray(v).tobytes())) for k, v in sorted(c.attrs.items())))
        if sig in seen:
            out.append(f'<p class="note">{html.escape(str(p.relative_to(root)))}: the same points as '
                       f'{html.escape(seen[sig])} (not drawn again)</p>')
            continue
        seen[sig] = str(p.relative_to(root))
        out.append(_cloud_block(p, c, root, params))
    return out


def _cloud_block(p: Path, c, root: Path, params: ReportParams) -> str:
    """A cloud's block: points, CRS, bounds and dimensions, its history, a top view coloured
    by class (with a legend of the classes present) or automatically, and its class histogram."""
    from workstation.render.render import RenderParams, render

    lo, hi = c.bounds
    info = [("points", c.n), ("CRS", (c.crs or "none")[:80]), ("min", np.round(lo, 3).tolist()),
            ("max", np.round(hi, 3).tolist()), ("dimensions", ", ".join(c.dims))]
    block = f"<h3>{html.escape(str(p.relative_to(root)))}</h3>" + _table(info, ("", ""))
    hist = [(h.stage, h.seconds if h.seconds is not None else "", dict(h.params)) for h in c.history]
    if hist:
        block += _table(hist, ("history stage", "seconds", "parameters"))
    col = "class" if "classification" in c.attrs and len(np.unique(c.attrs["classification"])) > 1 else "auto"
    figs = []
    try:
        img = render(c, RenderParams(size=params.render_size, view="top", color=col, max_points=params.max_points,
                                     legend=col != "class"))
        if col == "class":
            figs.append(_img(_class_legend_figure(img, c.attrs["classification"], p.name),
                             f"{p.name}: top view, colour class"))
        else:
            figs.append(_img(_png_b64(img), f"{p.name}: top view, colour {col}"))
    except Exception as e:  # noqa: BLE001
        block += f'<p class="note">render failed: {html.escape(str(e))}</p>'
    if "classification" in c.attrs:
        figs.append(_img(_plot_class_histogram(c.attrs["classification"], p.name), f"{p.name}: classes"))
    return block + "".join(figs)


def _meshes_html(meshes: list[Path], root: Path, params: ReportParams) -> list[str]:
    """One block per mesh: faces, vertices, area, vertex attributes and an iso view; a note
    for a mesh that cannot be read or drawn."""
    from workstation.io.mesh import read_mesh
    from workstation.render.render import RenderParams, render

    out = []
    for p in meshes:
        try:
            m = read_mesh(p)
            img = render(m, RenderParams(size=params.render_size, view="iso"))
        except Exception as e:  # noqa: BLE001
            out.append(f'<p class="note">{html.escape(p.name)}: {html.escape(str(e))}</p>')
            continue
        info = [("faces", m.n_faces), ("vertices", m.n_vertices), ("area", float(m.face_areas().sum())),
                ("vertex attributes", ", ".join(m.vertex_attrs))]
        out.append(f"<h3>{html.escape(str(p.relative_to(root)))}</h3>" + _table(info, ("", ""))
                   + _img(_png_b64(img), f"{p.name}: iso view"))
    return out


def _previews_html(root: Path, rasters: list[Path], params: ReportParams, meta_of) -> list[str]:
    """Previews: a plot per raster (ortho, hillshade, DTM, density...; a note for an
    unreadable one), then the PNG images of the folder (renders, plots; up to 2 MB, embedded as
    they are; not the photos in an ``images`` folder). ``meta_of(path)``: a raster's metadata,
    which orders the previews (:func:`~.report_rasters.preview_rasters`)."""
    out = []
    for p in preview_rasters(root, rasters, params.max_files, meta_of):
        try:
            r = plot_raster(p)
        except Exception as e:  # noqa: BLE001
            out.append(f'<p class="note">{html.escape(p.name)}: {html.escape(str(e))}</p>')
            continue
        if r:
            out.append(_img(r[1], r[0]))
    pngs = [p for p in _find(root, (".png",), params.max_depth) if p.stat().st_size <= 2_000_000
            and "images" not in p.relative_to(root).parts[:-1]]  # the photos of an SfM folder are inputs
    out += [_img(base64.b64encode(p.read_bytes()).decode("ascii"), str(p.relative_to(root)))
            for p in pngs[: params.max_files]]
    return out


def write_report(workdir, output, overwrite: bool = False, params: ReportParams = ReportParams(),
                 pdf: bool = False) -> list[Path]:
    """Build the report of ``workdir`` and write it atomically to ``output``: an .html page,
    or a .pdf printed by headless Chromium (:mod:`workstation.render.report_pdf`). With
    ``pdf`` an .html ``output`` also gets its PDF beside it (same name, .pdf). Returns the
    files written.

    Raises
    ------
    InvalidInputError
        When ``output`` is neither .html nor .pdf.
    MissingDependencyError
        When a PDF is asked for and Chromium is not found (checked before the report is built).
    """
    from workstation.io import atomic_path
    from workstation.io.atomic import check_outputs

    from .report_pdf import print_to_pdf, require_chromium

    out = Path(output)
    suffix = out.suffix.lower()
    if suffix not in (".html", ".htm", ".pdf"):
        raise InvalidInputError("the report must be an .html or a .pdf file", path=out, field="--output")
    pdf_out = out if suffix == ".pdf" else (out.with_suffix(".pdf") if pdf else None)
    if pdf_out is not None:
        require_chromium()  # before the long build
    check_outputs([out] if pdf_out in (None, out) else [out, pdf_out], overwrite)
    text = build_report(workdir, params)
    written = []
    if suffix != ".pdf":
        with atomic_path(out, overwrite=overwrite) as tmp:
            tmp.write_text(text, encoding="utf-8")
        written.append(out)
    if pdf_out is not None:
        with atomic_path(pdf_out, overwrite=overwrite) as tmp:
            page = tmp.with_suffix(".html")
            page.write_text(text, encoding="utf-8")
            try:
                print_to_pdf(page, tmp)
            finally:
                page.unlink(missing_ok=True)
        written.append(pdf_out)
    return written
