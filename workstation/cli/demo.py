"""`ws demo`: the whole chain on a generated synthetic scene; prints where the products are."""

from __future__ import annotations

import click

from .options import nonneg_int


@click.command()
@click.option("-o", "--output", "outdir", default="demo_output", show_default=True,
              type=click.Path(file_okay=False), help="Folder for the products.")
@click.option("--seed", type=nonneg_int, default=0, show_default=True, help="Seed of the synthetic scene.")
@click.option("--overwrite", is_flag=True, help="Reuse an existing, non-empty output folder.")
def demo(outdir, seed, overwrite):
    """Generate a synthetic scene and run every stage on it."""
    from pathlib import Path

    from workstation.core.errors import OutputExistsError
    from workstation.pipeline.demo import run_demo

    out = Path(outdir)
    if out.exists() and any(out.iterdir()) and not overwrite:
        raise OutputExistsError(out, "pass --overwrite to reuse the folder")

    def report(title, seconds, made):
        click.echo(f"[{seconds:6.1f} s] {title}", err=True)
        for key, path in made.items():
            paths = path if isinstance(path, (list, tuple)) else [path]
            for p in paths:
                click.echo(f"    {key:<16} {p}")

    ctx = run_demo(out, seed=seed, on_step=report)
    click.echo(f"Demo products are in {ctx.outdir.resolve()}")
    from workstation.cli.summary import emit_summary

    emit_summary("demo", "every stage on a synthetic scene", ctx.outdir)
