"""The QC report as one self-contained HTML page: the verdict first, then the maps and tables a
client checks (density and voids, swath separation, checkpoint residuals, classes, findings).

Images are inlined as base64 PNG and the page has no script, so it can be mailed or archived.
"""

from __future__ import annotations

import html
from pathlib import Path

import numpy as np

from workstation.io.atomic import atomic_path
from workstation.render.html import fig_b64, img, table

_CSS = """body{font-family:sans-serif;margin:2em;max-width:72em}table{border-collapse:collapse;margin:.5em 0}
td,th{border:1px solid #ccc;padding:.2em .5em;text-align:left}th{background:#eee}.pass{color:#060;font-weight:bold}
.fail{color:#b00;font-weight:bold}.na{color:#777}figure{display:inline-block;margin:.5em}img{max-width:36em}"""
MAX_FINDINGS = 500
MAX_MAP_PIXELS = 1200  # the longer side of a map as drawn in the page


def _verdict(v: dict) -> str:
    word, cls = ("PASS", "pass") if v["pass"] else ("FAIL", "fail")
    note = "" if v["complete"] else " — not every criterion could be measured (see the rows marked n/a)"
    rows = "".join(
        f"<tr><td>{html.escape(r['name'])}</td><td>{_num(r['value'])}</td><td>{html.escape(r['op'])} "
        f"{_num(r['threshold'])} {html.escape(r['unit'])}</td><td class='{_cls(r['pass'])}'>{_word(r['pass'])}</td></tr>"
        for r in v["criteria"])
    return (f"<h2>Verdict: {html.escape(v['spec'])} <span class='{cls}'>{word}</span></h2><p>{html.escape(v['source'])}"
            f"{html.escape(note)}</p><table><thead><tr><th>criterion</th><th>measured</th><th>required</th>"
            f"<th>result</th></tr></thead><tbody>{rows}</tbody></table>")


def _num(v) -> str:
    if v is None:
        return "n/a"
    return f"{v:.4g}" if isinstance(v, float) else html.escape(str(v))


def _cls(ok) -> str:
    return "na" if ok is None else ("pass" if ok else "fail")


def _word(ok) -> str:
    return "n/a" if ok is None else ("pass" if ok else "fail")


