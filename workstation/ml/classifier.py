"""An sklearn-shaped point classifier: ``PointClassifier(...).fit(clouds).predict(cloud)``.

Two estimators share one harness (the same features, the same labels, the same tiling):
``model="mlp"`` the compact PyTorch network of :mod:`workstation.ml.model` (the shipped
model), and ``model="rf"`` a scikit-learn random forest baseline (Breiman 2001).

Model classes are :data:`workstation.ml.dataset.MODEL_CLASSES` (ground, vegetation, building,
water, other, noise); outputs are ASPRS codes: ground 2, vegetation 3/4/5 by height above the
provisional ground (< 0.5 m, < 2 m, above), building 6, water 9, other 1 (cars, wires,
towers), noise 7 below the ground and 18 above it; bridge decks 17 by a geometric test after
the network (:func:`workstation.ground.bridges.bridge_decks`).

Large clouds have the feature pass's kNN neighbourhoods, its largest memory, computed tile by
tile (square tiles with buffers wide enough that every neighbourhood is the whole cloud's);
the grids, statistics and objects are the whole cloud's, so the classes do not depend on the
tiling.

References
----------
A. Alharthy, J. Bethel (2002). Heuristic filtering and 3D feature extraction from LIDAR data.
ISPRS Archives XXXIV-3A:29-34.
L. Breiman (2001). Random forests. Machine Learning 45:5-32.
"""

from __future__ import annotations

import io
import json
import time
import warnings
from concurrent.futures import Future, ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.core.cloud import Cloud
from workstation.core.cpu import available_cores
from workstation.core.errors import InvalidInputError, NotFittedError, StageError
from workstation.core.log import get_logger
from workstation.ground.bridges import BridgeParams, deck_search
from workstation.ground.common import column_max
from workstation.ground.crests import CrestParams
from workstation.ground.refine import Refine, check_steps, declare, run_chain

from .dataset import MODEL_CLASSES, asprs_to_model, sample_balanced
from .features import (
    FEATURE_NAMES,
    FeatureParams,
    compute_features,
    features_and_segments,
    knn_buffer,
    metric_xyz,
    square_tiles,
)

log = get_logger(__name__)

FORMAT = "workstation-point-classifier/1"
#: Default shipped model.
SHIPPED_MODEL = Path(__file__).resolve().parents[2] / "models" / "point_classifier.pt"
#: The refine steps the classifier can declare (:mod:`workstation.ground.refine`); ``bridges``,
#: when declared, is last: it runs on the classes.
STEPS = ("understorey", "raised_patches", "crests", "water", "bridges")
#: The step switches: a boolean attribute each, overridable per call (:class:`StepSwitches`).
SWITCHES = ("understorey", "raised_patches", "crests", "water", "roof_test", "bridges")
_NOISE = MODEL_CLASSES.index("noise")
_HAG_COL = FEATURE_NAMES.index("hag_prov")
_SLOPE_COL = FEATURE_NAMES.index("ground_slope")


def _segment_mean(P: np.ndarray, labels: np.ndarray, weight: float) -> np.ndarray:
    """Blend each labelled point's object-class probabilities with its segment's mean.

    Column 0 (ground) is kept: the gate decides ground; the segment only decides among the
    other classes, whose blended probabilities are rescaled to the point's own ``1 - P0``.
    Rows with ``labels == 0`` are returned unchanged.
    """
    sel = labels > 0
    if not sel.any():
        return P
    lab = labels[sel]
    k = int(lab.max()) + 1
    cnt = np.maximum(np.bincount(lab, minlength=k), 1).astype(np.float64)
    obj = P[sel, 1:].astype(np.float64)
    obj /= np.maximum(obj.sum(axis=1, keepdims=True), 1e-12)
    mean = np.empty((k, obj.shape[1]))
    for j in range(obj.shape[1]):
        mean[:, j] = np.bincount(lab, weights=obj[:, j], minlength=k) / cnt
    blend = (1.0 - weight) * obj + weight * mean[lab]  # one gather of each point's segment means
    out = P.copy()
    out[sel, 1:] = blend * (1.0 - P[sel, :1])
    return out


@dataclass
class _RoofJob:
    """A roof planarity test under way: the tester (a future of
    :class:`workstation.ml.roofs.RoofTest`), the candidates given to it and the future of
    :func:`_run_roof_job`'s result."""

    tester: object
    tested: np.ndarray
    result: object


@dataclass
class _Started:
    """Work :meth:`PointClassifier._infer` started for :meth:`PointClassifier._codes`: the
    roof test (:class:`_RoofJob`) and the future of the refine chain's ground steps on the
    gate's ground (:meth:`PointClassifier._ground_chain`), None where not started."""

    roof: _RoofJob | None = None
    chain: Future | None = None
    ground: np.ndarray | None = None  # the gate's ground the chain started on
    steps: tuple = ()  # and its steps
    surface: np.ndarray | None = None  # and the points that could be terrain (None: all)

    def chain_for(self, ground: np.ndarray, steps: tuple, surface: np.ndarray | None = None) -> Future | None:
        """The started chain's future when it ran ``steps`` on ``ground`` and ``surface``, else
        None (and the started one, of no use, is cancelled if it has not begun)."""
        if self.chain is None:
            return None
        if self.steps == steps and np.array_equal(self.ground, ground) and _same(self.surface, surface):
            return self.chain
        self.chain.cancel()
        return None


def _same(a: np.ndarray | None, b: np.ndarray | None) -> bool:
    """Both None, or equal arrays."""
    return a is b or (a is not None and b is not None and np.array_equal(a, b))


def _reads_noise(chain) -> bool:
    """Whether a ground step of ``chain`` reads the points that could be terrain (the crest
    step's ``surface``)."""
    return any(isinstance(q, CrestParams) for q in chain)


