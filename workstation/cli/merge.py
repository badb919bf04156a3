"""`ws merge IN... -o OUT`: merge registered clouds, keeping every attribute."""

from __future__ import annotations

import json
from pathlib import Path

import click
import numpy as np

from workstation.cli.options import emit_json, json_option, output_option, overwrite_option
from workstation.cli.options import RegistryChoice, field_option, positive_float, read_options
from workstation.cli.pipeline_out import pipeline_out_option, save_pipeline
from workstation.io.textfile import read_text
from workstation.ops.merge import SOURCE_IDS, merge_files


def read_poses(path, n: int) -> list[np.ndarray]:
    """Poses from JSON: a list of 4x4 matrices or an object with ``poses`` (as ``--poses-out`` writes)."""
    from workstation.core.errors import InvalidInputError

    p = Path(path)
    try:
        obj = json.loads(read_text(p))
        poses = [np.asarray(m, dtype=np.float64) for m in (obj["poses"] if isinstance(obj, dict) else obj)]
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InvalidInputError(f"cannot read poses: {e}", path=p) from None
    if len(poses) != n or any(m.shape != (4, 4) for m in poses):
        raise InvalidInputError(f"expected {n} 4x4 poses, one per input", path=p)
    return poses


def _save_merge_pipeline(path, inputs, output, overwrite, read_opts=None) -> None:
    """readers..., filters.merge, writer (plain merges; poses and thinning have no PDAL stage here);
    the readers query what ``read_opts`` selects (:func:`workstation.ops.pdal.read_stages`)."""
    if path:
        from workstation.io import format_of
        from workstation.ops import pdal

        layout = pdal.las_layout(output) if format_of(output)[0] in ("las", "laz") else None
        stages = pdal.read_stages(inputs, read_opts)
        if len(inputs) == 1:  # read_stages merges several inputs only
            stages.insert(1, {"type": "filters.merge"})
        save_pipeline(path, [*stages, pdal.writer(output, layout)], overwrite, inputs)


@click.command("merge")
@click.argument("inputs", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False))
@output_option
@click.option("--poses", "poses_path", type=click.Path(exists=True, dir_okay=False), default=None,
              help="JSON with one 4x4 pose (input -> merged frame) per input.")
@click.option("--register", "do_register", is_flag=True,
              help="Compute the poses with a pose graph (pairwise + loop closures) into the first input's frame.")
@click.option("--poses-out", type=click.Path(dir_okay=False), default=None,
              help="Write the poses and the per-edge residual table of --register as JSON.")
@click.option("--voxel-size", type=positive_float, default=None, help="Keep one point per voxel of this edge (metres).")
@click.option("--duplicate-distance", type=positive_float, default=None,
              help="Drop points closer than this (metres) to an earlier input's points (overlap thinning).")
@field_option(merge_files, "source_ids", "--source-ids", type=RegistryChoice(SOURCE_IDS), show_default=True,
              help="point_source_id of the output: keep the inputs' (flight lines, as PDAL's filters.merge), the "
                   "input number 1, 2, ..., or auto: keep them when an input has non-zero ids (always the input "
                   "number with --poses, --register, --voxel-size or --duplicate-distance).")
@read_options
@pipeline_out_option
@overwrite_option
@json_option
def merge(inputs, output, poses_path, do_register, poses_out, voxel_size, duplicate_distance, source_ids, read_opts,
          pipeline_out, overwrite, as_json):
    """Merge clouds IN... into OUT: union of attributes and point formats, the finest LAS scales.

    Without poses, registration or thinning the files are concatenated chunk by chunk (bounded
    memory), as PDAL's filters.merge does."""
    from workstation.core.errors import InvalidInputError
    from workstation.io import atomic_paths, check_outputs, read_cloud, write_cloud
    from workstation.registration.merge import MergeParams, merge_clouds

    if poses_path and do_register:
        raise InvalidInputError("give either --poses or --register")
    if poses_out and not do_register:
        raise InvalidInputError("--poses-out writes the poses of --register; add --register")
    check_outputs([output, poses_out, pipeline_out], overwrite, inputs=[*inputs, *([poses_path] if poses_path else [])])
    if not (poses_path or do_register or voxel_size or duplicate_distance):
        summary = merge_files(list(inputs), output, source_ids=source_ids, overwrite=overwrite, read_opts=read_opts)
        _save_merge_pipeline(pipeline_out, inputs, output, overwrite, read_opts)
        from workstation.cli.summary import count, emit_summary

        emit_summary("merge", f"{count(summary['points'], 'points')} from {count(len(inputs), 'clouds')}",
                     [output, pipeline_out], details=[f"{len(summary['attributes'])} attributes",
                                                      f"source ids {summary['source_ids']}"])
        if as_json:
            emit_json({"output": str(output), "inputs": len(inputs), **summary})
        return
    clouds = [read_cloud(p, **read_opts) for p in inputs]
    poses = read_poses(poses_path, len(clouds)) if poses_path else None
    summary = {}
    if do_register:
        from workstation.registration.posegraph import MultiwayParams, register_multiway

        mw = register_multiway(clouds, MultiwayParams())
        poses = mw.poses
        summary["registration"] = mw.to_dict()
    merged = merge_clouds(clouds, poses, MergeParams(duplicate_distance=duplicate_distance, voxel_size=voxel_size))
    if not poses_out:
        write_cloud(merged, output, overwrite=overwrite, inputs=inputs)
    else:  # both files or neither
        with atomic_paths([output, poses_out], overwrite, inputs=inputs) as (cloud_tmp, poses_tmp):
            write_cloud(merged, cloud_tmp, overwrite=True)
            poses_tmp.write_text(json.dumps(summary["registration"], indent=2, default=float))
    from workstation.cli.summary import count, emit_summary

    emit_summary("merge", f"{count(merged.n, 'points')} from {count(len(inputs), 'clouds')}", [output, poses_out],
                 details=[f"{len(merged.dims)} attributes", "registered" if do_register else ""])
    _save_merge_pipeline(pipeline_out, inputs, output, overwrite, read_opts)
    if as_json:
        emit_json({"output": str(output), "points": merged.n, "inputs": len(inputs),
                   "attributes": merged.dims, **summary})
