"""`ws buildings IN -o OUT_DIR [--footprints GEOJSON|GPKG]`: footprints, roof planes, LoD1.2/LoD2.2
models (CityJSON, glTF, OBJ) and rooftop solar potential (per face, and a roof map GeoTIFF) of
the buildings of a classified cloud."""

from __future__ import annotations

import click

from workstation.buildings.pipeline import BuildingsParams
from workstation.buildings.solar import SolarParams

from .options import emit_json, json_option, overwrite_option, read_options
from .options import FiniteFloatRange, positive_float
from .options import bound, param_group

OUTPUTS = ("footprints.geojson", "roofs.geojson", "buildings.city.json", "buildings.glb", "buildings_lod22.obj",
           "buildings_lod12.obj", "buildings.mtl")
SOLAR_MAP = "solar_roofs.tif"
SOLAR_PNG = "solar_roofs.png"
NODATA = -9999.0


@click.command()
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@click.option("-o", "--output", "out_dir", required=True, type=click.Path(file_okay=False),
              help="Output folder (footprints.geojson, roofs.geojson, buildings.city.json, buildings.glb, "
                   "buildings_lod22.obj, buildings_lod12.obj with buildings.mtl, solar_roofs.tif with its preview "
                   "solar_roofs.png).")
@click.option("--footprints", "footprints_path", default=None, type=click.Path(dir_okay=False, exists=True),
              help="Building outlines (polygons of a GeoJSON or GeoPackage file, in the cloud's CRS) used "
                   "instead of tracing them.")
@click.option("--classify", "run_classifier", is_flag=True,
              help="Classify the cloud first with the shipped point classifier (else class 6 is taken as given).")
@param_group(
    "classes",
    bound(BuildingsParams, "building_class", "--building-class", show_default=True, type=click.IntRange(0, 255),
          help="Class of roof points."),
    bound(BuildingsParams, "ground_class", "--ground-class", show_default=True, type=click.IntRange(0, 255),
          help="Class of ground points (DTM)."),
)
@param_group(
    "site",
    bound(SolarParams, "latitude", "--latitude", type=FiniteFloatRange(-90, 90), default=None,
          help="Site latitude in degrees for the sun (default: from the CRS)."),
    bound(SolarParams, "longitude", "--longitude", type=FiniteFloatRange(-180, 180), default=None,
          help="Site longitude in degrees for the sun (default: from the CRS)."),
    bound(SolarParams, "linke_turbidity", "--linke-turbidity", type=positive_float, show_default=True,
          help="Linke turbidity factor of the clear-sky model (ESRA); 3-4 is typical in central Europe."),
)
@param_group(
    "maps",
    bound(BuildingsParams, "solar_map_cell", "--solar-cell", show_default=True, type=positive_float,
          help="Cell (m) of the roof solar map solar_roofs.tif (kWh/m2/year per cell, each shaded by the DSM)."),
)
@click.option("--workers", type=click.IntRange(1, 512), default=None,
              help="Worker processes of a local Dask cluster that model the buildings in batches (default: all in "
                   "this process); the same models either way.")
@click.option("--scheduler", default=None, help="Address of a running Dask scheduler, e.g. tcp://host:8786, that "
                                                "models the buildings instead of a local cluster.")
@click.option("--no-solar", is_flag=True, help="Skip the solar potential (solar_kwh_m2_year becomes null, no solar_roofs.tif or .png).")
@overwrite_option
@read_options
@json_option
def buildings(src, out_dir, footprints_path, run_classifier, classes, site, maps, workers, scheduler, no_solar,
              overwrite, read_opts, as_json):
    """Model the buildings of IN: roof planes (region growing + RANSAC), footprints (traced and
    regularised, or --footprints), LoD1.2 blocks and LoD2.2 roofs (closed solids, as CityJSON,
    glTF and OBJ), and the clear-sky annual irradiation of every roof face shaded by the DSM,
    also mapped per roof cell in solar_roofs.tif. With --workers N or --scheduler the footprint
    outlines, roof planes and models are made on a Dask cluster, batches of buildings at once."""
    import time
    from pathlib import Path

    import numpy as np

    from workstation.buildings.pipeline import reconstruct_buildings
    from workstation.core.errors import doing
    from workstation.io import check_outputs, read_cloud, work_folder

    if scheduler and workers:
        raise click.UsageError("--workers sizes a local cluster; an external --scheduler has its own workers")
    t0 = time.perf_counter()
    out = Path(out_dir)
    paths = [out / name for name in OUTPUTS] + ([] if no_solar else [out / SOLAR_MAP, out / SOLAR_PNG])
    if out.is_dir():
        check_outputs(paths, overwrite, inputs=[src])
    cloud = read_cloud(src, **read_opts)
    footprints = None
    if footprints_path:
        from workstation.buildings.export import read_footprints

        footprints = read_footprints(footprints_path, cloud.crs)
    if run_classifier:
        from workstation.ml.classifier import PointClassifier

        with doing("classifying"):
            cloud = PointClassifier.load(None, device="cpu").classify(cloud)
    if "classification" not in cloud.attrs:
        from workstation.core.errors import InvalidInputError

        raise InvalidInputError("has no classification", "pass --classify or classify it with ws classify", path=src)
    solar = None if no_solar else _solar_params(cloud, site)
    params = BuildingsParams(**classes, **maps, solar=solar)
    with doing(f"modelling the buildings of {src}"):
        result = reconstruct_buildings(cloud.xyz, np.asarray(cloud.attrs["classification"]), params, footprints,
                                       workers=workers or 1, scheduler=scheduler)
    with work_folder(out):
        _write(result, paths, cloud.crs, overwrite, src)
    _report(src, out, result, solar, time.perf_counter() - t0, as_json, paths)


