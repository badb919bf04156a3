"""`ws train RECIPE.toml -o MODEL.pt`: train the point classifier on simulated LiDAR."""

from __future__ import annotations

import click

from .options import emit_json, json_option, output_option, overwrite_option


@click.command()
@click.argument("recipe", metavar="RECIPE.toml", type=click.Path(dir_okay=False))
@output_option
@overwrite_option
@click.option("--baseline", is_flag=True, help="Also fit the random-forest baseline on the same rows and report it.")
@json_option
def train(recipe, output, overwrite, baseline, as_json):
    """Simulate the recipe's training tiles (deterministic, domain-randomised), train with early
    stopping on a simulated validation split, and write MODEL.pt plus MODEL.card.json."""
    from workstation.ml.train import train_from_recipe

    card = train_from_recipe(recipe, output, overwrite=overwrite, baseline=baseline)
    from workstation.cli.summary import count, emit_summary

    emit_summary("train", f"model, {count(card['epochs'], 'epochs')}", card["model_path"], card["total_seconds"],
                 details=f"validation accuracy {card['validation']['accuracy']:.4f}")
    if as_json:
        emit_json(card)
