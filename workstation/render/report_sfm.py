"""The photogrammetry part of the work-folder report: SfM figures and ground-control residuals.

An SfM work folder is any folder holding ``sparse/0`` (a COLMAP model, binary or text, as
``ws sfm`` writes it); the model in the survey frame (``georef/0``) is drawn instead when it
exists. For each: the reprojection error of every image observation (measured pixel against
the projection of its 3-D point through the model's camera, distortion included), a histogram
of those errors and the camera centres over the sparse points seen from above. Ground-control
residuals come from any JSON record holding a georeferencing result (``metrics`` with control
or check RMSE and a ``points`` table of ``role``, ``X``, ``Y``, ``Z``, ``dX``, ``dY``, ``dZ``),
as ``georef_report.json`` and the sfm stage record do.
"""

from __future__ import annotations

import html
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .html import fig_b64, img, table

# Folders that hold tool internals; a model found below one of them is not an SfM work folder.
_SKIP_PARTS = {"stereo", "depth_maps", "normal_maps", ".ws-cache"}


@dataclass(frozen=True)
class SfMModel:
    """What the report draws of one SfM work folder.

    Attributes
    ----------
    folder : Path
        The work folder.
    model : Path
        The model folder read (``georef/0`` when present, else ``sparse/0``).
    points : (n, 3) float
        Sparse points.
    centres : (m, 3) float
        Centres of the registered images.
    names : list of str
        Their names, in the order of ``centres``.
    residuals : (k,) float
        Reprojection error of every observation (px).
    record : dict
        The folder's sfm stage record (``summary.json``), {} when absent.
    """

    folder: Path
    model: Path
    points: np.ndarray
    centres: np.ndarray
    names: list
    residuals: np.ndarray
    record: dict


def find_sfm_folders(root: Path, max_depth: int) -> list[Path]:
    """Work folders below ``root`` (itself included, ``max_depth`` levels down) that hold a
    COLMAP model in ``sparse/0``."""
    out = []
    for cams in sorted(root.rglob("cameras.*")):
        if cams.suffix not in (".bin", ".txt") or cams.parent.name != "0" or cams.parent.parent.name != "sparse":
            continue
        folder = cams.parent.parent.parent
        rel = folder.relative_to(root).parts
        if len(rel) > max_depth or _SKIP_PARTS & set(rel) or "sparse" in rel or folder in out:
            continue
        out.append(folder)
    return out


def observation_residuals(rec) -> np.ndarray:
    """Reprojection error (px) of every observation of a core reconstruction with tracks: the
    distance between the measured pixel and its point projected into the observing image."""
    from workstation.raster.ortho import project_points

    tr = rec.tracks
    if tr is None or len(tr.point) == 0:
        return np.empty(0)
    out = np.full(len(tr.point), np.nan)
    for iid in np.unique(tr.image):
        im = rec.images[int(iid)]
        sel = np.flatnonzero(tr.image == iid)
        uv, depth = project_points(rec.cameras[im.camera_id], im.pose, rec.points[tr.point[sel]])
        out[sel] = np.where(depth > 0, np.hypot(*(uv - tr.uv[sel]).T), np.nan)
    return out[np.isfinite(out)]


def read_sfm_model(folder: Path, record: dict | None = None) -> SfMModel:
    """The points, camera centres and observation residuals of the SfM work folder ``folder``."""
    from workstation.interop.pycolmap import find_model, read_model

    model = find_model(folder / "georef" / "0") or find_model(folder / "sparse" / "0")
    rec = read_model(model if model is not None else folder / "sparse" / "0", with_tracks=True)
    ids = sorted(rec.images)
    centres = np.array([rec.images[i].pose.center for i in ids], dtype=float).reshape(-1, 3)
    pts = np.asarray(rec.points if rec.points is not None else np.empty((0, 3)), dtype=float)
    return SfMModel(folder, model, pts, centres, [rec.images[i].name for i in ids],
                    observation_residuals(rec) if pts.size else np.empty(0), dict(record or {}))


