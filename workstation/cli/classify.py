"""`ws classify IN -o OUT [--model PATH]`: per-point classes with the point classifier."""

from __future__ import annotations

import click

from workstation.ml.model import DEVICES, resolve_device

from .options import emit_json, json_option, output_option, overwrite_option, read_options
from .options import RegistryChoice, field_option, positive_float


@click.command()
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@output_option
@click.option("--model", "model_path", default=None, type=click.Path(dir_okay=False),
              help="Model file from `ws train` (default: the shipped models/point_classifier.pt).")
@field_option(resolve_device, "device", "--device", type=RegistryChoice(DEVICES), show_default=True,
              help="Where the network runs (auto: CUDA when present).")
@click.option("--tile-points", type=click.IntRange(10_000), default=None,
              help="Above this many points the feature pass's neighbourhoods (its largest memory) are "
                   "computed tile by tile (default 3,000,000); the classes are the same either way.")
@click.option("--roof-tolerance", type=positive_float, default=None,
              help="Roof planarity test: RMS distance (m) to the local plane above which a building point "
                   "is not a roof (default 0.08, the model's setting); raise it for a noisy scan, as with "
                   "lasclassify's -planar.")
@click.option("--no-roof-test", is_flag=True, help="Keep the network's building points as they are.")
@click.option("--raised-patches/--no-raised-patches", default=None,
              help="Take out of the ground the patches that drop by 1 m or more on all sides (roofs, decks the "
                   "ground gate let in; as ws ground --method ml does); default on; off saves about 15 % of "
                   "the time.")
@click.option("--crests/--no-crests", default=None,
              help="Give the ground back the crests of dykes and narrow ridges that the provisional surface cut "
                   "off: raised terrain 2 m or more high none of whose points stands steeper than 45° (plus "
                   "0.5 m) over any lower point, near or far; one such point (an object, a steep spot) keeps "
                   "the whole feature out. Default: the model's setting, off in the shipped model (real crests "
                   "often have steeper parts, and then it takes nothing).")
@click.option("--no-water", is_flag=True,
              help="Leave still water as ground (by default, level single-echo surfaces of 150 m2 or more whose "
                   "banks rise from them become water, class 9).")
@click.option("--no-bridges", is_flag=True,
              help="Leave bridge decks to the network (by default, surfaces spanning a gap at least 2 m below them, "
                   "with the road continuing beyond both ends, become class 17).")
@overwrite_option
@read_options
@json_option
def classify(src, output, model_path, device, tile_points, roof_tolerance, no_roof_test, raised_patches, crests, no_water,
             no_bridges, overwrite, read_opts, as_json):
    """Classify IN into ground, vegetation (3/4/5), building, water, other (1) and noise (7/18);
    writes `classification` and a `confidence` (0-1) to OUT, keeping every other attribute."""
    import time

    import numpy as np

    from workstation.io import check_output, read_cloud, write_cloud
    from workstation.ml.classifier import PointClassifier

    t0 = time.perf_counter()
    check_output(output, overwrite, inputs=[src])
    resolve_device(device)  # --device cuda without CUDA fails before the cloud is read
    clf = PointClassifier.load(model_path, device=device)
    if tile_points:
        clf.tile_points = tile_points
    if roof_tolerance is not None:
        clf.roof_tolerance = roof_tolerance
    if no_roof_test:
        clf.roof_test = False
    if raised_patches is not None:
        clf.raised_patches = raised_patches
    if crests is not None:
        clf.crests = crests
    if no_water:
        clf.water = False
    if no_bridges:
        clf.bridges = False
    cloud = read_cloud(src, **read_opts)
    t1 = time.perf_counter()
    out = clf.classify(cloud)
    t2 = time.perf_counter()
    write_cloud(out, output, overwrite=overwrite, inputs=[src])
    codes, counts = np.unique(np.asarray(out.attrs["classification"]), return_counts=True)
    from workstation.cli.summary import count, emit_summary, percent
    from workstation.core.classes import class_name

    top = sorted(zip(counts.tolist(), codes.tolist()), reverse=True)[:3]
    emit_summary("classify", count(cloud.n, "points"), output, time.perf_counter() - t0,
                 [", ".join(f"{class_name(int(c)).lower()} {percent(k, cloud.n)}" for k, c in top),
                  f"{cloud.n / max(t2 - t1, 1e-9):,.0f} points/s"])
    if as_json:
        emit_json({"input": src, "output": output, "point_count": cloud.n, "classes": dict(zip(codes.tolist(), counts.tolist())),
                   "mean_confidence": float(np.mean(out.attrs["confidence"])), "classify_seconds": t2 - t1,
                   "seconds": time.perf_counter() - t0})
