"""Structure from motion with pycolmap (COLMAP; Schönberger & Frahm, CVPR 2016).

Feature extraction (SIFT; one self-calibrated camera per group of images of one size and one
EXIF camera, so photos from several cameras each get their own intrinsics), matching (exhaustive for small sets; for large sets sequential
pairs in name order plus image retrieval — each image with its most similar images by a VLAD
descriptor of its own SIFT features, :mod:`~workstation.photogrammetry.retrieval` — so loops
close and photos named out of order still pair; spatial when the images carry GPS priors), incremental mapping (or global mapping,
GLOMAP — Pan et al., ECCV 2024 — where pycolmap has it), then, when the intrinsics are
self-calibrated, one final bundle adjustment that also frees the principal point: COLMAP's
mapper keeps it at the image centre, which tilts every camera when the real one is off-centre.
Extraction runs over runs of images and matching over blocks of the matcher's image pairs, so
that a progress bar with the time left follows both; the mapper advances its bar with each
registered image, and each stage's time is printed when it ends (not with ``-q``).
:func:`orient_photos` adds the upright/scale step and the sparse cloud, as ``ws sfm`` and the
project pipeline run them, and :func:`sfm_record` makes their stage record.

``WORKDIR`` follows COLMAP's layout: ``database.db``, ``sparse/0`` (binary model of the largest
reconstruction), ``sparse/1``... (other, disconnected models), later ``dense/``.
"""

from __future__ import annotations

import math
import shutil
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

import numpy as np

from workstation.core.errors import InvalidInputError, OutputExistsError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Reconstruction

from .calibration import list_images

log = get_logger(__name__)

MATCHERS = ("auto", "exhaustive", "sequential", "retrieval", "spatial")
MAPPERS = ("incremental", "global")
CAMERA_SHARING = ("auto", "single", "per-image")


@dataclass(frozen=True)
class SfMParams:
    """Options of :func:`run_sfm`.

    Attributes
    ----------
    matcher : str
        "auto" (exhaustive up to ``exhaustive_max_images`` images; beyond, spatial when the
        images carry GPS priors, retrieval otherwise), "exhaustive", "sequential", "retrieval"
        (the sequential pairs and each image with its ``retrieval_neighbors`` most similar
        images), "spatial".
    exhaustive_max_images : int
        Largest image count matched exhaustively in "auto" mode (n·(n-1)/2 pairs).
    sequential_overlap : int
        Sequential matching (images in name order, COLMAP's quadratic overlap) pairs each image
        with the images 1, 2, 4, ... 2^(sequential_overlap - 1) places after it.
    retrieval_neighbors : int
        Retrieval matching pairs each image with this many most similar images (VLAD cosine).
    retrieval_words : int
        Words of the retrieval codebook, learned by k-means on the set's own SIFT descriptors.
    mapper : str
        "incremental" (COLMAP) or "global" (GLOMAP in pycolmap ≥ 3.12).
    max_image_size : int
        Longest image side used for feature extraction, pixels (-1: full size). Smaller is
        faster but loses accuracy.
    max_features : int
        SIFT features per image.
    camera_model : str
        COLMAP model for self-calibration ("SIMPLE_RADIAL", "RADIAL", "OPENCV", ...).
    cameras : str
        Which images share intrinsics: "auto" (one camera per group of images of one pixel size
        and one EXIF make, model and focal length — one camera for a set from one body and lens,
        one per photo for internet photos; images without EXIF group by size alone), "single"
        (one camera for all; refused when the sizes differ) or "per-image".
    refine_intrinsics : bool
        With a given camera: refine it in the bundle adjustments instead of keeping it fixed.
    refine_principal_point : bool
        Free the principal point in the final bundle adjustment when the intrinsics are refined.
    final_ba : bool
        Run one final bundle adjustment of the largest model with a robust loss (below), the
        intrinsics free when self-calibrated (principal point included), fixed otherwise.
    final_ba_loss : str
        Ceres loss of the final adjustment: "CAUCHY", "SOFT_L1", "HUBER" or "TRIVIAL".
    final_ba_loss_scale : float
        Scale of the robust loss, pixels (residuals beyond it are down-weighted).
    max_principal_point_shift : float
        Largest accepted move of the principal point from the image centre in the final
        adjustment, as a fraction of the longer image side; beyond it the geometry is too weak
        (few or narrow views) and the adjustment is repeated with the principal point fixed.
    seed : int
        Random seed of the pairs' RANSAC, the retrieval codebook and the mapper; -1 leaves it
        random. With one thread on the CPU a run repeats exactly. With more, two runs can
        differ a little: COLMAP numbers the images in the order their features are done, the
        mapper follows those numbers, and COLMAP's threaded nearest-neighbour matching changes
        a pair now and then. 24 runs of a 30-photo, 12 m strip on two threads gave 18 different
        models, their largest camera error 4.4-6.0 cm (``scripts/bench_sfm.py --part
        repeat``).
    num_threads : int
        Threads of every COLMAP step (-1: all cores).
    """

    matcher: str = "auto"
    exhaustive_max_images: int = 60
    sequential_overlap: int = 10
    retrieval_neighbors: int = 10
    retrieval_words: int = 64
    mapper: str = "incremental"
    max_image_size: int = -1
    max_features: int = 8192
    camera_model: str = "SIMPLE_RADIAL"
    cameras: str = "auto"
    refine_intrinsics: bool = False
    refine_principal_point: bool = True
    final_ba: bool = True
    final_ba_loss: str = "CAUCHY"
    final_ba_loss_scale: float = 1.0
    max_principal_point_shift: float = 0.1
    seed: int = 0
    num_threads: int = -1

    def __post_init__(self):
        if self.matcher not in MATCHERS:
            raise InvalidInputError(f"matcher must be one of {MATCHERS}", field="matcher")
        if self.mapper not in MAPPERS:
            raise InvalidInputError(f"mapper must be one of {MAPPERS}", field="mapper")
        if self.cameras not in CAMERA_SHARING:
            raise InvalidInputError(f"cameras must be one of {CAMERA_SHARING}", field="cameras")
        if self.retrieval_neighbors < 1 or self.retrieval_words < 2:
            raise InvalidInputError("retrieval needs at least 1 neighbour per image and 2 codebook words",
                                    field="retrieval_neighbors" if self.retrieval_neighbors < 1 else "retrieval_words")