def _surface(P: np.ndarray, gate: np.ndarray, chain) -> np.ndarray | None:
    """The points that could be terrain, for a chain with the crest step (None otherwise, as
    no other ground step reads them): all but those the network calls noise outside the gate's
    ground, so that a multipath echo does not look like terrain far below the crest beside it."""
    if not _reads_noise(chain):
        return None
    return gate | (P[:, 1:].argmax(axis=1) + 1 != _NOISE)


def _run_roof_job(tester, candidate):
    """The roof test of :class:`_RoofJob`: (tested points, their failures, the vote, the vote's
    KD-tree of the tested points, None when the vote needed none). The vote's tree is built
    beside the plane fits, whether or not the vote will need it."""
    t = tester.result()
    with ThreadPoolExecutor(max_workers=1) as pool:
        pending = []
        tested, bad = t.test(candidate, with_tested=lambda pts: pending.append(pool.submit(t.vote_tree, pts)))
        tree = pending[0].result() if pending and bad.any() and not bad.all() else None
    return tested, bad, t.vote(candidate, tested, bad, tree), tree


def _ground_steps(chain) -> tuple:
    """The ground steps of a declared refine chain (all but ``bridges``)."""
    return tuple(p for p in chain if not isinstance(p, BridgeParams))


@dataclass(frozen=True)
class StepSwitches:
    """Step switches for one call of :meth:`PointClassifier.predict_codes` (None: the
    classifier's own, its attribute of the same name).

    Attributes
    ----------
    understorey, raised_patches, crests, water, bridges : bool or None
        The refine steps of those names (see :class:`PointClassifier`).
    roof_test : bool or None
        The roof planarity test.
    """

    understorey: bool | None = None
    raised_patches: bool | None = None
    crests: bool | None = None
    water: bool | None = None
    roof_test: bool | None = None
    bridges: bool | None = None


@dataclass(frozen=True, eq=False)
class Prediction:
    """What :meth:`PointClassifier.predict_codes` returns.

    Attributes
    ----------
    codes : (n,) uint8
        ASPRS class codes.
    confidence : (n,) float32
        Confidence (0-1) of each point's class.
    proba : (n, len(MODEL_CLASSES)) float32
        The network's model-class probabilities (column 0: ground).
    gate : (n,) bool
        The ground of the gate, before the refine chain (see ``ground_gate`` of
        :class:`PointClassifier`; without the gate, the points whose best class is ground):
        the classifier's own ground vote, e.g. for a vote among several filters
        (:func:`workstation.ml.ground.member_vote_ground`).
    """

    codes: np.ndarray
    confidence: np.ndarray
    proba: np.ndarray
    gate: np.ndarray


@dataclass
class TrainReport:
    """What :meth:`PointClassifier.fit` did.

    Attributes
    ----------
    epochs : int
        Epochs run (early stopping may end before the maximum).
    best_epoch : int
    train_loss, val_loss : list of float
        Per-epoch mean cross-entropy.
    val_accuracy : float
        Accuracy on the validation rows at the best epoch (NaN without validation data).
    seconds : float
        Wall-clock training time (features excluded).
    cpu_seconds : float
        Process CPU time of training.
    """

    epochs: int = 0
    best_epoch: int = 0
    train_loss: list = field(default_factory=list)
    val_loss: list = field(default_factory=list)
    val_accuracy: float = float("nan")
    seconds: float = 0.0
    cpu_seconds: float = 0.0


