"""`ws evaluate PRED --reference REF`: confusion matrix, ISPRS Type I/II, total error, kappa."""

from __future__ import annotations

import click

from workstation.ground.evaluate import evaluate_clouds

from .options import emit_json, json_option
from .options import fraction, nonneg_float
from .options import IntTuple, bound, field_option, param_group, read_options


@click.command()
@click.argument("pred", metavar="PRED", type=click.Path(dir_okay=False))
@click.option("--reference", "ref", required=True, type=click.Path(dir_okay=False),
              help="Reference: a classified LAS/LAZ, or an ISPRS text sample (x y z label; 0 ground, 1 object).")
@param_group(
    "given",
    bound(evaluate_clouds, "tolerance", "--tolerance", type=nonneg_float, show_default=True,
          help="Largest distance for matching points by coordinates, CRS units."),
    bound(evaluate_clouds, "min_matched", "--min-matched", type=fraction, show_default=True,
          help="Smallest share of the smaller cloud's points that must be matched (fraction)."),
)
@click.option("--plot-dir", type=click.Path(file_okay=False), default=None,
              help="Write errors_plan.png (Type I/II in plan view) and confusion.png into this folder.")
@field_option(evaluate_clouds, "ground_classes", "--ground-classes", type=IntTuple("ground_classes", usage=True),
              show_default=True, help="Classes counted as bare earth in the ground / non-ground view, comma separated "
                   "(e.g. 2,9,11 for simulated truth with water and roads).")
@click.option("--pred-columns", default=None, help="Column spec when PRED is a text file (must hold classification).")
@click.option("--overwrite", is_flag=True, help="Replace the plots in --plot-dir if they exist.")
@read_options
@json_option
def evaluate(pred, ref, given, plot_dir, ground_classes, pred_columns, overwrite, read_opts, as_json):
    """Compare the classes of PRED with a reference (points matched by order or coordinates).

    Prints Type I (ground rejected), Type II (object accepted), total error and Cohen's kappa
    as in the ISPRS filter test (Sithole & Vosselman 2004), and per-class precision, recall
    and F1. With --json the rates are fractions. --bounds keeps the points inside the box in
    both clouds; --resolution/--level read a coarser PRED (a COPC file), matched by coordinates.
    """
    from pathlib import Path

    import numpy as np

    from workstation.ground.evaluate import plot_confusion, plot_errors, read_reference
    from workstation.io import check_outputs, work_folder, read_cloud

    gcls = ground_classes
    if plot_dir:  # before any work: the plots must be new files unless --overwrite
        plots = [Path(plot_dir) / "errors_plan.png", Path(plot_dir) / "confusion.png"]
        if Path(plot_dir).is_dir():
            check_outputs(plots, overwrite, inputs=[pred, ref])
    pc = read_cloud(pred, **read_opts, **({"columns": pred_columns} if pred_columns else {}))
    rc = read_reference(ref, bounds=read_opts["bounds"])
    ev, pi, ri = evaluate_clouds(pc, rc, **given, ground_classes=gcls)
    files = {}
    if plot_dir:
        from workstation.ground.evaluate import reference_classes

        rg = np.isin(reference_classes(rc)[ri], gcls)
        pg = np.isin(np.asarray(pc.attrs["classification"])[pi], gcls)
        with work_folder(plot_dir):
            files["errors_plan"] = str(plot_errors(pc.xyz[pi], rg, pg, plots[0], title=Path(pred).name,
                                                   overwrite=overwrite))
            files["confusion"] = str(plot_confusion(ev, plots[1], overwrite=overwrite))
    from workstation.cli.summary import count, emit_summary

    emit_summary("evaluate", f"{count(ev.n_matched, 'points')} compared", list(files.values()) or None,
                 details=[f"total error {100 * ev.total_error:.2f} %", f"kappa {100 * ev.kappa:.2f} %"])
    if as_json:
        emit_json({**ev.to_dict(), "prediction": pred, "reference": ref, "plots": files})
        return
    out = click.echo
    out(f"points compared   {ev.n_matched} (matched by {ev.matched_by}; unmatched: {ev.n_unmatched_pred} predicted, "
        f"{ev.n_unmatched_ref} reference)")
    out(f"Type I            {100 * ev.type1:6.2f} %   (ground rejected as object)")
    out(f"Type II           {100 * ev.type2:6.2f} %   (object accepted as ground)")
    out(f"total error       {100 * ev.total_error:6.2f} %")
    out(f"kappa             {100 * ev.kappa:6.2f} %")
    out(f"overall accuracy  {100 * ev.overall_accuracy:6.2f} %")
    out("class                          support   precision  recall     F1")
    for s in ev.per_class:
        out(f"{s.code:>3} {s.name[:26]:<26} {s.support:>9}   {s.precision:8.4f}  {s.recall:8.4f}  {s.f1:8.4f}")
    for k, v in files.items():
        out(f"{k}: {v}")