def _solar_params(cloud, site: dict):
    """SolarParams at the given (``site``: latitude, longitude, linke_turbidity) or the
    CRS-derived site; None (with a warning) without either."""
    from workstation.core.log import get_logger

    latitude, longitude = site["latitude"], site["longitude"]
    if latitude is None or longitude is None:
        lon_lat = _site_from_crs(cloud)
        if lon_lat is None:
            get_logger(__name__).warning("no CRS and no --latitude/--longitude: solar potential skipped")
            return None
        longitude = lon_lat[0] if longitude is None else longitude
        latitude = lon_lat[1] if latitude is None else latitude
    return SolarParams(latitude=latitude, longitude=longitude, linke_turbidity=site["linke_turbidity"],
                       elevation=float(max(0.0, float(cloud.xyz[:, 2].min()))))


def _site_from_crs(cloud):
    """(longitude, latitude) of the cloud's centre from its CRS, or None."""
    if not cloud.crs:
        return None
    try:
        from pyproj import Transformer

        c = (cloud.xyz.min(axis=0) + cloud.xyz.max(axis=0)) / 2
        lon, lat = Transformer.from_crs(cloud.crs, "EPSG:4326", always_xy=True).transform(c[0], c[1])
    except Exception:
        return None
    return (lon, lat) if all(map(lambda v: v == v and abs(v) <= 180, (lon, lat))) else None


def _write(result, paths, crs, overwrite, src):
    import json

    from workstation.buildings.export import (cityjson_document, footprints_geojson, glb_scene, mtl_text, obj_text,
                                              roofs_geojson)
    from workstation.io import atomic_path

    docs = [footprints_geojson(result.models, crs), roofs_geojson(result.models, result.solar_kwh_m2_year, crs),
            cityjson_document(result.models, result.solar_kwh_m2_year, crs)]
    for doc, path in zip(docs, paths[:3]):
        with atomic_path(path, overwrite, inputs=[src]) as tmp:
            tmp.write_text(json.dumps(doc, separators=(",", ":"), allow_nan=False), encoding="utf-8")
    with atomic_path(paths[3], overwrite, inputs=[src]) as tmp:
        tmp.write_bytes(glb_scene(result.models).export(file_type="glb"))
    for lod, path in (("2.2", paths[4]), ("1.2", paths[5])):
        with atomic_path(path, overwrite, inputs=[src]) as tmp:
            tmp.write_text(obj_text(result.models, lod, paths[6].name, crs), encoding="utf-8")
    with atomic_path(paths[6], overwrite, inputs=[src]) as tmp:
        tmp.write_text(mtl_text(), encoding="utf-8")
    if result.solar_map is not None:
        from workstation.core.products import Raster
        from workstation.io.geotiff import write_raster

        arr, transform = result.solar_map
        write_raster(Raster(arr, transform, crs, NODATA, {"kind": "solar_roofs", "units": "kWh/m2/year"}),
                     paths[7], overwrite=overwrite, inputs=[src])
        from workstation.buildings.solar import solar_map_png

        solar_map_png(arr, transform, paths[8], overwrite=overwrite, inputs=[src])


def _report(src, out, result, solar, seconds, as_json, paths):
    import numpy as np

    from workstation.cli.summary import count, emit_summary

    kinds = {}
    for m in result.models:
        kinds[m.roof_type] = kinds.get(m.roof_type, 0) + 1
    faces = sum(len(m.roofs) for m in result.models)
    emit_summary("buildings", count(len(result.models), "buildings"), str(out), seconds,
                 [f"{faces} roof faces", ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())),
                  f"footprints from {result.footprint_source}"])
    if as_json:
        sol = np.concatenate(result.solar_kwh_m2_year) if faces else np.zeros(0)
        from workstation.buildings.export import model_origin

        files = [str(p) for p in paths if p.name not in (SOLAR_MAP, SOLAR_PNG) or result.solar_map is not None]
        emit_json({"input": src, "output": str(out), "files": files,
                   "local_origin": model_origin(result.models).tolist(),
                   "buildings": len(result.models), "roof_faces": faces, "roof_types": kinds,
                   "footprint_source": result.footprint_source, "point_spacing_m": result.spacing,
                   "coverage": result.coverage,
                   "solar": None if solar is None else {"latitude": solar.latitude, "longitude": solar.longitude,
                                                         "linke_turbidity": solar.linke_turbidity,
                                                         "median_kwh_m2_year": float(np.nanmedian(sol)) if len(sol) else None},
                   "timings_s": result.timings})