class PointClassifier:
    """Per-point classifier on multi-scale local features.

    Parameters
    ----------
    model : {"mlp", "rf"}
        The PyTorch MLP or the random-forest baseline.
    hidden : tuple of int
        MLP hidden widths.
    dropout : float
        MLP dropout probability after each hidden layer.
    weight_decay : float
        Adam L2 weight decay.
    epochs : int
        Maximum MLP epochs.
    batch : int
        MLP minibatch size.
    lr : float
        Adam learning rate.
    patience : int
        Early stopping: epochs without validation improvement before stopping.
    time_budget_s : float
        Stop training after this many seconds (wall clock), keeping the best epoch.
    n_estimators, max_depth : int
        Random forest size.
    seed : int
    device : str
        ``auto`` (CUDA when present), ``cpu`` or ``cuda``.
    feature_params : FeatureParams
    tile_points : int
        Above this many points the feature pass's kNN scales are computed tile by tile, each
        tile's core holding about 0.64 of it (memory bound); the classes are the same.
    veg_low_max, veg_medium_max : float
        Height above ground (m) splitting low / medium / high vegetation.
    ignore_features : sequence of str
        Feature names (:data:`FEATURE_NAMES`) set to zero, for inputs that do not transfer
        from simulation to real scans.
    ground_gate : bool
        Call a point ground only when it also lies within SMRF's band of the provisional
        ground surface, ``|hag_prov| <= gate_threshold + gate_scalar * slope`` (Pingel et al.
        2013; metres), and the network gives ground at least ``gate_min_probability``; other
        points take the network's best non-ground class. The physical prior that keeps the
        network's sim-to-real errors off the terrain (see models/MODEL_CARD.md).
    gate_threshold, gate_scalar, gate_min_probability : float
    segment_weight : float
        Context step (0-1): the non-ground class probabilities of a point in a planar raised
        object (a roof candidate, :func:`workstation.ml.features.features_and_segments`) become
        ``(1 - w) * own + w * mean over the object``, so a roof decides as one object and
        the few points the network calls canopy or car follow the rest (segment-based
        classification, Vosselman et al. 2017); the ground probability is left to the gate.
        0 switches it off.
    gate_promote_probability, gate_promote_height : float
        A point outside the band is still ground when the network gives ground at least
        ``gate_promote_probability`` and it lies within ``gate_promote_height`` metres of the
        provisional surface: the network repairs the surface where the morphological filter
        cut into the terrain (ridges, embankments, steep edges).
    steps : tuple of str
        The refine chain after the gate, in order (:mod:`workstation.ground.refine`; names
        from :data:`STEPS`, each run when its switch below is on): ``("understorey",
        "raised_patches", "crests", "water", "bridges")``. The ground the steps take out takes the
        network's best non-ground class. The roof test runs between the ground steps and
        ``bridges``, which, when declared, is last and runs on the classes. Without the gate
        only ``bridges`` runs.
    understorey : bool
        The ``understorey`` step: under canopy (read from the echoes), ground points above the
        lower envelope of the ground leave it
        (:func:`workstation.ground.understorey.refine_understorey`, a step of ``auto``'s chain
        too; needs return numbers, a no-op without them). A rule, not learned.
    roof_test : bool
        Building points whose raw neighbourhood is not planar (neither the disc of the 24
        nearest raised points nor any of its four half-discs fits a plane within
        ``roof_tolerance``; one test per 1 m voxel, each point taking the majority of the 5
        tests nearest to it) take the network's best class other than ground and building
        (:class:`workstation.ml.roofs.RoofTest`, lasclassify's ``-planar`` test), vegetation
        for a point of a pulse with several echoes. A rule, not learned; its settings were
        chosen on the LiDAR HD tile.
    roof_tolerance : float
        RMS distance (m) to the local plane above which a building point fails the roof
        test (0.08); raise it for a noisy scan, as lasclassify's documentation advises for
        its ``-planar``.
    raised_patches : bool
        The ``raised_patches`` step: patches of ground cut off from the terrain by breaks of
        more than 1 m that drop on all sides (roofs, decks, platforms) leave the ground
        (:func:`workstation.ground.patches.raised_patches`, a step of ``auto``'s chain too). A
        rule, not learned; it costs about 15 % of the inference time. Not read from a model
        file: a loaded model has it on unless the caller turns it off (models saved while it
        was off by default stored it off).
    crests : bool
        The ``crests`` step, off by default: where the provisional surface cut off raised
        terrain (a dyke's or a narrow ridge's crest, 2 m or more high, with sides no steeper
        than 45°), the points the gate refused there join the ground when none of them stands
        steeper than 45° (plus 0.5 m) over any lower point, near or far
        (:func:`workstation.ground.crests.crest_fill`); roofs and crowns do, at their walls and
        over the ground beneath, and one such point keeps its whole feature out. It gives back
        the gallery's ridge of sparse old ALS, but not the crests of ISPRS samp61, whose faces
        are steeper than 45° in places and carry objects as steep (docs/benchmarks.md), so it
        is not on unless asked for.
    water : bool
        The ``water`` step: ground points on still water (level, single-echo surfaces of
        150 m² or more whose banks rise from them,
        :func:`workstation.ground.water.water_surfaces`) become water (ASPRS 9); their
        confidence falls from 1 at the surface's level to 0.5 at 0.15 m from it. A rule, not
        learned: the network alone finds almost no water, having neither trustworthy
        intensity nor density inputs. Models saved before load with it on.
    bridges : bool
        The ``bridges`` step: the points of bridge decks (ground-like surfaces dropping
        abruptly on both sides to the gap they span and running on into the terrain at both
        ends; their parapets) become class 17, whatever the network said
        (:func:`workstation.ground.bridges.bridge_decks`, judged on the lowest echoes of every
        class but noise). The network, trained with decks as "other", calls most of a deck
        ground or building. Models saved before load with it on.
    """

    def __init__(self, model: str = "mlp", hidden=(64, 64), dropout: float = 0.05, weight_decay: float = 1e-5, epochs: int = 40, batch: int = 2048,
                 lr: float = 2e-3, patience: int = 5, time_budget_s: float = 3000.0,
                 n_estimators: int = 60, max_depth: int = 18, seed: int = 0, device: str = "auto",
                 feature_params: FeatureParams | None = None, tile_points: int = 3_000_000,
                 veg_low_max: float = 0.5, veg_medium_max: float = 2.0, ignore_features=(),
                 ground_gate: bool = True, gate_threshold: float = 0.5, gate_scalar: float = 1.25,
                 gate_min_probability: float = 0.002, gate_promote_probability: float = 0.9,
                 gate_promote_height: float = 1.5, segment_weight: float = 0.8, understorey: bool = True,
                 roof_test: bool = True, roof_tolerance: float = 0.08, raised_patches: bool = True,
                 crests: bool = False, water: bool = True, bridges: bool = True, steps=STEPS):
        if model not in ("mlp", "rf"):
            raise InvalidInputError(f"unknown model {model!r}", "use 'mlp' or 'rf'", field="model")
        self.model = model
        self.hidden = tuple(int(h) for h in hidden)
        self.dropout = float(dropout)
        self.weight_decay = float(weight_decay)
        self.epochs = int(epochs)
        self.batch = int(batch)
        self.lr = float(lr)
        self.patience = int(patience)
        self.time_budget_s = float(time_budget_s)
        self.n_estimators = int(n_estimators)
        self.max_depth = int(max_depth)
        self.seed = int(seed)
        self.device = device
        self.feature_params = feature_params or FeatureParams()
        self.tile_points = int(tile_points)
        self.veg_low_max = float(veg_low_max)
        self.veg_medium_max = float(veg_medium_max)
        unknown = set(ignore_features) - set(FEATURE_NAMES)
        if unknown:
            raise InvalidInputError(f"unknown features {sorted(unknown)}", f"known: {', '.join(FEATURE_NAMES)}")
        self.ignore_features = tuple(str(f) for f in ignore_features)
        self.ground_gate = bool(ground_gate)
        self.gate_threshold = float(gate_threshold)
        self.gate_scalar = float(gate_scalar)
        self.gate_min_probability = float(gate_min_probability)
        self.gate_promote_probability = float(gate_promote_probability)
        self.gate_promote_height = float(gate_promote_height)
        self.segment_weight = float(segment_weight)
        self.understorey = bool(understorey)
        self.roof_test = bool(roof_test)
        self.roof_tolerance = float(roof_tolerance)
        self.raised_patches = bool(raised_patches)
        self.crests = bool(crests)
        self.water = bool(water)
        self.bridges = bool(bridges)
        self.steps = check_steps(steps, "steps", STEPS)
        if "bridges" in self.steps[:-1]:
            raise InvalidInputError("the bridges step must be the last of steps (it runs on the classes)",
                                    f"e.g. {tuple(n for n in self.steps if n != 'bridges') + ('bridges',)}", field="steps")
        self.net_ = None
        self.rf_ = None
        self.report_: TrainReport | None = None
        self.meta_: dict = {}

    # -- fitting -----------------------------------------------------------------------------
    @property
    def is_fitted(self) -> bool:
        return self.net_ is not None or self.rf_ is not None

    def _check_fitted(self):
        if not self.is_fitted:
            raise NotFittedError("the classifier is not fitted", "call fit(...) or PointClassifier.load(path) first")

    def features(self, cloud: Cloud) -> np.ndarray:
        """Feature matrix (n, f) float32 of a cloud (see :mod:`workstation.ml.features`)."""
        F = compute_features(cloud, self.feature_params)
        return self._mask(F)

    def _mask(self, F: np.ndarray) -> np.ndarray:
        if self.ignore_features:
            F[:, [FEATURE_NAMES.index(f) for f in self.ignore_features]] = 0
        return F

    def fit(self, clouds, samples_per_cloud: int = 50_000, validation=None) -> "PointClassifier":
        """Fit on labelled clouds (their ``classification``).

        Parameters
        ----------
        clouds : Cloud or sequence of Cloud
            Training clouds with ASPRS ``classification``.
        samples_per_cloud : int
            Points drawn per cloud (class-balanced by the square root of frequency).
        validation : sequence of Cloud, optional
            Clouds for early stopping; without them 10 % of the training rows are held out.
        """
        if isinstance(clouds, Cloud):
            clouds = [clouds]
        rng = np.random.default_rng(self.seed)

        def rows(cs):
            Xs, ys = [], []
            for c in cs:
                if "classification" not in c.attrs:
                    raise InvalidInputError("a training cloud has no classification", field="classification")
                F = self.features(c)
                y = asprs_to_model(c.attrs["classification"])
                i = sample_balanced(y, samples_per_cloud, rng)
                Xs.append(F[i])
                ys.append(y[i])
            return np.concatenate(Xs), np.concatenate(ys)

        X, y = rows(clouds)
        Xv = yv = None
        if validation:
            Xv, yv = rows(validation)
        return self.fit_arrays(X, y, Xv, yv)

    def fit_arrays(self, X: np.ndarray, y: np.ndarray, X_val=None, y_val=None, progress: bool = True) -> "PointClassifier":
        """Fit on a feature matrix (m, f) float32 and model-class labels (m,) int."""
        X = self._mask(np.array(X, np.float32))
        y = np.asarray(y, np.int64)
        if X.ndim != 2 or X.shape[1] != len(FEATURE_NAMES) or len(y) != len(X):
            raise InvalidInputError(f"X must be (m, {len(FEATURE_NAMES)}) with one label per row, got {X.shape} / {y.shape}")
        if len(np.unique(y)) < 2:
            raise InvalidInputError("training labels hold a single class", "add clouds with other classes")
        rng = np.random.default_rng(self.seed)
        if X_val is None:
            perm = rng.permutation(len(X))
            nv = max(len(X) // 10, 1)
            X_val, y_val = X[perm[:nv]], y[perm[:nv]]
            X, y = X[perm[nv:]], y[perm[nv:]]
        X_val = self._mask(np.array(X_val, np.float32))
        y_val = np.asarray(y_val, np.int64)
        t0, c0 = time.perf_counter(), time.process_time()
        if self.model == "rf":
            from sklearn.ensemble import RandomForestClassifier

            rf = RandomForestClassifier(n_estimators=self.n_estimators, max_depth=self.max_depth, n_jobs=-1,
                                        random_state=self.seed, min_samples_leaf=2)
            rf.fit(X, y)
            self.rf_ = rf
            self.classes_present_ = rf.classes_
            acc = float((rf.predict(X_val) == y_val).mean())
            self.report_ = TrainReport(1, 1, [], [], acc, time.perf_counter() - t0, time.process_time() - c0)
            return self
        self._fit_mlp(X, y, X_val, y_val, progress)
        self.report_.seconds = time.perf_counter() - t0
        self.report_.cpu_seconds = time.process_time() - c0
        return self

    def _fit_mlp(self, X, y, Xv, yv, progress):
        import torch

        from workstation.core.progress import progress_bar

        from .model import build_mlp, resolve_device, set_standardisation

        torch.manual_seed(self.seed)
        dev = resolve_device(self.device)
        if dev.type == "cpu":
            # a small MLP gains nothing from intra-op threads; on a busy machine they spin
            torch.set_num_threads(1)
        net = build_mlp(X.shape[1], len(MODEL_CLASSES), self.hidden, self.dropout).to(dev)
        set_standardisation(net, X)
        net.to(dev)
        opt = torch.optim.Adam(net.parameters(), lr=self.lr, weight_decay=self.weight_decay)
        sched = torch.optim.lr_scheduler.CosineAnnealingLR(opt, T_max=max(self.epochs, 1))
        lossf = torch.nn.CrossEntropyLoss()
        Xt = torch.from_numpy(X).to(dev)
        yt = torch.from_numpy(y).to(dev)
        Xvt = torch.from_numpy(Xv).to(dev)
        yvt = torch.from_numpy(yv).to(dev)
        g = torch.Generator(device="cpu").manual_seed(self.seed)
        rep = TrainReport()
        best, best_state, bad = float("inf"), None, 0
        t0 = time.perf_counter()
        with progress_bar("training", self.epochs, unit="epochs") as advance:
            for ep in range(self.epochs):
                net.train()
                perm = torch.randperm(len(Xt), generator=g).to(dev)
                tot = 0.0
                for s in range(0, len(perm), self.batch):
                    idx = perm[s:s + self.batch]
                    opt.zero_grad()
                    loss = lossf(net(Xt[idx]), yt[idx])
                    loss.backward()
                    opt.step()
                    tot += float(loss.detach()) * len(idx)
                sched.step()
                net.eval()
                with torch.no_grad():
                    lv = net(Xvt)
                    vl = float(lossf(lv, yvt))
                    va = float((lv.argmax(1) == yvt).float().mean())
                rep.train_loss.append(tot / len(Xt))
                rep.val_loss.append(vl)
                rep.epochs = ep + 1
                log.info("epoch %d: train loss %.4f, val loss %.4f, val acc %.4f", ep + 1, tot / len(Xt), vl, va)
                advance(1)
                if vl < best - 1e-4:
                    best, bad = vl, 0
                    best_state = {k: v.detach().clone() for k, v in net.state_dict().items()}
                    rep.best_epoch, rep.val_accuracy = ep + 1, va
                else:
                    bad += 1
                if bad >= self.patience or time.perf_counter() - t0 > self.time_budget_s:
                    break
        if best_state is None:
            raise StageError("train", "the validation loss never became finite", "check the features for NaN or lower the learning rate")
        net.load_state_dict(best_state)
        net.eval()
        self.net_ = net.cpu()
        self.report_ = rep

    # -- prediction --------------------------------------------------------------------------
    def predict_proba_features(self, F: np.ndarray) -> np.ndarray:
        """Class probabilities (n, len(MODEL_CLASSES)) float32 of a feature matrix."""
        self._check_fitted()
        if self.rf_ is not None:
            p = self.rf_.predict_proba(F)
            out = np.zeros((len(F), len(MODEL_CLASSES)), np.float32)
            out[:, self.rf_.classes_] = p
            return out
        from .model import predict_logits, resolve_device

        dev = resolve_device(self.device)
        if next(self.net_.parameters()).device != dev:
            self.net_ = self.net_.to(dev)
        workers = self.feature_params.workers
        return predict_logits(self.net_, F, dev, threads=available_cores() if workers < 1 else min(workers, available_cores()))

    def _tile_side(self, cloud: Cloud) -> float | None:
        """Side (m) of the square tiles of the feature pass's kNN scales (None: one tile, the
        cloud has at most ``tile_points`` points): a core of about 0.64 ``tile_points`` at
        the cloud's mean density over its bounding box."""
        if cloud.n <= self.tile_points:
            return None
        ext = column_max(metric_xyz(cloud)[0][:, :2])
        area = max(float(ext[0] * ext[1]), 1.0)
        return max(float(np.sqrt(self.tile_points / (cloud.n / area))) * 0.8, 4 * knn_buffer(self.feature_params))

    def _tiles(self, cloud: Cloud):
        """(core mask, tile-with-buffer index array) pairs of the kNN tiles
        (:func:`workstation.ml.features.square_tiles`; one tile when the cloud is small), for
        the tiling benchmark and tests: the buffer is the first one, before the feature pass
        widens it for its stragglers."""
        side = self._tile_side(cloud)
        if side is None:
            yield np.ones(cloud.n, bool), np.arange(cloud.n)
            return
        for core, sel, _rect in square_tiles(metric_xyz(cloud)[0][:, :2], side, knn_buffer(self.feature_params)):
            yield core, sel

    def _roof_tester(self, cloud: Cloud, hag: np.ndarray):
        from .roofs import RoofParams, RoofTest

        return RoofTest(metric_xyz(cloud)[0], hag, RoofParams(tolerance=self.roof_tolerance),
                        workers=self.feature_params.workers)

    def _infer(self, cloud: Cloud, roof: bool = False, chain=()):
        """Probabilities, provisional-ground height and slope, and the work started in the
        background for :meth:`_codes` (:class:`_Started`): (``roof``) the roof test and the
        ground steps ``chain`` of the refine chain (with the gate).

        The roof test's KD-tree is built beside the kNN scales and the network; the ground
        steps start on the gate's ground as soon as the network has run (the segment step
        leaves the ground probability, all the gate reads, as it is; after the segment step
        when a step reads the noise, :func:`_reads_noise`), and the roof test's
        queries on the building points after the segment step and the gate, while the
        ground steps run on; those may add a few building points (tested in :meth:`_codes`).
        Above ``tile_points`` points only the feature pass's kNN scales go tile by tile: every
        value is the one the whole cloud gives (:func:`features_and_segments`)."""
        self._check_fitted()
        if cloud.n < 3:
            raise InvalidInputError(f"needs at least 3 points, got {cloud.n}", field="xyz")
        side = self._tile_side(cloud)
        pool = ThreadPoolExecutor(max_workers=2)
        started = _Started()
        try:
            tester = []  # the roof test's KD-tree, built while the feature pass waits for its kNN threads

            def build(hag):
                tester.append(pool.submit(self._roof_tester, cloud, hag.copy()))

            F, segments = features_and_segments(cloud, self.feature_params, with_hag=build if roof else None,
                                                tile_side=side)
            F = self._mask(F)
            tester = tester[0] if tester else None
            p = self.predict_proba_features(F)
            hs = F[:, [_HAG_COL, _SLOPE_COL]]
            gated = bool(chain) and self.ground_gate
            late = gated and _reads_noise(chain)  # a step reads the noise: after the segment step
            if gated and not late:
                self._start_chain(started, pool, p, hs, cloud, chain)
            if self.segment_weight > 0:
                p = _segment_mean(p, segments, self.segment_weight)
            if late:
                self._start_chain(started, pool, p, hs, cloud, chain)
            if tester is not None:  # the candidates _codes will have, but the refine chain's
                cand = self._building_candidates(p, hs)
                started.roof = _RoofJob(tester, cand, pool.submit(_run_roof_job, tester, cand))
        finally:
            pool.shutdown(wait=False)  # the roof job and the ground steps run on
        return p, hs, started

    def _start_chain(self, started: _Started, pool, P: np.ndarray, hs: np.ndarray, cloud: Cloud, chain) -> None:
        """Start the ground steps ``chain`` on the gate's ground in ``pool``, as :meth:`_codes`
        will run them (its gate, :func:`_surface`), recording their inputs in ``started``."""
        started.ground, started.steps = self._gate(P, hs), tuple(chain)
        started.surface = _surface(P, started.ground, chain)
        started.chain = pool.submit(self._ground_chain, started.ground, cloud, started.steps, started.surface)

    def predict_proba(self, cloud: Cloud) -> np.ndarray:
        """Probabilities (n, len(MODEL_CLASSES)) float32 of the model classes
        (:data:`workstation.ml.dataset.MODEL_CLASSES`)."""
        return self._infer(cloud)[0]

    def _nonplanar(self, candidate: np.ndarray, hag: np.ndarray, cloud: Cloud | None, job: _RoofJob | None) -> np.ndarray | None:
        """Building candidates that fail the roof planarity test (see ``roof_test``); ``job``:
        the test started by :meth:`_infer`, completed here for the candidates it did not have."""
        if cloud is None:
            return None
        if job is None:
            if int(np.count_nonzero(candidate)) < 3:
                return None
            return self._roof_tester(cloud, hag).nonplanar(candidate)
        tested, bad, fail, tree = job.result.result()
        extra = candidate & ~job.tested
        if extra.any():  # the newcomers: their voxels' tests, then their votes among every test
            t = job.tester.result()
            t2, b2 = t.test(extra)
            fail = fail | t.vote_more(extra, tested, bad, tree, t2, b2)
        return fail

    def _gate(self, P: np.ndarray, hs: np.ndarray) -> np.ndarray:
        """Ground of the gate (before the refine chain; :attr:`Prediction.gate`)."""
        hag, slope = hs[:, 0], hs[:, 1]
        band = np.abs(hag) <= self.gate_threshold + self.gate_scalar * slope
        ground = band & (P[:, 0] >= self.gate_min_probability)
        ground |= (P[:, 0] >= self.gate_promote_probability) & (np.abs(hag) <= self.gate_promote_height)
        return ground

    def _building_candidates(self, P: np.ndarray, hs: np.ndarray) -> np.ndarray:
        """Points that are building before the roof test (and the refine chain)."""
        if not self.ground_gate:
            return P.argmax(axis=1) == 2
        return (P[:, 1:].argmax(axis=1) == 1) & ~self._gate(P, hs)

    def switches(self, overrides: StepSwitches | None = None) -> dict[str, bool]:
        """The step switches (:data:`SWITCHES`) of this classifier, those ``overrides`` sets
        replaced."""
        given = {} if overrides is None else {k: v for k, v in asdict(overrides).items() if v is not None}
        return {n: bool(given.get(n, getattr(self, n))) for n in SWITCHES}

    def chain(self, overrides: StepSwitches | None = None) -> tuple:
        """The refine chain (:func:`workstation.ground.refine.declare`): the declared ``steps``
        that are switched on (``overrides``: switches for this call)."""
        return declare(self.steps, self.switches(overrides))

    def codes_from_proba(self, proba: np.ndarray, hag_slope: np.ndarray, cloud: Cloud | None = None,
                         overrides: StepSwitches | None = None) -> tuple[np.ndarray, np.ndarray]:
        """ASPRS codes (n,) uint8 and confidences (n,) float32 from the model-class
        probabilities ``proba`` (n, c) and the provisional-ground height and slope
        ``hag_slope`` (n, 2) of ``cloud``'s points: the gate, the refine chain, the roof test and
        the bridge step, which need ``cloud`` (None: the network's classes through the gate
        only); ``overrides``: step switches for this call."""
        return self._codes(np.asarray(proba), np.asarray(hag_slope), cloud, None, self.switches(overrides))[:2]

    def _codes(self, P: np.ndarray, hs: np.ndarray, cloud: Cloud | None, started: _Started | None,
               on: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """ASPRS codes, confidences and the gate's ground (:attr:`Prediction.gate`) from the
        probabilities and the provisional-ground height and slope; ``cloud`` (the same points)
        enables the refine chain and the roof planarity test (``started``: the work
        :meth:`_infer` started for them, if any, with the ground steps of this chain); ``on``:
        the step switches. The chain's ground steps run on the gate's ground, its ``bridges``
        step on the classes after the roof test (noise is no deck's surface)."""
        hag = hs[:, 0]
        started = started or _Started()
        chain = declare(self.steps, on) if cloud is not None else ()
        xyz = metric_xyz(cloud)[0] if chain else None
        if self.ground_gate:  # (the roof test started by _infer runs on meanwhile)
            gate = self._gate(P, hs)
            steps = _ground_steps(chain)
            surface = _surface(P, gate, steps)
            k, conf = self._gated(P, gate, cloud, steps, started.chain_for(gate, steps, surface), surface)
        else:
            k = P.argmax(axis=1)
            conf = P[np.arange(len(P)), k].astype(np.float32)
            gate = k == 0
        decks = tuple(p for p in chain if isinstance(p, BridgeParams))
        early = None
        if on["roof_test"]:
            nr = None if cloud is None else cloud.attrs.get("number_of_returns")
            with ThreadPoolExecutor(max_workers=1) as pool:
                if len(decks) == 1 and started.roof is not None:  # searched while the roof test ends
                    early = (k, pool.submit(deck_search, xyz, decks[0], k != _NOISE, k == 0))
                k, conf = self._roof_classes(P, k, conf, self._nonplanar(k == 2, hag, cloud, started.roof),
                                             None if nr is None else np.asarray(nr) > 1)
        codes = self._asprs(k, hag)
        if decks:
            codes[self._decks(xyz, k, decks, early)] = C.BRIDGE_DECK
        return codes, conf, gate

    @staticmethod
    def _decks(xyz: np.ndarray, k: np.ndarray, decks: tuple, early=None) -> np.ndarray:
        """(n,) bool: the points of the bridge decks the chain's bridge steps ``decks`` find on
        the model classes ``k`` (ground class 0; noise, class 5, is no deck's surface).
        ``early``: (classes, future of a :func:`workstation.ground.bridges.deck_search` on them)
        made before the roof test, used where it stands for ``k``: the roof test turns building
        points into other classes, never into ground, so the ground is the same and only the
        noise it made leaves the surface (:meth:`workstation.ground.bridges.DeckSearch.without`)."""
        surface, ground = k != _NOISE, k == 0
        if early is not None:
            found = early[1].result()
            moved = np.flatnonzero((early[0] != _NOISE) != surface)
            if not surface[moved].any() and np.array_equal(early[0] == 0, ground):
                return found.deck if len(moved) == 0 else found.without(xyz, decks[0], surface, moved, ground).deck
        return run_chain(Refine(xyz, ground, surface=surface), decks).deck

    def _ground_chain(self, ground: np.ndarray, cloud: Cloud, chain, surface: np.ndarray | None = None) -> Refine:
        """The refine chain's ground steps ``chain`` run on the gate's ground ``ground``
        (``surface``: the points that could be terrain, see :func:`_surface`)."""
        return run_chain(Refine(metric_xyz(cloud)[0], ground, return_number=cloud.attrs.get("return_number"),
                                number_of_returns=cloud.attrs.get("number_of_returns"), surface=surface), chain)

    def _gated(self, P: np.ndarray, ground: np.ndarray, cloud: Cloud | None, chain, done=None,
               surface: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Model classes (n,) and confidences of the gate: its ground ``ground`` refined by
        ``chain`` (``done``: the future of :meth:`_ground_chain`'s state, when started;
        ``surface`` as there) is class 0 (its water class 3), every other point takes the
        network's best non-ground class."""
        water = None
        if chain:
            state = done.result() if done is not None else self._ground_chain(ground, cloud, chain, surface)
            ground, water = state.ground, state.water
        rest = P[:, 1:]
        k2 = rest.argmax(axis=1) + 1
        c2 = rest[np.arange(len(P)), k2 - 1] / np.maximum(1.0 - P[:, 0], 1e-6)
        k = np.where(ground, 0, k2)
        conf = np.where(ground, np.maximum(P[:, 0], 0.5), np.minimum(c2, 1.0)).astype(np.float32)
        if water is not None and water.any():
            k[water] = 3
            conf[water] = state.water_confidence[water]
        return k, conf

    @staticmethod
    def _roof_classes(P: np.ndarray, k: np.ndarray, conf: np.ndarray, fail,
                      multi: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Building points (class 2 of ``k``) that ``fail`` the roof test take the network's best
        class other than ground and building, with its share of those classes' probability;
        those of pulses with several echoes (``multi``: ``number_of_returns > 1``, None when
        unknown) take vegetation: rough and penetrated by the pulse, the canopy signature that
        first/last-pulse methods tell trees from roofs by (Alharthy & Bethel 2002)."""
        if fail is None:
            return k, conf
        fail &= k == 2
        if fail.any():
            others = np.array([1, 3, 4, 5])  # vegetation, water, other, noise
            rows = np.flatnonzero(fail)
            po = P[np.ix_(rows, others)]
            best = others[po.argmax(axis=1)]
            if multi is not None:
                best = np.where(multi[rows], 1, best)
            k = k.copy()
            k[rows] = best
            conf = conf.copy()
            conf[rows] = P[rows, best] / np.maximum(po.sum(axis=1), 1e-6)
        return k, conf

    def _asprs(self, k: np.ndarray, hag: np.ndarray) -> np.ndarray:
        """ASPRS codes (n,) uint8 of model classes ``k``: vegetation by height above the
        provisional ground, noise low (7) below it and high (18) above it."""
        veg = np.where(hag < self.veg_low_max, C.LOW_VEGETATION,
                       np.where(hag < self.veg_medium_max, C.MEDIUM_VEGETATION, C.HIGH_VEGETATION))
        noise = np.where(hag < 0, C.LOW_POINT, C.HIGH_NOISE)
        table = np.array([C.GROUND, 0, C.BUILDING, C.WATER, C.UNCLASSIFIED, 0], np.uint8)
        codes = table[k]
        codes = np.where(k == 1, veg, codes)
        return np.where(k == 5, noise, codes).astype(np.uint8)

    def predict_codes(self, cloud: Cloud, overrides: StepSwitches | None = None) -> Prediction:
        """Codes, confidences, probabilities and the gate's ground of every point
        (:class:`Prediction`); ``overrides``: step switches for this call (e.g.
        ``StepSwitches(roof_test=False)``), the classifier's own left as they are."""
        on = self.switches(overrides)
        P, hag, started = self._infer(cloud, roof=on["roof_test"], chain=_ground_steps(self.chain(overrides)))
        codes, conf, gate = self._codes(P, hag, cloud, started, on)
        return Prediction(codes, conf, P, gate)

    def predict(self, cloud: Cloud) -> np.ndarray:
        """ASPRS class codes (n,) uint8 for every point."""
        return self.predict_codes(cloud).codes

    def classify(self, cloud: Cloud) -> Cloud:
        """A new cloud with ``classification`` (u8 ASPRS) and ``confidence`` (f4, the winning
        class probability); every other attribute is kept unchanged."""
        t0 = time.perf_counter()
        pred = self.predict_codes(cloud)
        if not np.isfinite(pred.confidence).all():
            raise StageError("classify", "non-finite probabilities", "check the input coordinates for NaN")
        out = cloud.with_attrs(classification=pred.codes, confidence=pred.confidence)
        return out.with_history("classify", {"model": self.model, **self.meta_.get("summary", {})}, time.perf_counter() - t0)

    # -- persistence -------------------------------------------------------------------------
    def config(self) -> dict:
        """JSON-able constructor settings."""
        return {"model": self.model, "hidden": list(self.hidden), "dropout": self.dropout,
                "weight_decay": self.weight_decay, "epochs": self.epochs, "batch": self.batch,
                "lr": self.lr, "patience": self.patience, "time_budget_s": self.time_budget_s,
                "n_estimators": self.n_estimators, "max_depth": self.max_depth, "seed": self.seed,
                "device": self.device, "feature_params": self.feature_params.to_dict(),
                "tile_points": self.tile_points, "veg_low_max": self.veg_low_max,
                "veg_medium_max": self.veg_medium_max, "ignore_features": list(self.ignore_features),
                "ground_gate": self.ground_gate, "gate_threshold": self.gate_threshold, "gate_scalar": self.gate_scalar,
                "gate_min_probability": self.gate_min_probability,
                "gate_promote_probability": self.gate_promote_probability, "gate_promote_height": self.gate_promote_height,
                "segment_weight": self.segment_weight, "understorey": self.understorey,
                "roof_test": self.roof_test, "roof_tolerance": self.roof_tolerance,
                "raised_patches": self.raised_patches, "crests": self.crests, "water": self.water, "bridges": self.bridges,
                "steps": list(self.steps)}

    def save(self, path, overwrite: bool = False) -> Path:
        """Write the MLP weights and config (loadable with ``torch.load(weights_only=True)``)."""
        self._check_fitted()
        if self.net_ is None:
            raise InvalidInputError("only the MLP model can be saved", "the random forest is a baseline for comparison")
        import torch

        from workstation.io import atomic_path

        payload = {
            "format": FORMAT,
            "config": json.dumps(self.config()),
            "features": json.dumps(list(FEATURE_NAMES)),
            "classes": json.dumps(list(MODEL_CLASSES)),
            "meta": json.dumps(self.meta_),
            "state_dict": {k: v.detach().cpu() for k, v in self.net_.state_dict().items()},
        }
        p = Path(path)
        buf = io.BytesIO()
        torch.save(payload, buf)
        with atomic_path(p, overwrite=overwrite) as tmp:
            Path(tmp).write_bytes(buf.getvalue())
        return p

    @classmethod
    def load(cls, path=None, device: str = "auto") -> "PointClassifier":
        """Load a saved model (the shipped one by default) with ``weights_only=True``; the
        step switches as saved (those a model predates on), but ``raised_patches`` on."""
        import torch

        p = Path(path) if path is not None else SHIPPED_MODEL
        if not p.exists():
            raise InvalidInputError("model file not found", "train one with `ws train` or use the shipped model", path=p)
        try:
            with warnings.catch_warnings():  # torch's pickle-protocol warning: the error below says it all
                warnings.simplefilter("ignore")
                payload = torch.load(p, map_location="cpu", weights_only=True)
        except Exception:  # torch's message advises weights_only=False, i.e. running the file's code: not ours
            raise InvalidInputError("not a workstation model file (it holds more than tensors and plain values, "
                                    "or is damaged); it is not executed", "give a model written by `ws train`",
                                    path=p) from None
        if not isinstance(payload, dict) or payload.get("format") != FORMAT:
            raise InvalidInputError("not a workstation point classifier", path=p)
        feats = json.loads(payload["features"])
        if tuple(feats) != FEATURE_NAMES:
            raise InvalidInputError("the model was trained on other features", "retrain it with this version", path=p)
        cfg = json.loads(payload["config"])
        fp = cfg.pop("feature_params")
        fp["min_radii"] = tuple(fp["min_radii"])
        fp.setdefault("ground_trend_slope", 0.0)  # models saved before the slope-adaptive surface
        cfg["device"] = device
        cfg.pop("raised_patches", None)  # not read: on unless the caller turns it off (see the class doc)
        self = cls(**cfg, feature_params=FeatureParams(**fp))
        from .model import build_mlp

        net = build_mlp(len(FEATURE_NAMES), len(json.loads(payload["classes"])), self.hidden, self.dropout)
        net.load_state_dict(payload["state_dict"])
        net.eval()
        self.net_ = net
        self.meta_ = json.loads(payload["meta"])
        return self
