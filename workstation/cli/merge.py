"""`ws merge IN... -o OUT`: merge registered clouds, keeping every attribute."""

from __future__ import annotations

import json
from pathlib import Path

import click
import numpy as np

from workstation.cli.options import emit_json, json_option, output_option, overwrite_option
from workstation.cli.options import positive_float
from workstation.io.textfile import read_text


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
@overwrite_option
@json_option
def merge(inputs, output, poses_path, do_register, poses_out, voxel_size, duplicate_distance, overwrite, as_json):
    """Merge clouds IN... into OUT: union of attributes, point_source_id = input number (1, 2, ...)."""
    from workstation.core.errors import InvalidInputError
    from workstation.io import atomic_paths, check_outputs, read_cloud, write_cloud
    from workstation.registration.merge import MergeParams, merge_clouds

    if poses_path and do_register:
        raise InvalidInputError("give either --poses or --register")
    if poses_out and not do_register:
        raise InvalidInputError("--poses-out writes the poses of --register; add --register")
    check_outputs([output, poses_out], overwrite, inputs=[*inputs, *([poses_path] if poses_path else [])])
    clouds = [read_cloud(p) for p in inputs]
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
    if as_json:
        emit_json({"output": str(output), "points": merged.n, "inputs": len(inputs),
                   "attributes": merged.dims, **summary})
