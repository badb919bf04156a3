"""`ws run PROJECT.toml`: process a whole survey chunk by chunk on a Dask cluster."""

from __future__ import annotations

import click

from workstation.cli.options import allow_outside_option

from .options import emit_json, json_option

STAGES = ["index", "noise", "ground", "classify", "hag", "dem", "density", "hillshade", "contours", "qc", "sfm", "dense",
          "mesh", "register"]


@click.command()
@click.argument("project", type=click.Path(dir_okay=False))
@click.option("--out", type=click.Path(file_okay=False), default=None,
              help="Output folder (default: the project file's folder).")
@click.option("--scheduler", default=None, help="Address of a running Dask scheduler, e.g. tcp://host:8786.")
@click.option("--workers", type=click.IntRange(1, 512), default=None,
              help="Worker processes of the local cluster (default: one per core).")
@click.option("--rerun-from", type=click.Choice(STAGES), default=None, help="Run this stage and the later ones again.")
@click.option("--end-with", type=click.Choice(STAGES[1:]), default=None, help="Stop after this stage.")
@click.option("--dry-run", is_flag=True, help="Show what would run and what is up to date; run nothing.")
@allow_outside_option
@json_option
def run(project, out, scheduler, workers, rerun_from, end_with, dry_run, as_json):
    """Run PROJECT (a project.toml): every stage it asks for over every chunk of its tiles.

    Chunks are read with their buffer, processed on a Dask cluster (a local one unless
    --scheduler is given) and written once; raster tiles are joined into Cloud-Optimized
    GeoTIFF mosaics. Photos are oriented, densified and meshed as one block (OUT/sfm, OUT/dense,
    OUT/mesh); scans are registered onto a reference, one task each, and merged (OUT/register).
    A second run does only what changed (run.json in the output folder). --end-with STAGE runs
    STAGE and the stages before it on its branch (clouds, photos or scans). Exit code 0 when
    complete, 3 when some chunk or scan failed (the others are written).
    """
    from workstation.pipeline.runner import RunOptions, run_project
    from workstation.pipeline.summary import print_summary

    if scheduler and workers:
        raise click.UsageError("--workers sizes a local cluster; an external --scheduler has its own workers")
    opts = RunOptions(out=out, scheduler=scheduler, workers=workers, rerun_from=rerun_from, end_with=end_with,
                      dry_run=dry_run)
    result = run_project(project, opts)
    print_summary(result)
    if as_json:
        emit_json(result.summary)
    if result.status == "incomplete":
        raise click.exceptions.Exit(3)
