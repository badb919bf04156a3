"""Train a point classifier from a simulated-dataset recipe and write the model and its card."""

from __future__ import annotations

import json
import os
import platform
import time
from pathlib import Path

import numpy as np

from workstation.core.log import get_logger

from .classifier import PointClassifier
from .dataset import MODEL_CLASSES, build_tileset, load_dataset_recipe

log = get_logger(__name__)

_TRAIN_KEYS = ("model", "hidden", "dropout", "weight_decay", "epochs", "batch", "lr", "patience", "time_budget_s", "n_estimators",
               "max_depth", "seed", "device", "ignore_features")


def split_scores(clf: PointClassifier, X: np.ndarray, y: np.ndarray) -> dict:
    """Accuracy, per-class F1 and ground/object total error (%) on feature rows."""
    P = clf.predict_proba_features(clf._mask(np.array(X, np.float32)))
    k = P.argmax(1)
    out = {"rows": int(len(y)), "accuracy": float((k == y).mean())}
    f1 = {}
    for i, name in enumerate(MODEL_CLASSES):
        tp = float(((k == i) & (y == i)).sum())
        den = float((k == i).sum() + (y == i).sum())
        if (y == i).any():
            f1[name] = 2 * tp / den if den else float("nan")
    out["f1"] = f1
    out["ground_total_error_pct"] = float(100 * ((k == 0) != (y == 0)).mean())
    return out


def train_from_recipe(recipe_path, out, overwrite: bool = False, baseline: bool = False, progress: bool = True) -> dict:
    """Build the simulated dataset of ``recipe_path``, train, save the model and a card.

    Parameters
    ----------
    recipe_path : path
        Dataset recipe TOML (see ``datasets_synth/ml_train.toml``).
    out : path
        Model file (``.pt``); the card is written beside it as ``<stem>.card.json``.
    overwrite : bool
    baseline : bool
        Also fit the random-forest baseline on the same rows and report its scores.

    Returns
    -------
    dict
        The card: recipe, seed, dataset size, timings (wall and CPU), hardware, epochs,
        validation scores (and the baseline's).
    """
    from workstation.io import atomic_path, check_output

    recipe = load_dataset_recipe(recipe_path)
    out = Path(out)
    card_path = out.with_suffix(".card.json")
    check_output(out, overwrite)
    check_output(card_path, overwrite)
    t0, c0 = time.perf_counter(), time.process_time()
    ts = build_tileset(recipe, progress=progress)
    t_data = time.perf_counter() - t0
    cache = os.environ.get("WS_ML_TILESET_CACHE")
    if cache:  # lets the benchmark fit the baseline on the very same rows
        import pickle

        Path(cache).write_bytes(pickle.dumps(ts))
    vm, use = _split_rows(ts, recipe)
    kw = {k: recipe.train[k] for k in _TRAIN_KEYS if k in recipe.train}
    kw.setdefault("seed", recipe.seed)
    clf = PointClassifier(**kw)
    clf.fit_arrays(ts.X[~vm & use], ts.y[~vm & use], ts.X[vm], ts.y[vm], progress=progress)
    card = _card(recipe_path, recipe, ts, vm, use, clf, t_data, t0, c0)
    if baseline:
        rf = PointClassifier(model="rf", seed=recipe.seed, ignore_features=clf.ignore_features)
        rf.fit_arrays(ts.X[~vm & use], ts.y[~vm & use], ts.X[vm], ts.y[vm])
        card["baseline_rf"] = {"train_seconds": rf.report_.seconds, "validation": split_scores(rf, ts.X[vm], ts.y[vm])}
    clf.meta_ = {"summary": {"recipe": Path(recipe_path).name, "seed": recipe.seed}, "card": {
        k: card[k] for k in ("recipe", "seed", "tiles", "train_rows", "epochs", "best_epoch", "total_seconds")}}
    clf.save(out, overwrite=overwrite)
    with atomic_path(card_path, overwrite=overwrite) as tmp:
        Path(tmp).write_text(json.dumps(card, indent=1, default=float))
    log.info("wrote %s and %s (%.1f s)", out, card_path, card["total_seconds"])
    card["model_path"] = str(out)
    card["card_path"] = str(card_path)
    return card


def _split_rows(ts, recipe) -> tuple[np.ndarray, np.ndarray]:
    """``(validation, use)`` row masks: validation rows are those of the recipe's validation
    tiles (every fifth tile when the recipe gives none or only those); ``use`` drops from
    training the simulated ground rows more than ``train.drop_ground_above_m`` metres from the
    provisional surface (where that surface failed: ridges, embankments), which would teach
    the network to distrust its main cue; validation rows are never dropped."""
    vm = ts.val[ts.tile]
    if not vm.any() or vm.all():
        vm = np.zeros(len(ts.y), bool)
        vm[ts.tile % 5 == 4] = True
    use = np.ones(len(ts.y), bool)
    drop_above = recipe.train.get("drop_ground_above_m")
    if drop_above is not None:
        from .features import FEATURE_NAMES

        use = ~(~vm & (ts.y == 0) & (np.abs(ts.X[:, FEATURE_NAMES.index("hag_prov")]) > float(drop_above)))
    return vm, use


def _card(recipe_path, recipe, ts, vm: np.ndarray, use: np.ndarray, clf: PointClassifier, t_data: float,
          t0: float, c0: float) -> dict:
    """The model card: recipe and seed, dataset and split sizes, timings (seconds, wall since
    ``t0`` and CPU since ``c0``), training curve, validation scores, hardware, tile draws."""
    rep = clf.report_
    return {
        "recipe": str(recipe_path),
        "seed": recipe.seed,
        "classes": list(MODEL_CLASSES),
        "tiles": len(ts.info),
        "validation_tiles": int(ts.val.sum()),
        "train_rows": int((~vm & use).sum()),
        "dropped_ground_rows": int((~use).sum()),
        "validation_rows": int(vm.sum()),
        "class_rows": np.bincount(ts.y, minlength=len(MODEL_CLASSES)).tolist(),
        "dataset_seconds": t_data,
        "train_seconds": rep.seconds,
        "total_seconds": time.perf_counter() - t0,
        "total_cpu_seconds": time.process_time() - c0,
        "epochs": rep.epochs,
        "best_epoch": rep.best_epoch,
        "train_loss": rep.train_loss,
        "val_loss": rep.val_loss,
        "validation": split_scores(clf, ts.X[vm], ts.y[vm]),
        "hardware": {"machine": platform.machine(), "processor": platform.processor(), "python": platform.python_version(),
                     "cpu_count": __import__("os").cpu_count()},
        "tile_draws": ts.info,
    }