@dataclass(frozen=True)
class SfMResult:
    """Outcome of :func:`run_sfm`.

    Attributes
    ----------
    reconstruction : Reconstruction
        The largest model (model frame, arbitrary scale unless georeferenced).
    cloud : Cloud
        Its sparse points with ``rgb``.
    summary : dict
        ``images``, ``registered``, ``points``, ``observations``, ``mean_reprojection_error_px``,
        ``mean_track_length``, ``matcher``, ``mapper``, ``timings_s``, ``cameras``,
        ``camera_sharing`` ("shared", "per-image" or "per camera group"), ``camera_count``
        (cameras in the database; the model holds those of its registered images) and
        ``matched_pairs`` (image pairs the matcher compared).
    unregistered : list of str
        Images not in the largest model.
    other_models : list of dict
        ``{"index", "images": [...]}`` for each disconnected model (``sparse/<index>``).
    workdir : Path
    """

    reconstruction: Reconstruction
    cloud: Any
    summary: Mapping[str, Any]
    unregistered: list = field(default_factory=list)
    other_models: list = field(default_factory=list)
    workdir: Path | None = None

    def to_dict(self) -> dict:
        d = dict(self.summary)
        d["unregistered"] = list(self.unregistered)
        d["other_models"] = list(self.other_models)
        d["workdir"] = str(self.workdir) if self.workdir else None
        return d


def _has_gps(db_path: Path, pycolmap) -> bool:
    try:
        db = pycolmap.Database.open(str(db_path)) if hasattr(pycolmap.Database, "open") else pycolmap.Database(str(db_path))
        n = db.num_pose_priors()
        db.close()
        return n > 0
    except Exception as e:  # noqa: BLE001 - only a heuristic for the matcher choice
        log.debug("could not read pose priors: %s", e)
        return False


def choose_matcher(n_images: int, has_gps: bool, params: SfMParams) -> str:
    """The matcher "auto" picks for ``n_images``.

    >>> choose_matcher(11, False, SfMParams()), choose_matcher(500, False, SfMParams()), choose_matcher(500, True, SfMParams())
    ('exhaustive', 'retrieval', 'spatial')
    """
    if params.matcher != "auto":
        return params.matcher
    if n_images <= params.exhaustive_max_images:
        return "exhaustive"
    return "spatial" if has_gps else "retrieval"


def check_images_readable(files) -> None:
    """Refuse files named like images that no image library can open (their headers only are
    read), so a folder of non-images is not reported later as "too few matches"."""
    from PIL import Image as PILImage

    bad = []
    for f in files:
        try:
            with PILImage.open(f) as im:
                im.verify()
        except Exception:  # noqa: BLE001 - any decoder failure means: not a readable image
            bad.append(f)
    if bad:
        more = f" and {len(bad) - 1} more" if len(bad) > 1 else ""
        raise InvalidInputError(f"not a readable image{more}", "remove or replace it; SfM reads png, jpg, tif ...",
                                path=bad[0])


