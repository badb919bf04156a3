"""Demo step of the raster products: DSM, DTM, CHM, hillshade and contours of the demo cloud."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.log import get_logger

log = get_logger(__name__)


def step(ctx) -> dict:
    from workstation.io import atomic_path
    from workstation.io.geotiff import write_raster
    from workstation.raster.contours import ContourParams, contour_lines, write_geojson
    from workstation.raster.dem import DemParams, build_dem
    from workstation.raster.terrain import hillshade

    src = next((ctx.products[k] for k in ("ground_laz", "als_laz", "cloud_las") if k in ctx.products), None)
    if src is None:
        log.warning("raster step: no cloud among the earlier products; skipped")
        return {}
    out = ctx.outdir
    made = {}
    rasters = {}
    for kind in ("dsm", "dtm", "chm"):
        r = build_dem(src, DemParams(kind=kind, resolution=None if kind == "dtm" else 1.0))
        path = out / f"raster_{kind}.tif"
        write_raster(r, path, overwrite=True)
        made[f"{kind}_tif"] = path
        rasters[kind] = r
    hs = hillshade(rasters["dtm"])
    write_raster(hs, out / "raster_hillshade.tif", overwrite=True)
    made["hillshade_tif"] = out / "raster_hillshade.tif"
    cs = contour_lines(rasters["dtm"], ContourParams(interval=0.5))
    write_geojson(cs, out / "raster_contours.geojson", overwrite=True)
    made["contours_geojson"] = out / "raster_contours.geojson"
    summary = {
        "source": str(src),
        "dtm_resolution_m": rasters["dtm"].meta["resolution"],
        "dtm_resolution_reason": rasters["dtm"].meta["resolution_reason"],
        "chm_max_m": float(np.nanmax(rasters["chm"].array)),
        "contour_lines": len(cs),
    }
    with atomic_path(out / "raster_summary.json", overwrite=True) as tmp:
        tmp.write_text(json.dumps(summary, indent=2))
    made["raster_summary"] = out / "raster_summary.json"
    ctx.summaries["raster"] = summary
    return made