def _raster_figure(path: Path, title: str, cmap: str = "viridis", label: str = "") -> str:
    """A single-band GeoTIFF as a colour map with a colour bar, or an RGB GeoTIFF as it is."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import rasterio

    with rasterio.open(path) as src:
        step = max(1, -(-max(src.height, src.width) // MAX_MAP_PIXELS))  # decimated: a picture, not the data
        a = src.read(out_shape=(src.count, max(1, src.height // step), max(1, src.width // step)), masked=True)
        b = src.bounds
    fig, ax = plt.subplots(figsize=(6, 5))
    ext = (b.left, b.right, b.bottom, b.top)
    if a.shape[0] >= 3:
        ax.imshow(np.moveaxis(np.asarray(a[:3].filled(255)), 0, -1), extent=ext)
    else:
        im = ax.imshow(a[0].astype(float).filled(np.nan), extent=ext, cmap=cmap)
        fig.colorbar(im, ax=ax, label=label)
    ax.set_title(title)
    return img(fig_b64(fig), title)


def _residual_figure(acc: dict) -> str:
    """Checkpoint residuals dz (lidar minus survey) by checkpoint, vegetated ones apart."""
    import matplotlib.pyplot as plt

    rows = [r for r in acc["checkpoints"] if r.get("dz") is not None]
    dz = np.array([r["dz"] for r in rows], float)
    veg = np.array([bool(r["vegetated"]) for r in rows], dtype=bool)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.5))
    idx = np.arange(len(dz))
    a1.scatter(idx[~veg], dz[~veg], s=12, label="non-vegetated")
    a1.scatter(idx[veg], dz[veg], s=12, marker="^", label="vegetated")
    a1.axhline(0, color="k", lw=0.8)
    a1.set_xlabel("checkpoint")
    a1.set_ylabel("dz (m)")
    a1.legend()
    a2.hist([dz[~veg], dz[veg]], bins=20, label=["non-vegetated", "vegetated"], stacked=True)
    a2.set_xlabel("dz (m)")
    return img(fig_b64(fig), "Checkpoint residuals (lidar TIN minus surveyed elevation)")


def _class_figure(classes: dict) -> str:
    import matplotlib.pyplot as plt

    hist = {int(k): int(v) for k, v in classes["histogram"].items() if int(v) > 0}
    names = classes.get("names", {})
    fig, ax = plt.subplots(figsize=(7, 3))
    keys = sorted(hist)
    ax.bar([f"{k} {names.get(str(k), '')}" for k in keys], [hist[k] for k in keys])
    ax.set_yscale("log")
    ax.tick_params(axis="x", rotation=60)
    ax.set_ylabel("points")
    return img(fig_b64(fig), "Points per class")


def _maps(doc: dict, folder: Path) -> str:
    parts, maps = [], doc.get("maps", {})
    spec = [("density.tif", "First-return density per 2×ANPS cell", "viridis", "points/m²"),
            ("voids.tif", "Voids (yellow) inside the footprint", "cividis", "void"),
            ("dz.tif", "Swath separation image (DZ)", "", ""),
            ("dz_values.tif", "Largest |dz| between overlapping swaths", "magma", "m")]
    for name, title, cmap, label in spec:
        if name in maps.values() and (folder / name).exists():
            parts.append(_raster_figure(folder / name, title, cmap or "viridis", label))
    return "".join(parts)


def build_html(doc: dict, folder: Path) -> str:
    """The report page of the QC document ``doc``; maps are read from ``folder``."""
    s = doc["swath"]
    body = [f"<h1>Quality control of {len(doc['files'])} file(s), {doc['points']:,} points</h1>", _verdict(doc["verdict"]),
            "<h2>Density and coverage</h2>",
            table([("ANPD (first returns, single swaths)", doc["anpd"], "pts/m²"), ("ANPS", doc["anps"], "m"),
                   ("cells of 2×ANPS filled", doc["coverage"], ""), ("voids", doc["voids"], ""),
                   ("CRS", doc.get("crs") or "unknown", "")], ("quantity", "value", "unit")),
            _maps(doc, folder), "<h2>Swath overlap</h2>",
            table([(p["a"], p["b"], p["rmsdz"], p["mean_dz"], p["max_abs_dz"], p["cells"]) for p in s.get("swaths", [])],
                  ("swath a", "swath b", "RMSDz (m)", "mean dz (m)", "max |dz| (m)", "cells")),
            table([(r["id"], r.get("precision_m"), r.get("p95_m"), r.get("cells")) for r in s.get("intraswath", [])],
                  ("swath", "intraswath precision (m)", "95th percentile (m)", "cells"))]
    body += _accuracy_html(doc)
    body += ["<h2>Classification</h2>", _class_figure(doc["classes"]),
             table([(c["name"], c["value"], c["threshold"], _word(c["pass"])) for c in doc["classes"].get("criteria", [])],
                   ("check", "value", "threshold", "result"))]
    body += _findings_html(doc["findings"])
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>QC report</title><style>{_CSS}</style></head>"
            f"<body>{''.join(body)}</body></html>")


def _accuracy_html(doc: dict) -> list[str]:
    acc, dem = doc.get("accuracy"), doc.get("dem_accuracy")
    out = ["<h2>Absolute accuracy</h2>"]
    if acc is None:
        return out + ["<p>No checkpoints given (--checkpoints): absolute accuracy not measured.</p>"]
    flat = [(f"{k}.{k2}", v2) for k, v in acc.items() if isinstance(v, dict) for k2, v2 in v.items()]
    out += [table(flat, ("statistic", "value (m)")), _residual_figure(acc)]
    out.append(_outliers_html(acc.get("outliers")))
    if dem is not None:
        out += ["<h3>DEM</h3>", table([(r["name"], r["value"], r["threshold"], _word(r["pass"])) for r in dem.get("rules", [])],
                                      ("rule", "value", "threshold", "result"))]
    return out


def _outliers_html(o: dict | None) -> str:
    """The checkpoints beyond the outlier rule: listed for review, still counted in the figures."""
    if not o or not o.get("items"):
        return ""
    return (f"<p>Outliers ({html.escape(o['rule'])}), listed, not removed:</p>"
            + table([(i["id"], i["dz_m"], i["deviation_m"]) for i in o["items"]],
                    ("checkpoint", "dz (m)", "dz − mean (m)")))


def _findings_html(findings: list) -> list[str]:
    rows = [(f["severity"], f["check"], Path(f["file"]).name if f.get("file") else "", f["field"], f["expected"],
             f["found"], f["message"]) for f in findings[:MAX_FINDINGS]]
    more = f"<p>{len(findings) - MAX_FINDINGS} more in qc.json.</p>" if len(findings) > MAX_FINDINGS else ""
    return [f"<h2>Findings ({len(findings)})</h2>",
            table(rows, ("severity", "check", "file", "field", "expected", "found", "message")), more]


def write_html(doc: dict, path, folder) -> Path:
    """Write the report page of ``doc`` to ``path`` (atomic)."""
    text = build_html(doc, Path(folder))
    with atomic_path(path, overwrite=True) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    return Path(path)