@contextmanager
def _timed(timings: dict, step: str):
    """Record the seconds the block takes as ``timings[step]`` and, unless progress is off
    (``-q``, ``WS_PROGRESS=0``), say on stderr how long the stage took."""
    from workstation.core.progress import format_duration, progress_mode, stderr_console

    t0 = time.perf_counter()
    yield
    timings[step] = time.perf_counter() - t0
    if progress_mode() != "off":
        stderr_console().print(f"sfm {step.replace('_', ' ')}: {format_duration(timings[step])}", highlight=False)


def _input_images(image_dir: Path) -> list[Path]:
    """The image files of ``image_dir``, all readable, at least 2."""
    files = list_images(image_dir)
    check_images_readable(files)
    if len(files) < 2:
        raise InvalidInputError(f"structure from motion needs at least 2 images, found {len(files)}", path=image_dir)
    return files


def _prepare_workdir(workdir: Path, overwrite: bool) -> None:
    """Refuse a non-empty ``workdir`` unless ``overwrite``; then clear its database and models."""
    if workdir.exists() and any(workdir.iterdir()):
        if not overwrite:
            raise OutputExistsError(workdir)
        for sub in ("database.db", "sparse"):
            q = workdir / sub
            if q.is_dir():
                shutil.rmtree(q)
            elif q.exists():
                q.unlink()
    workdir.mkdir(parents=True, exist_ok=True)


def _device(pycolmap):
    return pycolmap.Device.cpu if not pycolmap.has_cuda else pycolmap.Device.auto


def camera_key(path) -> tuple:
    """What tells the camera that took an image: its pixel size as stored (before any EXIF
    rotation) and its EXIF make, model, focal length and 35 mm equivalent focal length (None
    where absent)."""
    from PIL import Image as PILImage

    with PILImage.open(path) as im:
        exif = im.getexif()
        shot = exif.get_ifd(0x8769)  # Exif sub-IFD: FocalLength (37386), FocalLengthIn35mmFilm (41989)
        focal = shot.get(37386)
        return (im.size, exif.get(271), exif.get(272), None if focal is None else float(focal), shot.get(41989))


def camera_groups(files) -> list[list[Path]]:
    """``files`` grouped by :func:`camera_key`, in order of first appearance: the images one
    self-calibrated camera is shared by in ``cameras="auto"``."""
    groups: dict[tuple, list[Path]] = {}
    for f in files:
        groups.setdefault(camera_key(f), []).append(Path(f))
    return list(groups.values())


def _single_camera_sizes(files, camera: Camera | None) -> None:
    """Refuse a shared camera for images of different sizes (COLMAP would drop every image
    whose size differs from the first one's), or of another size than the given camera."""
    sizes = [camera_key(f)[0] for f in files]
    ref, ref_name = ((camera.width, camera.height), "the given camera") if camera is not None else (sizes[0], files[0].name)
    for f, size in zip(files, sizes):
        if size != ref:
            raise InvalidInputError(
                f"this image is {size[0]}x{size[1]} but {ref_name} is {ref[0]}x{ref[1]}",
                "use the camera's own image size, or recalibrate" if camera is not None
                else "photos of several cameras or sizes need --cameras auto or per-image",
                path=f,
            )


def _extraction_batches(files, camera: Camera | None, params: SfMParams) -> tuple[list, str]:
    """``[(camera_mode, files)]``, one feature-extraction call each (a call in SINGLE mode
    makes one camera of its own), and how the intrinsics are shared: "shared", "per-image" or
    "per camera group"."""
    if camera is not None or params.cameras == "single":
        _single_camera_sizes(files, camera)
        return [("SINGLE", list(files))], "shared"
    if params.cameras == "per-image":
        return [("PER_IMAGE", list(files))], "per-image"
    groups = camera_groups(files)
    if len(groups) == 1:
        return [("SINGLE", groups[0])], "shared"
    shared = [("SINGLE", g) for g in groups if len(g) > 1]
    alone = [g[0] for g in groups if len(g) == 1]
    log.info("%d camera groups among %d images (by image size and EXIF camera)", len(groups), len(files))
    return shared + ([("PER_IMAGE", alone)] if alone else []), "per-image" if not shared else "per camera group"


PROGRESS_STEPS = 20  # feature extraction and matching run in about this many calls, one bar step each


def _chunks(items: list, least: int) -> list[list]:
    """``items`` cut into about :data:`PROGRESS_STEPS` consecutive runs of at least ``least``."""
    size = max(int(least), math.ceil(len(items) / PROGRESS_STEPS))
    return [items[i:i + size] for i in range(0, len(items), size)]


