"""`ws thin IN -o OUT (--voxel SIZE [--keep ...] | --poisson RADIUS)`: keep fewer, real points."""

from __future__ import annotations

import click

from workstation.ops.thin import KEEP, VoxelParams

from .options import RegistryChoice, field_option, json_option, output_option, overwrite_option, positive_float
from .options import read_options
from .pipeline_out import pipeline_out_option


@click.command("thin")
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@output_option
@click.option("--voxel", type=positive_float, default=None, help="Keep one point per voxel of this edge (CRS units).")
@field_option(VoxelParams, "keep", "--keep", type=RegistryChoice(KEEP),
              show_default=True, help="[--voxel] which point of a voxel stays: first in file order, nearest the "
                                      "centroid or the centre of the voxel, lowest or highest.")
@click.option("--poisson", type=positive_float, default=None,
              help="Poisson-disk radius (CRS units): no two kept points closer (PDAL filters.sample).")
@read_options
@pipeline_out_option
@overwrite_option
@json_option
def thin(src, output, voxel, keep, poisson, read_opts, pipeline_out, overwrite, as_json):
    """Thin IN by voxels or Poisson disks; write OUT. Kept points keep every attribute; deterministic."""
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_outputs, format_of, read_cloud, write_cloud
    from workstation.ops.thin import PoissonParams, poisson_thin, voxel_thin

    from .options import emit_json
    from .pipeline_out import save_pipeline

    t0 = time.perf_counter()
    if (voxel is None) == (poisson is None):
        raise click.UsageError("give exactly one of --voxel and --poisson")
    format_of(src)
    format_of(output)
    check_outputs([output, pipeline_out], overwrite, inputs=[src])
    cloud = read_cloud(src, **read_opts)
    out = voxel_thin(cloud, VoxelParams(voxel, keep)) if voxel else poisson_thin(cloud, PoissonParams(poisson))
    write_cloud(out, output, overwrite=overwrite, inputs=[src])
    if pipeline_out:
        from workstation.ops import pdal

        layout = pdal.las_layout(output) if format_of(output)[0] in ("las", "laz") else None
        save_pipeline(pipeline_out, [*pdal.read_stages([src], read_opts), *pdal.thin_stages(voxel, keep, poisson),
                                     pdal.writer(output, layout)], overwrite, [src])
    dt = time.perf_counter() - t0
    get_logger(__name__).info("kept %d of %d points in %.2f s", out.n, cloud.n, dt)
    if as_json:
        emit_json({"input": src, "output": output, "points_in": cloud.n, "points_out": out.n, "seconds": dt})