def plot_reprojection_histogram(res: np.ndarray, title: str) -> str:
    """Histogram of observation reprojection errors (px) with their mean and median marked."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.2))
    hi = float(np.percentile(res, 99.5)) if res.size else 1.0
    ax.hist(np.clip(res, 0, hi), bins=50, range=(0, hi or 1.0), color="#4a7ab7", edgecolor="white", linewidth=0.3)
    for v, ls, name in ((res.mean(), "-", "mean"), (np.median(res), "--", "median")):
        ax.axvline(v, color="#b22", ls=ls, lw=1, label=f"{name} {v:.3f} px")
    ax.set_xlabel("reprojection error (px)")
    ax.set_ylabel("observations")
    ax.set_title(title)
    ax.legend(fontsize=8)
    return fig_b64(fig)


def plot_cameras_top(points: np.ndarray, centres: np.ndarray, title: str, max_points: int = 200_000) -> str:
    """Camera centres (red) over the sparse points (grey, coloured by height) seen from above,
    equal axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 5))
    if len(points):
        step = max(1, -(-len(points) // max_points))
        p = points[::step]
        lo, hi = np.percentile(p[:, 2], [2, 98])
        sc = ax.scatter(p[:, 0], p[:, 1], c=p[:, 2], s=1, cmap="Greys_r", vmin=lo, vmax=hi, rasterized=True)
        fig.colorbar(sc, ax=ax, shrink=0.7, label="height of sparse points")
    ax.scatter(centres[:, 0], centres[:, 1], s=18, c="#d22", marker="^", edgecolors="black", linewidths=0.4,
               label=f"{len(centres)} camera centres")
    ax.set_aspect("equal", adjustable="datalim")
    ax.ticklabel_format(useOffset=False, style="plain")
    ax.set_xlabel("X")
    ax.set_ylabel("Y")
    ax.set_title(title)
    ax.legend(fontsize=8, loc="upper right")
    return fig_b64(fig)


def _is_georef(d: dict) -> bool:
    m = d.get("metrics")
    return isinstance(m, dict) and ("control_rmse_3d" in m or "check_rmse_3d" in m) and isinstance(d.get("points"), list)


def find_georef(doc, limit: int = 8) -> list[tuple[str, dict]]:
    """(key path, result) of the georeferencing results inside a JSON document: dicts with a
    ``metrics`` dict holding ``control_rmse_3d`` or ``check_rmse_3d`` and a ``points`` list."""
    from .report_checks import walk

    return walk(doc, _is_georef, limit)


def gcp_table(points: list) -> tuple[list, np.ndarray, np.ndarray]:
    """(names, roles, (n, 6) X Y Z dX dY dZ) of the rows of a georeferencing ``points`` table
    that carry residuals."""
    rows = [p for p in points if isinstance(p, dict) and all(isinstance(p.get(k), (int, float))
                                                             for k in ("X", "Y", "dX", "dY", "dZ"))]
    a = np.array([[p["X"], p["Y"], p.get("Z", np.nan), p["dX"], p["dY"], p["dZ"]] for p in rows], dtype=float)
    return [str(p.get("name", "")) for p in rows], np.array([str(p.get("role", "")) for p in rows]), a.reshape(-1, 6)


def plot_gcp_residuals(points: list, title: str) -> str | None:
    """Residuals of control and check points: horizontal vectors in plan view (arrow length
    scaled, the scale given) and horizontal / vertical residual per point. None without rows."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names, roles, a = gcp_table(points)
    if not len(names):
        return None
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6), gridspec_kw={"width_ratios": [1, 1.4]})
    x0, y0 = np.floor(a[:, 0].min()), np.floor(a[:, 1].min())
    a[:, 0] -= x0
    a[:, 1] -= y0
    extent = max(np.ptp(a[:, 0]), np.ptp(a[:, 1]), 1e-9)
    dh = np.hypot(a[:, 3], a[:, 4])
    scale = 0.12 * extent / max(dh.max(), 1e-12)
    for role, mk, col in (("control", "o", "#1f6fb4"), ("check", "^", "#e07b00")):
        s = roles == role
        ax.scatter(a[s, 0], a[s, 1], marker=mk, c=col, s=28, label=role, edgecolors="black", linewidths=0.4)
        ax.quiver(a[s, 0], a[s, 1], a[s, 3] * scale, a[s, 4] * scale, color=col, angles="xy", scale_units="xy", scale=1)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"X − {x0:.0f}")
    ax.set_ylabel(f"Y − {y0:.0f}")
    ax.set_title(f"horizontal residuals (arrows ×{scale:.3g})", fontsize=10)
    ax.legend(fontsize=8)
    x = np.arange(len(names))
    cols = np.where(roles == "check", "#e07b00", "#1f6fb4")
    bx.bar(x - 0.2, dh, 0.4, color=cols, edgecolor="black", linewidth=0.4, label="horizontal |dXY|")
    bx.bar(x + 0.2, a[:, 5], 0.4, color=cols, alpha=0.45, hatch="//", edgecolor="black", linewidth=0.4, label="vertical dZ")
    bx.axhline(0, color="black", lw=0.6)
    bx.set_xticks(x, names, rotation=60, ha="right", fontsize=7)
    bx.set_ylabel("residual (CRS units)")
    bx.legend(fontsize=8)
    bx.set_title("residual per point (blue: control, orange: check)", fontsize=10)
    fig.suptitle(title, y=1.02)
    return fig_b64(fig)


def georef_rows(m: dict) -> list[tuple]:
    """The accuracy rows of georeferencing metrics: control and check RMSE (X, Y, Z, H, 3-D)
    with their counts, and CE90 / LE90 of the check points."""
    rows = []
    for role in ("control", "check"):
        if not m.get(f"{role}_n"):
            continue
        rows.append((role, m.get(f"{role}_n"), *(m.get(f"{role}_rmse_{k}", "") for k in ("x", "y", "z", "h", "3d")),
                     m.get("check_ce90", "") if role == "check" else "", m.get("check_le90", "") if role == "check" else ""))
    return rows


GEOREF_HEADER = ("points", "n", "RMSE X", "RMSE Y", "RMSE Z", "RMSE H", "RMSE 3D", "CE90", "LE90")


def georef_html(docs: dict, root: Path) -> list[str]:
    """A block per georeferencing result found in the records: its RMSE table, notes and the
    residual figure."""
    out = []
    for p, doc in docs.items():
        for key, g in find_georef(doc):
            where = str(p.relative_to(root)) + (f" ({key})" if key else "")
            block = f"<h3>Ground control: {html.escape(where)}</h3>"
            block += f"<p>adjustment: {html.escape(str(g.get('adjustment', '')))}</p>" if g.get("adjustment") else ""
            block += table(georef_rows(g["metrics"]), GEOREF_HEADER)
            notes = [n for n in g.get("notes", []) if isinstance(n, str)]
            block += "".join(f'<p class="note">{html.escape(n)}</p>' for n in notes)
            fig = plot_gcp_residuals(g["points"], f"GCP residuals — {where}")
            out.append(block + (img(fig, f"GCP and check point residuals: {where}") if fig else ""))
    return out


def sfm_html(models: list, root: Path) -> list[str]:
    """A block per SfM work folder: its figures table, the reprojection-error histogram and
    the camera positions over the sparse cloud."""
    from .report_checks import kv_table
    from .report_summary import registered

    out = []
    for m in models:
        if isinstance(m, tuple):  # (folder, exception): a model that could not be read
            out.append(f'<p class="note">{html.escape(str(m[0].relative_to(root)))}: model not readable '
                       f"({html.escape(str(m[1]))})</p>")
            continue
        name = str(m.folder.relative_to(root)) if m.folder != root else root.name
        r = m.record
        rows = [("model", str(m.model.relative_to(root))),
                ("images", registered(m)),
                ("sparse points", len(m.points)), ("observations", len(m.residuals)),
                ("mean reprojection error (px)", float(m.residuals.mean()) if m.residuals.size else "n/a"),
                ("median reprojection error (px)", float(np.median(m.residuals)) if m.residuals.size else "n/a"),
                ("mean track length", r.get("mean_track_length", "")), ("intrinsics", r.get("intrinsics", "")),
                ("not registered", ", ".join(r.get("unregistered", []) or []))]
        block = f"<h3>SfM: {html.escape(name)}</h3>" + kv_table([x for x in rows if x[1] != ""])
        if m.residuals.size:
            block += img(plot_reprojection_histogram(m.residuals, f"Reprojection error — {name}"),
                         f"Reprojection error histogram: {name}")
        block += img(plot_cameras_top(m.points, m.centres, f"Cameras over the sparse cloud — {name}"),
                     f"Camera positions over the sparse cloud (top view): {name}")
        out.append(block)
    return out