def _reader_options(pycolmap, camera: Camera | None, params: SfMParams, existing_camera_id: int = -1):
    """COLMAP's image reader options: the given camera's model and parameters, or the
    self-calibration model; ``existing_camera_id`` makes every image use that database camera."""
    from workstation.interop.pycolmap import camera_to_colmap_params

    reader = pycolmap.ImageReaderOptions()
    if camera is not None:
        model, cparams = camera_to_colmap_params(camera)
        reader.camera_model = model
        reader.camera_params = ",".join(repr(float(v)) for v in cparams)
    else:
        reader.camera_model = params.camera_model
    reader.existing_camera_id = int(existing_camera_id)
    return reader


def _camera_id_of(pycolmap, db: Path, name: str) -> int:
    """The database camera of the image ``name``."""
    with pycolmap.Database.open(str(db)) as d:
        return int(d.read_image_with_name(name).camera_id)


def _extract_features(pycolmap, db: Path, image_dir: Path, files, camera: Camera | None, params: SfMParams) -> tuple[str, int]:
    """SIFT features of every image into the database; a given camera is applied to all,
    otherwise the images share cameras as ``params.cameras`` says. Returns how the intrinsics
    are shared (:func:`_extraction_batches`) and the number of cameras.

    Each camera group is extracted in runs of images (:func:`_chunks`) so that a progress bar
    with the time left follows the work: in a shared-camera group the first run makes the
    camera and the later runs reuse it (``existing_camera_id``), so the database holds the
    same images, ids, cameras and features as one call over the group would write."""
    from workstation.core.progress import progress_bar

    ext = pycolmap.FeatureExtractionOptions()
    ext.max_image_size = int(params.max_image_size)
    ext.num_threads = int(params.num_threads)
    ext.sift.max_num_features = int(params.max_features)
    batches, sharing = _extraction_batches(files, camera, params)
    n_cameras = sum(1 if mode == "SINGLE" else len(group) for mode, group in batches)
    log.info("extracting features from %d images (%d camera%s)", len(files), n_cameras, "s" * (n_cameras > 1))
    least = 2 * max(1, _threads(params))  # keep every extraction thread busy in a call
    with progress_bar("features", len(files), unit="images") as advance:
        for mode, group in batches:
            existing = -1
            for chunk in _chunks(group, least):
                pycolmap.extract_features(
                    db, image_dir, image_names=[f.name for f in chunk], camera_mode=getattr(pycolmap.CameraMode, mode),
                    reader_options=_reader_options(pycolmap, camera, params, existing),
                    extraction_options=ext, device=_device(pycolmap),
                )
                if mode == "SINGLE" and existing < 0:
                    existing = _camera_id_of(pycolmap, db, chunk[0].name)
                advance(len(chunk))
    return sharing, n_cameras


def _threads(params: SfMParams) -> int:
    """Threads COLMAP uses for ``params.num_threads`` (-1: every core)."""
    import os

    return int(params.num_threads) if params.num_threads > 0 else (os.cpu_count() or 1)


def _pairs(pycolmap, db: Path, matcher: str, params: SfMParams) -> tuple[list, dict]:
    """The image pairs COLMAP's ``matcher`` would match (its own pair generator) and the image
    names by id; "retrieval" adds to the sequential pairs each image's
    ``params.retrieval_neighbors`` most similar images (:func:`retrieval.retrieval_pairs`).
    Each pair once, in name order (:func:`_in_name_order`)."""
    with pycolmap.Database.open(str(db)) as d:
        names = {int(im.image_id): im.name for im in d.read_all_images()}
        if matcher == "exhaustive":
            gen = pycolmap.ExhaustivePairGenerator(pycolmap.ExhaustivePairingOptions(), d)
        elif matcher in ("sequential", "retrieval"):
            gen = pycolmap.SequentialPairGenerator(_sequential_options(pycolmap, params), d)
        else:
            gen = pycolmap.SpatialPairGenerator(pycolmap.SpatialPairingOptions(), d)
        pairs = [(int(a), int(b)) for a, b in gen.all_pairs()]
    if matcher == "retrieval" and any(c.isspace() for n in names.values() for c in n):
        log.warning("image names with white space: sequential matching only, without retrieval pairs")
        return pairs, names  # retrieval pairs reach COLMAP only through a pairs file
    if matcher == "retrieval" and len(names) > 1:
        from .retrieval import retrieval_pairs

        pairs += retrieval_pairs(db, pycolmap, params.retrieval_neighbors, params.retrieval_words, params.seed)
    return _in_name_order(pairs, names), names


def _in_name_order(pairs: list, names: dict) -> list:
    """The distinct pairs, each image of a pair and the pairs in name order. Threaded feature
    extraction numbers the images in the order they finish, so ids differ between runs;
    names do not, and COLMAP matches a pair in the order it is given."""
    ordered = {tuple(sorted((a, b), key=names.__getitem__)) for a, b in pairs if a != b}
    return sorted(ordered, key=lambda p: (names[p[0]], names[p[1]]))


