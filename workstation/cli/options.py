"""Options and helpers shared by every command (output, overwrite, json)."""

from __future__ import annotations

import sys

import click

from workstation.core.jsonutil import dumps

output_option = click.option(
    "-o", "--output", "output", required=True, type=click.Path(dir_okay=False), help="Output file."
)
overwrite_option = click.option("--overwrite", is_flag=True, help="Replace the output if it exists.")
json_option = click.option("--json", "as_json", is_flag=True, help="Print a machine-readable result on stdout.")


def emit_json(obj) -> None:
    """Write one JSON document on stdout (NaN/inf become null)."""
    text = dumps(obj, indent=2)
    sys.stdout.write(text + "\n")
    sys.stdout.flush()
