"""`ws register SOURCE TARGET -o OUT`: register one cloud onto another, write the moved source."""

from __future__ import annotations

import json
from pathlib import Path

import click
import numpy as np

from workstation.cli.options import (
    emit_json,
    json_option,
    output_option,
    overwrite_option,
)
from workstation.cli.options import fraction, positive_float
from workstation.cli.options import RegistryChoice, bound, field_option, param_group, read_options
from workstation.io.textfile import read_text
from workstation.registration.icp import ICP_METHODS, KERNELS, ICPParams
from workstation.registration.register import METHODS, RegisterParams


def read_matrix(path) -> np.ndarray:
    """A 4x4 matrix from a JSON file (a 4x4 list, or an object with ``transform``) or a text file."""
    from workstation.core.errors import InvalidInputError

    p = Path(path)
    try:
        if p.suffix.lower() == ".json":
            obj = json.loads(read_text(p))
            M = np.asarray(obj["transform"] if isinstance(obj, dict) else obj, dtype=np.float64)
        else:
            import warnings

            with warnings.catch_warnings():  # an empty file: the shape check below says so
                warnings.simplefilter("ignore", UserWarning)
                M = np.loadtxt(p, dtype=np.float64)
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InvalidInputError(f"cannot read a 4x4 matrix: {e}", path=p) from None
    if M.shape != (4, 4) or not np.isfinite(M).all():
        raise InvalidInputError(f"expected a finite 4x4 matrix, got shape {M.shape}", path=p)
    return M


def read_pairs(path) -> tuple[np.ndarray, np.ndarray]:
    """Point pairs from a CSV/text file: 6 numbers per row ``sx sy sz tx ty tz`` (header allowed)."""
    from workstation.core.errors import InvalidInputError

    p = Path(path)
    rows = []
    for line in read_text(p).splitlines():
        parts = line.replace(",", " ").split()
        if not parts or line.lstrip().startswith("#"):
            continue
        try:
            vals = [float(x) for x in parts[-6:]]
        except ValueError:
            continue  # header
        if len(vals) == 6:
            rows.append(vals)
    if len(rows) < 3:
        raise InvalidInputError(f"{len(rows)} point pairs read; need at least 3 rows of 'sx sy sz tx ty tz'", path=p)
    a = np.asarray(rows)
    return a[:, :3], a[:, 3:]


def write_matrix(result, tmp: Path) -> None:
    """The result as JSON (``.json``) or the 4x4 matrix as text (any other extension)."""
    if tmp.suffix.lower() == ".json":
        tmp.write_text(json.dumps(result.to_dict(), indent=2, default=float))
    else:
        np.savetxt(tmp, result.transform, fmt="%.12g")


@click.command("register")
@click.argument("source", type=click.Path(exists=True, dir_okay=False))
@click.argument("target", type=click.Path(exists=True, dir_okay=False))
@output_option
@field_option(RegisterParams, "method", "--method", type=RegistryChoice(METHODS, extra=["pairs"]), show_default=True,
              help="Coarse method (auto tries clique and RANSAC, verified by ICP; planes matches large planes, for "
                   "indoor scans); icp = fine only from --init; "
                   "similarity = 7 DoF for SfM <-> LiDAR (a search over scale hypotheses unless --init or "
                   "--pairs --scale gives a start, then 7-DoF point-to-plane ICP); pairs = only the --pairs fit.")
@param_group(
    "icp",
    bound(ICPParams, "method", "--fine", "fine", type=RegistryChoice(ICP_METHODS), show_default=True,
          help="Fine ICP variant."),
    bound(ICPParams, "kernel", "--kernel", type=RegistryChoice(KERNELS), show_default=True,
          help="Robust kernel of the fine stage."),
)
@param_group("given", bound(RegisterParams, "voxel_size", "--voxel-size", type=positive_float,
                            help="Voxel edge in metres (CRS units) from which every radius derives; estimated when omitted."))
@click.option("--init", "init_path", type=click.Path(exists=True, dir_okay=False), default=None,
              help="Initial 4x4 source->target matrix (JSON or text).")
@click.option("--pairs", "pairs_path", type=click.Path(exists=True, dir_okay=False), default=None,
              help="CSV of >= 3 picked point pairs 'sx sy sz tx ty tz' (metres) giving the initial transform.")
@click.option("--scale", "with_scale", is_flag=True, help="Estimate a scale from --pairs (7 DoF).")
@param_group("given", bound(RegisterParams, "min_fitness", "--min-fitness", type=fraction, show_default=True,
                            help="Smallest accepted overlap (share of source points with a correspondence)."))
@click.option("--matrix-out", type=click.Path(dir_okay=False), default=None,
              help="Also write the result: .json (all fields) or text (the 4x4 matrix).")
@read_options
@overwrite_option
@json_option
def register(source, target, output, method, icp, given, init_path, pairs_path, with_scale, matrix_out, read_opts,
             overwrite, as_json):
    """Register SOURCE onto TARGET and write the transformed SOURCE to OUT.

    The transform maps SOURCE coordinates into TARGET's frame. --bounds/--resolution/--level
    select the points read from both clouds (the moved SOURCE written holds only those). A result with too little overlap
    or no convergence is an error (exit 1) with a hint, not a silently wrong matrix.
    """
    import time

    from workstation.core.errors import InvalidInputError, doing
    from workstation.io import atomic_paths, check_outputs, read_cloud, write_cloud
    from workstation.registration.merge import transform_cloud
    from workstation.registration.register import register as run_register
    from workstation.registration.transforms import register_point_pairs

    inputs = [source, target, *(p for p in (init_path, pairs_path) if p)]
    check_outputs([output, matrix_out], overwrite, inputs=inputs)
    t0 = time.perf_counter()
    src = read_cloud(source, **read_opts)
    tgt = read_cloud(target, **read_opts)
    init = read_matrix(init_path) if init_path else None
    pair_fit = None
    if pairs_path:
        a, b = read_pairs(pairs_path)
        with doing(f"fitting the point pairs of {pairs_path}"):
            pair_fit = register_point_pairs(a, b, with_scale=with_scale)
        init = pair_fit.result.transform
    if method == "pairs":
        if pair_fit is None:
            raise InvalidInputError("--method pairs needs --pairs FILE")
        result = pair_fit.result
    else:
        m = "icp" if (init is not None and method == "auto") else method
        params = RegisterParams(method=m, **given, fine=ICPParams(**icp))
        result = run_register(src, tgt, params, init=init)
    moved = transform_cloud(src, result.transform).with_crs(tgt.crs or src.crs)
    moved = moved.with_history("register", {"method": method, "target": str(target), "fitness": result.fitness},
                               time.perf_counter() - t0)
    if not matrix_out:
        write_cloud(moved, output, overwrite=overwrite, inputs=inputs)
    else:  # both files or neither
        with atomic_paths([output, matrix_out], overwrite, inputs=inputs) as (cloud_tmp, matrix_tmp):
            write_cloud(moved, cloud_tmp, overwrite=True)
            write_matrix(result, matrix_tmp)
    from workstation.cli.summary import count, emit_summary

    emit_summary("register", count(moved.n, "points"), [output, matrix_out],
                 details=[f"fitness {result.fitness:.3f}", f"inlier RMSE {result.inlier_rmse:.4g}",
                          "converged" if result.converged else "NOT converged"])
    if as_json:
        d = result.to_dict()
        if pair_fit is not None:
            d["pairs_rmse"] = pair_fit.result.inlier_rmse
            d["pairs_residuals"] = pair_fit.residual_norms.tolist()
        d["output"] = str(output)
        emit_json(d)