def _sequential_options(pycolmap, params: SfMParams):
    """COLMAP's sequential pairing in name order with its default quadratic overlap: each image
    with the images 1, 2, 4, ... 2^(overlap-1) places after it (``params.sequential_overlap``)."""
    pair = pycolmap.SequentialPairingOptions()
    pair.overlap = int(params.sequential_overlap)
    return pair


def _match(pycolmap, db: Path, n_images: int, params: SfMParams) -> tuple[str, int]:
    """Match the features of the database; returns the matcher used (:func:`choose_matcher`)
    and the number of image pairs it matched.

    The pairs the matcher's own generator makes are matched in blocks (a pairs file each,
    ``match_image_pairs``), one progress step per block; each pair's matching and geometric
    verification do not depend on the other pairs, so the result is that of one call. Image
    names with white space cannot be written to a pairs file: those sets are matched in one
    call, without a bar (and sequentially instead of with retrieval pairs)."""
    import tempfile

    from workstation.core.progress import progress_bar

    matcher = choose_matcher(n_images, _has_gps(db, pycolmap) if params.matcher == "auto" else False, params)
    mopt = pycolmap.FeatureMatchingOptions()
    mopt.num_threads = int(params.num_threads)
    vopt = _verification_options(pycolmap, params)
    dev = _device(pycolmap)
    pairs, names = _pairs(pycolmap, db, matcher, params)
    log.info("matching (%s, %d pairs)", matcher, len(pairs))
    if any(c.isspace() for n in names.values() for c in n):
        matcher = "sequential" if matcher == "retrieval" else matcher  # _pairs left the retrieval pairs out
        _match_at_once(pycolmap, db, matcher, mopt, vopt, params, dev)
        return matcher, len(pairs)
    with tempfile.TemporaryDirectory(prefix="ws_sfm_pairs_") as tmp, \
            progress_bar(f"matching ({matcher})", len(pairs), unit="pairs") as advance:
        opt, listing = pycolmap.ImportedPairingOptions(), Path(tmp) / "pairs.txt"
        opt.match_list_path = listing
        for block in _chunks(pairs, 4 * _threads(params)):
            listing.write_text("".join(f"{names[a]} {names[b]}\n" for a, b in block))
            pycolmap.match_image_pairs(db, matching_options=mopt, pairing_options=opt, verification_options=vopt,
                                       device=dev)
            advance(len(block))
    return matcher, len(pairs)


def _verification_options(pycolmap, params: SfMParams):
    """COLMAP's two-view geometric verification with its RANSAC seeded by ``params.seed``, so
    that each pair's estimate starts from the seed whichever thread takes the pair. Unseeded,
    a pair's draws depend on the pairs its thread took before it, which changes from run to
    run."""
    vopt = pycolmap.TwoViewGeometryOptions()
    if params.seed >= 0:
        vopt.ransac.random_seed = int(params.seed)
    return vopt


def _match_at_once(pycolmap, db: Path, matcher: str, mopt, vopt, params: SfMParams, dev) -> None:
    """One call of COLMAP's ``matcher`` over the database."""
    if matcher == "exhaustive":
        pycolmap.match_exhaustive(db, matching_options=mopt, verification_options=vopt, device=dev)
    elif matcher == "sequential":
        pycolmap.match_sequential(db, matching_options=mopt, pairing_options=_sequential_options(pycolmap, params),
                                  verification_options=vopt, device=dev)
    else:
        pycolmap.match_spatial(db, matching_options=mopt, verification_options=vopt, device=dev)


def _map(pycolmap, db: Path, image_dir: Path, sparse: Path, n_images: int, fixed: bool, params: SfMParams) -> dict:
    """Incremental or global mapping into ``sparse``; fixed intrinsics stay fixed. Returns
    pycolmap's models by index."""
    from workstation.core.progress import progress_bar

    if params.mapper == "global":
        gopt = pycolmap.GlobalPipelineOptions()
        gopt.random_seed = int(params.seed)
        gopt.num_threads = int(params.num_threads)
        log.info("global mapping")
        return pycolmap.global_mapping(db, image_dir, sparse, gopt)
    opt = pycolmap.IncrementalPipelineOptions()
    opt.random_seed = int(params.seed)
    opt.num_threads = int(params.num_threads)
    if fixed:
        opt.ba_refine_focal_length = False
        opt.ba_refine_extra_params = False
        opt.ba_refine_principal_point = False
        opt.mapper.abs_pose_refine_focal_length = False
        opt.mapper.abs_pose_refine_extra_params = False
    with progress_bar("register images", n_images, unit="images") as advance:
        return pycolmap.incremental_mapping(db, image_dir, sparse, opt, next_image_callback=lambda: advance(1))


