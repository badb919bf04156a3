"""The compact point network: a per-point MLP on standardised multi-scale features.

Why an MLP on hand-built multi-scale features rather than a point convolution network
(PointNet++, KPConv): the neighbourhood context (heights above local minima up to 40 m,
height above a provisional morphological ground surface, eigenvalue shape at two scales,
echo structure) is computed once, vectorised, in :mod:`workstation.ml.features`; the network
only has to combine it, which a two-hidden-layer MLP does in a few thousand multiply-adds per
point. That keeps inference at hundreds of thousands of points per second on two CPU cores
and training in minutes, and — the point for sim-to-real — the inputs are explicit,
scanner-independent quantities rather than raw coordinates a deep network could overfit to
simulator artefacts. Hackel et al. (2016) and Weinmann et al. (2015) show such multi-scale
features with a shallow classifier reach the accuracy of much heavier models on ALS.

torch is imported inside the functions, never at module import.
"""

from __future__ import annotations

import threading
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager

import numpy as np


def build_mlp(n_in: int, n_out: int, hidden=(64, 64), dropout: float = 0.05):
    """A standardising MLP (``torch.nn.Module``).

    Parameters
    ----------
    n_in, n_out : int
        Feature count and class count.
    hidden : sequence of int
        Hidden layer widths.
    dropout : float

    Returns
    -------
    torch.nn.Module
        Input (b, n_in) float32 -> logits (b, n_out); buffers ``mean``/``std`` hold the feature
        standardisation (set by :func:`set_standardisation`).
    """
    import torch
    from torch import nn

    class PointMLP(nn.Module):
        def __init__(self):
            super().__init__()
            self.register_buffer("mean", torch.zeros(n_in))
            self.register_buffer("std", torch.ones(n_in))
            layers = []
            prev = n_in
            for h in hidden:
                layers += [nn.Linear(prev, int(h)), nn.ReLU()]
                if dropout > 0:
                    layers.append(nn.Dropout(dropout))
                prev = int(h)
            layers.append(nn.Linear(prev, n_out))
            self.net = nn.Sequential(*layers)

        def forward(self, x):
            return self.net((x - self.mean) / self.std)

    return PointMLP()


def set_standardisation(model, X: np.ndarray) -> None:
    """Store per-feature mean and standard deviation of ``X`` (m, f) in the model's buffers."""
    import torch

    mu = X.mean(axis=0)
    sd = X.std(axis=0)
    sd = np.where(sd < 1e-6, 1.0, sd)
    with torch.no_grad():
        model.mean.copy_(torch.as_tensor(mu, dtype=torch.float32))
        model.std.copy_(torch.as_tensor(sd, dtype=torch.float32))


#: Where a network may run: ``auto`` (CUDA when present), ``cpu`` or ``cuda``.
DEVICES = ("auto", "cpu", "cuda")


def resolve_device(device: str = "auto"):
    """``torch.device`` for ``auto`` (CUDA when present), ``cpu`` or ``cuda``.

    ``cuda`` on a machine where torch sees no CUDA device is an :class:`InvalidInputError`
    naming ``--device``, raised here rather than as torch's error at the first tensor moved.
    """
    import torch

    if device == "auto":
        return torch.device("cuda" if torch.cuda.is_available() else "cpu")
    if str(device).startswith("cuda") and not torch.cuda.is_available():
        from workstation.core.errors import InvalidInputError

        why = "this torch has no CUDA support" if torch.version.cuda is None else "no CUDA device is visible"
        raise InvalidInputError(f"--device {device}: {why}", "use --device cpu or auto", field="device")
    return torch.device(device)


def predict_logits(model, X: np.ndarray, device, batch: int = 65_536, threads: int = 1) -> np.ndarray:
    """Softmax probabilities (m, c) float32 of feature rows, in batches, without gradients.

    On the CPU (:func:`_predict_cpu`) batches of 16,384 rows run on one torch thread each,
    shared among up to ``threads`` Python threads when called from the main thread;
    elsewhere ``batch`` rows go to the device at a time.
    """
    import torch

    model.eval()
    if torch.device(device).type == "cpu":
        return _predict_cpu(model, X, threads)
    out = np.empty((len(X), model.net[-1].out_features), np.float32)
    with torch.inference_mode():
        for s in range(0, len(X), batch):
            xb = torch.from_numpy(np.ascontiguousarray(X[s:s + batch])).to(device)
            out[s:s + batch] = torch.softmax(model(xb), dim=1).cpu().numpy()
    return out


#: Rows per CPU batch: a batch's hidden activations (16,384 x 64 float32, 4 MiB) stay in cache.
CPU_BATCH = 16_384


def _predict_cpu(model, X: np.ndarray, threads: int = 1) -> np.ndarray:
    """:func:`predict_logits` on the CPU.

    Each batch is standardised by numpy straight into a C-ordered buffer (``X`` may be the
    feature pass's Fortran-ordered matrix: no separate contiguous copy) with the model's own
    float32 ``(x - mean) / std``, then passed through ``model.net`` on one torch thread
    (:func:`_one_torch_thread`): torch's own threads would spin-wait between the small
    layers, costing CPU time that other work on the machine needs. Called from the main
    thread, the batches are shared out in contiguous runs among ``threads`` Python threads
    (:func:`_batch_runs`), each running torch on one thread: the cores work without waiting
    on each other. Each row goes through the same kernels whatever the batching and the
    thread, so the values do not depend on them.
    """
    import torch

    out = np.empty((len(X), model.net[-1].out_features), np.float32)
    mean, std = model.mean.cpu().numpy(), model.std.cpu().numpy()

    def run(starts):  # one run of batches, with its own buffer
        buf = np.empty((CPU_BATCH, X.shape[1]), np.float32)
        with torch.inference_mode():
            for s in starts:
                e = min(s + CPU_BATCH, len(X))
                xb = buf[:e - s]
                np.subtract(X[s:e], mean, out=xb)
                np.divide(xb, std, out=xb)
                out[s:e] = torch.softmax(model.net(torch.from_numpy(xb)), dim=1).numpy()

    with _one_torch_thread() as main:
        runs = _batch_runs(len(X), threads if main else 1)
        if len(runs) == 1:
            run(runs[0])
            return out
        with ThreadPoolExecutor(max_workers=len(runs) - 1) as pool:
            helpers = [pool.submit(run, r) for r in runs[1:]]
            run(runs[0])
            for h in helpers:
                h.result()
    return out


def _batch_runs(n: int, threads: int) -> list:
    """The starts of the ``CPU_BATCH``-row batches of ``n`` rows in at most ``threads``
    contiguous runs of nearly equal length (one run: all of them, in order)."""
    starts = np.arange(0, n, CPU_BATCH)
    return [r.tolist() for r in np.array_split(starts, max(min(threads, len(starts)), 1))]


@contextmanager
def _one_torch_thread():
    """Run torch on one intra-op thread inside the block when called from the main thread,
    restoring its count after; yields whether it did. Torch keeps the count per thread, but
    a thread that first uses torch takes the count last set anywhere as its own for good, so
    other threads (a Dask worker's, say) are left as they are rather than risk leaving them
    on one thread; the threads started inside the block (:func:`_predict_cpu`'s) take the
    one thread."""
    import torch

    if threading.current_thread() is not threading.main_thread():
        yield False
        return
    before = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        yield True
    finally:
        torch.set_num_threads(before)
