"""The summary page of the work-folder report: what was processed, the key accuracies, the QC
verdict and the list of the figures that follow.

Everything here is read from what the report has already gathered (the clouds read, the
rasters found, the JSON records parsed, the SfM models read), so the summary costs no further
pass over the data except the valid-cell count of one DTM.
"""

from __future__ import annotations

import datetime as _dt
import html
import re
from pathlib import Path

import numpy as np

from .html import fmt, table
from .report_checks import find_all, kv_table
from .report_sfm import find_georef


def crs_label(crs: str | None) -> str:
    """A short name of a CRS ("EPSG:32632 WGS 84 / UTM zone 32N"), the text itself cut to 60
    characters when pyproj cannot read it, "" for None."""
    if not crs:
        return ""
    try:
        from workstation.io.crs import crs_info

        i = crs_info(crs, identify=False)
    except Exception:  # noqa: BLE001 - a label, not a check
        return str(crs)[:60]
    return f"EPSG:{i.epsg} {i.name}" if i.epsg else i.name


def _dtm_area(rasters: list[Path], kind_of) -> tuple[str, float] | None:
    """(name, area, unit of area) of the valid cells of the first DTM among ``rasters``
    (``kind_of(path)`` gives a raster's ``ws`` kind), read decimated to at most ~1000² cells."""
    import rasterio

    for p in rasters:
        if kind_of(p) != "dtm" and "dtm" not in p.stem.lower():
            continue
        with rasterio.open(p) as ds:
            step = max(1, -(-max(ds.height, ds.width) // 1000))
            h, w = max(1, ds.height // step), max(1, ds.width // step)
            valid = np.count_nonzero(ds.read_masks(1, out_shape=(h, w)))
            cell_area = abs(ds.transform.a * ds.transform.e) * (ds.height / h) * (ds.width / w)
            crs = ds.crs.to_wkt() if ds.crs is not None else None
        from workstation.io.crs import unit_symbol

        return p.name, float(valid * cell_area), f"{unit_symbol(crs) or 'CRS units'}²"
    return None


def _dates(steps: list[tuple], files: list[Path]) -> str:
    """The span of the stage records' finish times, else of the products' modification times."""
    if steps:
        first, last = steps[0][1][:16].replace("T", " "), steps[-1][1][:16].replace("T", " ")
        return first if first == last else f"{first} — {last} (stage records)"
    if not files:
        return ""
    t = [p.stat().st_mtime for p in files]
    f = [_dt.datetime.fromtimestamp(x, _dt.timezone.utc).strftime("%Y-%m-%d %H:%M") for x in (min(t), max(t))]
    return (f[0] if f[0] == f[1] else f"{f[0]} — {f[1]}") + " UTC (file times)"


def _inputs(docs: dict, root: Path) -> list[str]:
    """The inputs the stage records name (``inputs`` of a record with a ``stage``) that lie
    outside the work folder: the photos, the scans, the GCP file..."""
    base = str(root.resolve())
    vals = {str(v) for d in docs.values() if isinstance(d, dict) and isinstance(d.get("stage"), str)
            and isinstance(d.get("inputs"), dict) for v in d["inputs"].values() if v}
    return sorted(v for v in vals if not v.startswith(base))


def processed_rows(root: Path, clouds: dict, meshes: list, rasters: list, steps: list, sfm: list, docs: dict,
                   kind_of) -> list:
    """(what, value) rows of what the folder holds: clouds and points, photos, meshes, rasters,
    the inputs named by the stage records, CRS, area covered and dates."""
    ok = {p: c for p, c in clouds.items() if not isinstance(c, Exception)}
    rows = [("work folder", str(root.resolve()))]
    if ok:
        big = max(ok, key=lambda p: ok[p].n)
        rows.append(("point clouds", f"{len(ok)} files, {sum(c.n for c in ok.values()):,} points "
                                     f"(largest: {big.relative_to(root)}, {ok[big].n:,})"))
    for m in sfm:
        if not isinstance(m, tuple):
            rows.append(("photos", f"{registered(m)} ({m.folder.relative_to(root) if m.folder != root else '.'})"))
    if meshes:
        rows.append(("meshes", ", ".join(str(p.relative_to(root)) for p in meshes[:6])))
    whole = [p for p in rasters if "tiles" not in p.relative_to(root).parts[:-1]]
    if rasters:
        rows.append(("rasters", ", ".join(str(p.relative_to(root)) for p in whole[:8])
                     + (f" and {len(whole) - 8} more" if len(whole) > 8 else "")
                     + (f" ({len(rasters) - len(whole)} tiles besides)" if len(whole) < len(rasters) else "")))
    ins = _inputs(docs, root)
    if ins:
        rows.append(("inputs (stage records)", ", ".join(ins[:6])))
    crs = sorted({crs_label(c.crs) for c in ok.values() if c.crs})
    if crs:
        rows.append(("CRS", "; ".join(crs)))
    area = _dtm_area(rasters, kind_of)
    if area is not None:
        rows.append(("area covered", f"{area[1]:,.0f} {area[2]} (valid cells of {area[0]})"))
    elif ok:
        lo = np.min([c.bounds[0] for c in ok.values()], axis=0)
        hi = np.max([c.bounds[1] for c in ok.values()], axis=0)
        rows.append(("extent", f"{hi[0] - lo[0]:,.1f} × {hi[1] - lo[1]:,.1f} (bounding box of the clouds)"))
    d = _dates(steps, list(ok) + rasters + meshes)
    return rows + ([("dates", d)] if d else [])


def registered(m) -> str:
    """"<registered> of <images> registered" of an SfM model from its record, or the count of
    images in the model when the folder has no sfm record."""
    r = m.record
    if "registered" in r and "images" in r:
        return f"{r['registered']} of {r['images']} registered"
    return f"{len(m.centres)} images in the model (no sfm record)"


def _acc(rows: list, what: str, value, where: str, unit: str = "") -> None:
    """Append (what, value with its unit, where) when ``value`` is a finite number; ``unit``
    "%" shows a share (0-1) as a percentage, any other unit follows 4 significant digits."""
    if isinstance(value, (int, float)) and not isinstance(value, bool) and np.isfinite(value):
        text = f"{100 * value:.3f} %" if unit == "%" else f"{value:.4g}" + (f" {unit}" if unit else "")
        rows.append((what, text, where))


def length_unit(clouds: dict) -> str:
    """Symbol of the horizontal unit of the clouds' CRS (:func:`workstation.io.crs.unit_symbol`;
    "m" without a CRS, as the workstation assumes metres then); "CRS units" when the clouds
    disagree or the unit has no name."""
    from workstation.io.crs import unit_symbol

    names = {unit_symbol(c.crs) for c in clouds.values() if not isinstance(c, Exception) and c.crs}
    return (names.pop() or "CRS units") if len(names) == 1 else ("m" if not names else "CRS units")


def _where(p: Path, key: str, root: Path) -> str:
    return str(p.relative_to(root)) + (f" ({key})" if key else "")


def _record_accuracies(docs: dict, root: Path, unit: str) -> list[tuple]:
    """Accuracy rows of the records: GCP control / check RMSE and registration RMSE (lengths in
    ``unit``), registration fitness, ground evaluation."""
    rows: list = []
    for p, doc in docs.items():
        for key, g in find_georef(doc):
            m, w = g["metrics"], _where(p, key, root)
            _acc(rows, f"GCP control RMSE 3D ({m.get('control_n', '?')} points)", m.get("control_rmse_3d"), w, unit)
            for k, name in (("h", "horizontal"), ("z", "vertical"), ("3d", "3D")):
                _acc(rows, f"check point RMSE {name} ({m.get('check_n', '?')} points)", m.get(f"check_rmse_{k}"), w,
                     unit)
    for p, key, d in find_all(docs, "registration"):
        w = _where(p, key, root)
        _acc(rows, "registration inlier RMSE", d.get("inlier_rmse"), w, unit)
        _acc(rows, "registration fitness (overlap share)", d.get("fitness"), w, "%")
        edges = [e["inlier_rmse"] for e in d.get("edges") or [] if isinstance(e.get("inlier_rmse"), (int, float))]
        _acc(rows, "registration inlier RMSE, worst edge", max(edges) if edges else None, w, unit)
    for p, key, d in find_all(docs, "ground_eval"):
        w = _where(p, key, root)
        for k, name in (("total_error", "ground filter total error"), ("type1", "ground filter Type I error"),
                        ("type2", "ground filter Type II error")):
            _acc(rows, name, d.get(k), w, "%")
        _acc(rows, "ground filter kappa", d.get("kappa"), w)
    return rows


def _flat_numbers(d, limit: int = 2000) -> list:
    """(key path, number) of the numbers among the first ``limit`` leaves of a JSON document."""
    from workstation.core.jsonutil import flatten

    return [(k, v) for k, v in flatten(d, limit) if isinstance(v, (int, float)) and not isinstance(v, bool)]


def _named_accuracies(docs: dict, root: Path, unit: str) -> list[tuple]:
    """Accuracy figures named by their keys: an RMSE of a DTM / DEM (``rmse`` with ``dtm`` or
    ``dem`` in the file or key name), per-class F1 (``<class>_f1``), the overall accuracy of a
    classification and the median accuracy of a dense cloud (``accuracy_median_m``)."""
    rows: list = []
    for p, doc in docs.items():
        for key, v in _flat_numbers(doc):
            low, leaf = f"{p.stem}.{key}".lower(), key.rsplit(".", 1)[-1].lower()
            if "rmse" in leaf and ("dtm" in low or "dem" in low):
                _acc(rows, f"DTM/DEM RMSE ({key})", v, str(p.relative_to(root)), unit)
            elif leaf.endswith("_f1") and "." not in key:
                _acc(rows, f"classification F1, {leaf[:-3]}", v, str(p.relative_to(root)))
            elif leaf == "overall_accuracy":
                _acc(rows, "classification overall accuracy", v, str(p.relative_to(root)))
            elif leaf == "accuracy_median_m":
                _acc(rows, "dense cloud median accuracy", v, str(p.relative_to(root)), "m")
    return rows


def key_accuracies(docs: dict, root: Path, sfm: list, unit: str = "m") -> list[tuple]:
    """(quantity, value, source) rows of the key accuracies found in the work folder: SfM
    reprojection error and registered images, GCP and check point RMSE, registration RMSE,
    ground-evaluation errors, DTM RMSE, classification F1."""
    rows: list = []
    for m in sfm:
        if isinstance(m, tuple):
            continue
        w = str(m.folder.relative_to(root)) if m.folder != root else "."
        if m.residuals.size:
            _acc(rows, "SfM mean reprojection error", float(m.residuals.mean()), w, "px")
        rows.append(("SfM registered images", registered(m), w))
    return rows + _record_accuracies(docs, root, unit) + _named_accuracies(docs, root, unit)


def qc_html(found: list, root: Path) -> str:
    """The verdict of each ``ws qc`` document found: PASS / FAIL with the specification, then
    the failed and unmeasured criteria (all criteria are in the appendix's qc.json)."""
    out = []
    for p, key, doc in found:
        v = doc["verdict"]
        word, cls = ("PASS", "pass") if v["pass"] else ("FAIL", "fail")
        note = "" if v.get("complete", True) else " (not every criterion could be measured)"
        out.append(f'<p class="verdict">QC {html.escape(str(v.get("spec", "")))}: <span class="{cls}">{word}</span>'
                   f'{html.escape(note)} — {html.escape(_where(p, key, root))}</p>')
        rows = [(r.get("name", ""), "n/a" if r.get("value") is None else r["value"], f"{r.get('op', '')} {fmt(r.get('threshold'))} {r.get('unit', '')}",
                 "n/a" if r.get("pass") is None else ("pass" if r["pass"] else "fail"))
                for r in v["criteria"] if isinstance(r, dict)]
        out.append(table(rows, ("criterion", "measured", "required", "result")))
    return "".join(out)


def figure_list(sections: list[tuple[str, str, str]]) -> str:
    """The list of sections and their figures (captions), linked to the sections; ``sections``
    holds (anchor, title, html)."""
    items = []
    for anchor, title, body in sections:
        caps = re.findall(r"<figcaption>(.*?)</figcaption>", body)
        sub = "".join(f"<li>{c}</li>" for c in caps)
        items.append(f'<li><a href="#{anchor}">{html.escape(title)}</a>' + (f"<ul>{sub}</ul>" if sub else "") + "</li>")
    return '<ol class="toc">' + "".join(items) + "</ol>"


def summary_section(g, sections: list[tuple[str, str, str]], kind_of) -> str:
    """The summary page: the QC verdict when a ``ws qc`` result is in the folder, what was
    processed, the key accuracies and the contents (sections and their figures). ``g`` is what
    the report gathered (files, records, clouds, SfM models); ``kind_of(path)`` gives a
    raster's ``ws`` kind."""
    qc = find_all(g.docs, "qc")
    parts = ['<section id="summary" class="summary"><h2>Summary</h2>']
    parts.append(qc_html(qc, g.root) if qc else '<p class="note">No quality-control result (ws qc) in the folder.</p>')
    parts.append("<h3>What was processed</h3>" + kv_table(
        processed_rows(g.root, g.cloud_cache, g.meshes, g.rasters, g.steps, g.sfm, g.docs, kind_of)))
    acc = key_accuracies(g.docs, g.root, g.sfm, length_unit(g.cloud_cache))
    parts.append("<h3>Key accuracies</h3>" + (table(acc, ("quantity", "value", "from")) if acc else
                                               "<p>No accuracy records found in the folder.</p>"))
    parts.append("<h3>Contents</h3>" + figure_list(sections) + "</section>")
    return "".join(parts)