def _final_bundle_adjustment(pycolmap, best, fixed: bool, params: SfMParams, notes: list):
    """One robust bundle adjustment of the largest model, the intrinsics free when
    self-calibrated and the principal point with them; when the principal point then moves
    beyond ``max_principal_point_shift`` the adjustment is repeated with it fixed (on a copy
    of the model taken before). A camera seen in one image only (per-image intrinsics) keeps
    its principal point: a shift of it is, to first order, a rotation of that one view.
    Returns the adjusted model."""
    bopt = pycolmap.BundleAdjustmentOptions()
    bopt.ceres.solver_options.num_threads = int(params.num_threads)
    bopt.refine_focal_length = not fixed
    bopt.refine_extra_params = not fixed
    bopt.refine_principal_point = (not fixed) and params.refine_principal_point
    if bopt.refine_principal_point and _has_single_view_camera(best):
        bopt.refine_principal_point = False
        notes.append("principal point kept at the image centre (cameras seen in one image only)")
    bopt.print_summary = False
    try:
        bopt.ceres.loss_function_type = getattr(pycolmap.LossFunctionType, params.final_ba_loss.upper())
    except AttributeError:
        raise InvalidInputError(f"unknown loss {params.final_ba_loss!r}", field="final_ba_loss") from None
    bopt.ceres.loss_function_scale = float(params.final_ba_loss_scale)
    log.info(
        "final bundle adjustment (%s loss, %.2g px%s)",
        params.final_ba_loss, params.final_ba_loss_scale, ", principal point free" if bopt.refine_principal_point else "",
    )
    backup = pycolmap.Reconstruction(best) if bopt.refine_principal_point else None
    pycolmap.bundle_adjustment(best, bopt)
    if backup is not None:
        drift = _principal_point_drift(best)
        if drift > params.max_principal_point_shift:
            # too few or too narrow views constrain the principal point: keep it central
            log.warning(
                "principal point moved %.1f %% of the image size in the final adjustment (limit %.1f %%): "
                "weak geometry; kept at the centre instead",
                100 * drift, 100 * params.max_principal_point_shift,
            )
            best = backup
            bopt.refine_principal_point = False
            pycolmap.bundle_adjustment(best, bopt)
            notes.append("principal point not estimated (weakly constrained)")
    return best


def _has_single_view_camera(rec) -> bool:
    """Whether a camera of the pycolmap model ``rec`` is used by one registered image only."""
    ids = np.array([im.camera_id for im in rec.images.values() if im.has_pose])
    return bool(ids.size) and bool((np.unique(ids, return_counts=True)[1] == 1).any())


def _write_models(ordered: list, sparse: Path) -> list[dict]:
    """Write the models in COLMAP layout, ``sparse/0`` the largest; returns
    ``{"index", "images"}`` of the others (disconnected models)."""
    from workstation.interop.pycolmap import write_model

    for q in list(sparse.iterdir()):
        if q.is_dir():
            shutil.rmtree(q)
    other = []
    for i, r in enumerate(ordered):
        write_model(r, sparse / str(i))
        if i:
            other.append({"index": i, "images": sorted(im.name for im in r.images.values() if im.has_pose)})
    return other


def _registered(best, names: list, other: list) -> tuple[set, list]:
    """Names of the images in the largest model and of those not in it (warned about, with the
    disconnected models)."""
    registered = {im.name for im in best.images.values() if im.has_pose}
    unregistered = [n for n in names if n not in registered]
    for n in unregistered:
        log.warning("image not registered in the main model: %s", n)
    for o in other:
        log.warning("disconnected model sparse/%d: %s", o["index"], ", ".join(o["images"]))
    return registered, unregistered


def _nadir_block_note(rec: Reconstruction) -> str | None:
    """A warning when every camera looks nearly one way (self-calibration cannot fix the scale)."""
    spread = viewing_spread_deg(rec)
    if not spread < NADIR_BLOCK_SPREAD_DEG:
        return None
    return (
        f"every camera looks within {spread:.1f} deg of one direction (a nadir-only block): "
        "focal length and flying height are nearly inseparable when self-calibrating, so the "
        "scale along the view may be wrong; give --camera CAMERA.json from a calibration"
    )


def _summary(names, registered, rec: Reconstruction, best, matcher: str, camera, fixed: bool, params: SfMParams,
             timings: dict, notes: list) -> dict:
    """The ``summary`` of :class:`SfMResult`."""
    tl = rec.meta["track_lengths"]
    return {
        "images": len(names),
        "registered": len(registered),
        "points": int(rec.points.shape[0]),
        "observations": int(best.compute_num_observations()),
        "mean_reprojection_error_px": float(best.compute_mean_reprojection_error()),
        "mean_track_length": float(np.mean(tl)) if tl.size else 0.0,
        "matcher": matcher,
        "mapper": params.mapper,
        "intrinsics": "fixed" if fixed else ("refined from given" if camera is not None else "self-calibrated"),
        "cameras": {str(k): _camera_summary(c) for k, c in rec.cameras.items()},
        "timings_s": timings,
        "notes": notes,
    }


