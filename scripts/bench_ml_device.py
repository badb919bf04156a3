"""Benchmark of the point classifier on CPU and CUDA: inference rate, agreement, training rate.

Prints one JSON line per result. Usage::

    PYTHONPATH=. python scripts/bench_ml_device.py FILE.las [FILE.laz ...] [--train-file FILE] [--epochs 5]
        [--train-rows 100000]

For each file, the shipped model (``PointClassifier.load()``, as ``ws classify`` loads it) runs
on ``cpu`` and on ``cuda`` (skipped where torch sees no CUDA device):

* ``ml_device_predict`` (one line per file and device): ``predict`` (the whole pipeline of
  ``ws classify`` without the file I/O: features, network, gate, understorey, roof test,
  water) timed once after one warm-up run on the same cloud, and the network alone
  (``predict_proba_features`` on the file's precomputed features, host-device copies
  included; best of three after a warm-up), both as points/s.
* ``ml_device_agreement`` (one line per file, with CUDA): the share of identical ASPRS codes of
  the two ``predict`` runs, and the largest absolute difference of the network's probabilities
  on the same features.

Then ``ml_device_train`` (one line per device): ``fit_arrays`` of a small MLP for a fixed number
of epochs (no early stop) on class-balanced rows of one file's features with its own
labels (``--train-file``, default the first), timed after a one-epoch warm-up. A speed figure only: the model is validated on rows
of the same file, so its loss and accuracy say nothing of generalisation.

CPU figures are those of the machine the script runs on (``cores``, ``torch_threads`` say
which); torch's intra-op threads are left at torch's default for inference, and training
on the CPU runs with one thread, as ``PointClassifier.fit`` sets it.
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

import numpy as np


def emit(**kw):
    print(json.dumps(kw, default=float), flush=True)


def _devices():
    import torch

    devs = ["cpu"]
    if torch.cuda.is_available():
        devs.append("cuda")
    else:
        emit(bench="ml_device_note", note="CUDA not available: cuda runs skipped",
             torch=torch.__version__, torch_cuda=torch.version.cuda)
    return devs


def _device_name(dev: str) -> str:
    import torch

    if dev == "cuda":
        return torch.cuda.get_device_name(0)
    return f"cpu x{os.cpu_count()}"


def _sync(dev: str):
    if dev == "cuda":
        import torch

        torch.cuda.synchronize()


def predict_file(path: Path, devs, repeats: int = 3):
    import torch

    from workstation.io import read_cloud
    from workstation.ml.classifier import PointClassifier

    cloud = read_cloud(path)
    base = PointClassifier.load(None, device="cpu")
    base.features(cloud[: min(cloud.n, 5000)])  # warm-up of the feature pass
    t0 = time.perf_counter()
    F = base.features(cloud)
    feat_s = time.perf_counter() - t0
    codes, probs = {}, {}
    for dev in devs:
        clf = PointClassifier.load(None, device=dev)
        clf.predict(cloud)  # warm-up: imports, CUDA context and kernels, allocator
        _sync(dev)
        t0 = time.perf_counter()
        codes[dev] = clf.predict(cloud)
        _sync(dev)
        pred_s = time.perf_counter() - t0
        probs[dev] = clf.predict_proba_features(F)  # warm-up of the network alone
        best = float("inf")
        for _ in range(repeats):
            _sync(dev)
            t0 = time.perf_counter()
            clf.predict_proba_features(F)
            _sync(dev)
            best = min(best, time.perf_counter() - t0)
        emit(bench="ml_device_predict", file=path.name, points=cloud.n, device=dev, device_name=_device_name(dev),
             predict_seconds=round(pred_s, 4), predict_points_per_s=round(cloud.n / pred_s),
             net_seconds=round(best, 5), net_points_per_s=round(cloud.n / best),
             features_seconds=round(feat_s, 4), torch_threads=torch.get_num_threads(), cores=os.cpu_count())
    if "cuda" in codes:
        same = codes["cpu"] == codes["cuda"]
        d = np.abs(probs["cpu"].astype(np.float64) - probs["cuda"])
        emit(bench="ml_device_agreement", file=path.name, points=cloud.n,
             identical_label_share=float(same.mean()), differing_labels=int((~same).sum()),
             max_abs_dprob=float(d.max()), mean_abs_dprob=float(d.mean()),
             argmax_agreement=float((probs["cpu"].argmax(1) == probs["cuda"].argmax(1)).mean()),
             tf32_matmul=bool(torch.backends.cuda.matmul.allow_tf32))
    return cloud, F


def train_speed(path: Path, cloud, F, devs, epochs: int, rows: int, hidden=(64, 64), batch: int = 2048):
    import torch

    from workstation.ml.classifier import PointClassifier
    from workstation.ml.dataset import asprs_to_model, sample_balanced

    if "classification" not in cloud.attrs:
        emit(bench="ml_device_train", file=path.name, skipped="the file has no classification")
        return
    y = asprs_to_model(np.asarray(cloud.attrs["classification"]))
    i = sample_balanced(y, rows, np.random.default_rng(0))
    X, y = F[i], y[i]
    if len(np.unique(y)) < 2:
        emit(bench="ml_device_train", file=path.name, skipped="a single model class in the file's labels")
        return
    threads = torch.get_num_threads()
    for dev in devs:
        kw = dict(hidden=hidden, batch=batch, patience=epochs + 1, seed=0, device=dev)
        PointClassifier(epochs=1, **kw).fit_arrays(X, y, progress=False)  # warm-up
        _sync(dev)
        clf = PointClassifier(epochs=epochs, **kw).fit_arrays(X, y, progress=False)
        train_threads = torch.get_num_threads()
        torch.set_num_threads(threads)  # fit on the CPU sets one thread: undo for what follows
        rep = clf.report_
        n_train = len(X) - max(len(X) // 10, 1)
        emit(bench="ml_device_train", file=path.name, device=dev, device_name=_device_name(dev),
             note="speed only: fitted and validated on rows of the same file with its own labels",
             rows=int(n_train), val_rows=int(len(X) - n_train), epochs=rep.epochs, batch=batch, hidden=list(hidden),
             seconds=round(rep.seconds, 4), rows_per_s=round(n_train * rep.epochs / rep.seconds),
             seconds_per_epoch=round(rep.seconds / rep.epochs, 4), torch_threads=train_threads,
             final_val_loss=round(rep.val_loss[-1], 5), cores=os.cpu_count())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+", type=Path)
    ap.add_argument("--epochs", type=int, default=5)
    ap.add_argument("--train-file", type=Path, default=None,
                    help="the file (one of FILES) whose labels train the speed model (default: the first)")
    ap.add_argument("--train-rows", type=int, default=100_000)
    ap.add_argument("--repeats", type=int, default=3, help="timed runs of the network alone (best kept)")
    a = ap.parse_args()
    import torch

    t0 = time.perf_counter()
    devs = _devices()
    emit(bench="ml_device_env", torch=torch.__version__, torch_cuda=torch.version.cuda, devices=devs,
         device_names=[_device_name(d) for d in devs], cores=os.cpu_count(), torch_threads=torch.get_num_threads())
    pick = a.train_file or a.files[0]
    train = None
    for f in a.files:
        cloud, F = predict_file(f, devs, a.repeats)
        if f.resolve() == pick.resolve():
            train = (f, cloud, F)
    if train is None:
        raise SystemExit(f"--train-file {pick} is not among the files")
    train_speed(*train, devs, a.epochs, a.train_rows)
    emit(bench="ml_device_total", seconds=round(time.perf_counter() - t0, 2))


if __name__ == "__main__":
    main()