def run_sfm(
    image_dir,
    workdir,
    camera: Camera | None = None,
    params: SfMParams = SfMParams(),
    overwrite: bool = False,
) -> SfMResult:
    """Orient the images of ``image_dir`` and build a sparse cloud in ``workdir``.

    Parameters
    ----------
    image_dir : path
        Folder of images (png, jpg, tif...; other files are ignored).
    workdir : path
        Output folder (COLMAP layout). Refused if it exists and is not empty, unless
        ``overwrite``.
    camera : Camera, optional
        Known intrinsics (e.g. from ``ws calibrate``), applied to every image and held fixed
        unless ``params.refine_intrinsics``. Without it the camera is self-calibrated from the
        EXIF focal length (or 1.2 × the longest side when there is none).
    params : SfMParams
    overwrite : bool

    Returns
    -------
    SfMResult

    Raises
    ------
    InvalidInputError
        Fewer than 2 images, images of another size than the given camera, images of
        several sizes with ``params.cameras == "single"``.
    StageError
        No model could be built.
    """
    from workstation.interop.pycolmap import cloud_from_reconstruction, import_pycolmap, reconstruction_from_pycolmap

    pycolmap = import_pycolmap()
    image_dir = Path(image_dir)
    files = _input_images(image_dir)
    names = [f.name for f in files]
    workdir = Path(workdir)
    _prepare_workdir(workdir, overwrite)
    db, sparse = workdir / "database.db", workdir / "sparse"
    if params.seed >= 0:
        pycolmap.set_random_seed(int(params.seed))
    fixed = camera is not None and not params.refine_intrinsics
    timings, notes = {}, []
    with _timed(timings, "features"):
        sharing, n_cameras = _extract_features(pycolmap, db, image_dir, files, camera, params)
    with _timed(timings, "matching"):
        matcher, n_pairs = _match(pycolmap, db, len(files), params)
    with _timed(timings, "mapping"):
        sparse.mkdir(exist_ok=True)
        recs = _map(pycolmap, db, image_dir, sparse, len(files), fixed, params)
    if not recs:
        raise StageError(
            "sfm",
            "no model could be built (too few matches between the images)",
            "check that the images overlap (60 %+), are sharp and show texture; try --matcher exhaustive",
        )
    ordered = sorted(recs.values(), key=lambda r: (r.num_reg_images(), r.num_points3D()), reverse=True)
    with _timed(timings, "final_ba"):
        best = _final_bundle_adjustment(pycolmap, ordered[0], fixed, params, notes) if params.final_ba else ordered[0]
    other = _write_models(ordered, sparse)
    registered, unregistered = _registered(best, names, other)
    rec = reconstruction_from_pycolmap(best, image_dir)
    note = None if fixed else _nadir_block_note(rec)
    if note:
        log.warning(note)
        notes.append(note)
    cloud = cloud_from_reconstruction(rec)
    summary = _summary(names, registered, rec, best, matcher, camera, fixed, params, timings, notes)
    summary.update(camera_sharing=sharing, camera_count=n_cameras, matched_pairs=n_pairs)
    if rec.points.shape[0] == 0:
        raise StageError("sfm", "the model has no 3-D points", "the images may not overlap enough")
    return SfMResult(rec, cloud, summary, unregistered, other, workdir)


def orient_photos(image_dir, workdir, camera: Camera | None = None, params: SfMParams = SfMParams(), *,
                  upright: bool = True, scale_bars=(), sigma_px: float = 1.0,
                  overwrite: bool = False) -> tuple[SfMResult, dict]:
    """The steps of ``ws sfm`` before georeferencing: :func:`run_sfm`, then the model in
    ``workdir/sparse/0`` turned upright and scaled
    (:func:`workstation.photogrammetry.scale.level_and_scale_model`) and its sparse cloud
    written as ``workdir/sparse.ply``.

    Parameters
    ----------
    image_dir, workdir, camera, params, overwrite
        As for :func:`run_sfm`.
    upright : bool
        Turn the model upright (z up, main façade facing -y).
    scale_bars : sequence of ScaleBar
        Known lengths (:func:`~workstation.photogrammetry.scale.parse_scale_bar` /
        ``parse_scale_distance``); none leaves the model unscaled.
    sigma_px : float
        Image measurement precision of the scale bars' ends, pixels.

    Returns
    -------
    (SfMResult, dict)
        The result (in SfM's frame) and the stage document: :meth:`SfMResult.to_dict`, the
        frame entries ("upright", "scale", "similarity"...) and ``sparse_cloud``.
    """
    from workstation.io import write_cloud
    from workstation.photogrammetry.scale import level_and_scale_model

    result = run_sfm(image_dir, workdir, camera, params, overwrite=overwrite)
    wd = Path(workdir)
    cloud, frame = level_and_scale_model(result, wd, upright, list(scale_bars), sigma_px)
    write_cloud(cloud, wd / "sparse.ply", overwrite=True)
    return result, {**result.to_dict(), **frame, "sparse_cloud": str(wd / "sparse.ply")}


def sfm_record(doc: dict, image_dir, workdir, params: SfMParams, *, upright: bool, outputs, seconds: float,
               camera_file=None, gcp_file=None, gcp_settings: Mapping | None = None) -> dict:
    """The sfm stage record (``WORKDIR/summary.json``) of a stage document from
    :func:`orient_photos`: the absolute image folder, camera and GCP files in ``inputs``, and
    in ``params`` the :class:`SfMParams`, the upright flag, how the intrinsics are shared
    and the GCP settings when there are GCPs."""
    import dataclasses

    from workstation.io.reconstruction import stage_record

    settings = {**dataclasses.asdict(params), "upright": bool(upright), "intrinsics": doc["camera_sharing"],
                **dict(gcp_settings or {})}
    return stage_record("sfm", doc, inputs={"image_dir": image_dir, "camera": camera_file, "gcp": gcp_file,
                                            "workdir": workdir},
                        params=settings, outputs=outputs, seconds=seconds)


NADIR_BLOCK_SPREAD_DEG = 10.0  # optical axes all within this of their mean: parallel-axis block


def viewing_spread_deg(rec) -> float:
    """Largest angle (degrees) between a registered image's optical axis and the mean axis.

    A block whose axes are all nearly parallel (a nadir-only aerial grid) cannot separate the
    focal length from the object distance when the camera is self-calibrated (the textbook
    reason for oblique images or a calibrated camera in aerial blocks).

    Examples
    --------
    >>> import numpy as np
    >>> from workstation.core.products import Image, Pose, Reconstruction
    >>> tilt = np.deg2rad(4.0)
    >>> R2 = np.array([[1, 0, 0], [0, np.cos(tilt), -np.sin(tilt)], [0, np.sin(tilt), np.cos(tilt)]])
    >>> imgs = {1: Image("a", 1, Pose(np.eye(3), np.zeros(3))), 2: Image("b", 1, Pose(R2, np.zeros(3)))}
    >>> round(viewing_spread_deg(Reconstruction(cameras={}, images=imgs)), 1)
    2.0
    """
    axes = np.array([np.asarray(im.pose.R)[2] for im in rec.images.values() if im.pose is not None])
    if len(axes) < 2:
        return 0.0
    mean = axes.mean(axis=0)
    mean /= np.linalg.norm(mean)
    return float(np.degrees(np.arccos(np.clip(axes @ mean, -1.0, 1.0)).max()))


def _principal_point_drift(rec) -> float:
    """Largest distance of a camera's principal point from its image centre, as a fraction of
    the longer image side (COLMAP pixel convention: centre at width/2, height/2)."""
    worst = 0.0
    for c in rec.cameras.values():
        d = np.hypot(c.principal_point_x - c.width / 2, c.principal_point_y - c.height / 2) / max(c.width, c.height)
        worst = max(worst, float(d))
    return worst


def _camera_summary(c: Camera) -> dict:
    return {"model": c.model, "fx": c.fx, "fy": c.fy, "cx": c.cx, "cy": c.cy, "dist": list(c.dist)}


def read_reconstruction(path, image_dir=None) -> Reconstruction:
    """Oriented cameras from a cameras JSON or a COLMAP workdir/model folder.

    ``path`` may be the JSON file (:mod:`workstation.io.reconstruction`), a folder holding
    ``cameras.json``, a COLMAP model folder (``cameras.bin``/``.txt``), or a workdir with
    ``sparse/0`` or ``sparse``; ``image_dir`` is where a COLMAP model's images are.
    """
    from workstation.io.reconstruction import read_reconstruction_json

    p = Path(path)
    if p.is_file():
        return read_reconstruction_json(p)
    if not p.is_dir():
        raise InvalidInputError("not found", "give a COLMAP workdir or a cameras JSON", path=p)
    if (p / "cameras.json").is_file():
        return read_reconstruction_json(p / "cameras.json")
    from workstation.interop.pycolmap import find_model, read_model

    if find_model(p) is not None:
        return read_model(p, image_dir)
    raise InvalidInputError("no cameras.json and no COLMAP model (cameras.bin/.txt) found",
                            "run ws sfm first or give the model folder", path=p)
