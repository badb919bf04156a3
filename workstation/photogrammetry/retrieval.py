"""Image retrieval for SfM pairing without a vocabulary file: VLAD global descriptors.

Each image is summarised by a VLAD vector (Jégou et al., CVPR 2010) built from the SIFT
descriptors COLMAP has already written to its database (RootSIFT already, Arandjelović &
Zisserman, CVPR 2012: COLMAP's default L1_ROOT normalisation, stored as bytes; here scaled to
unit length), are assigned to the nearest word of a small codebook
learned by k-means on a sample of this set's own descriptors, and their residuals to the words
are summed per word, normalised per word (intra-normalisation) and over the whole vector after
a signed square root. The cosine of two images' vectors ranks how likely they are to overlap;
each image is paired with its most similar images. Unlike name-order (sequential) pairing,
this closes loops (the last photos of a ring with the first) and pairs photos whose names are
out of order or which were taken in several passes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError

SAMPLE_PER_IMAGE = 300  # descriptors per image drawn for learning the codebook
SAMPLE_MAX = 60_000  # at most this many descriptors in all for k-means
KMEANS_ITERATIONS = 20  # Lloyd iterations of the codebook k-means


def unit_rows(desc: np.ndarray) -> np.ndarray:
    """``(n, 128)`` float32 copy of a database's descriptors scaled to unit length (COLMAP
    stores RootSIFT, already unit length in the Hellinger sense, as bytes times 512).

    >>> np.round(np.linalg.norm(unit_rows(np.array([[3, 4], [0, 0]], np.uint8)), axis=1), 6).tolist()
    [1.0, 0.0]
    """
    x = np.array(desc, dtype=np.float32)
    return x / np.maximum(np.linalg.norm(x, axis=1, keepdims=True), 1e-12)


def _per_image(n_images: int) -> int:
    """Descriptors drawn from each image for the codebook sample."""
    return max(1, min(SAMPLE_PER_IMAGE, SAMPLE_MAX // max(1, n_images)))


def _draw(x: np.ndarray, per: int, rng) -> np.ndarray:
    """Up to ``per`` rows of ``x`` drawn without replacement."""
    return x[rng.choice(len(x), min(per, len(x)), replace=False)]


def kmeans(sample: list[np.ndarray], words: int, rng, iterations: int = KMEANS_ITERATIONS) -> np.ndarray:
    """``(words, 128)`` k-means centres of the stacked rows of ``sample``: Lloyd's iterations
    from randomly drawn rows; a word left without rows restarts at a random row."""
    x = np.concatenate(sample) if sample else np.zeros((0, 128), np.float32)
    if len(x) < words:
        raise InvalidInputError(f"too few features ({len(x)}) for a retrieval codebook of {words} words",
                                "use a smaller codebook or more features per image", field="retrieval_words")
    centres = x[rng.choice(len(x), int(words), replace=False)].copy()
    for _ in range(int(iterations)):
        nearest = _nearest_word(x, centres)
        counts = np.bincount(nearest, minlength=len(centres))
        sums = _sum_by_word(x, nearest, len(centres))
        empty = counts == 0
        centres = np.where(empty[:, None], x[rng.choice(len(x), len(centres))], sums / np.maximum(counts, 1)[:, None])
    return centres.astype(np.float32)


def _sum_by_word(x: np.ndarray, word: np.ndarray, words: int) -> np.ndarray:
    """``(words, dim)`` sums of the rows of ``x`` by their word (a sparse one-hot product)."""
    from scipy.sparse import csr_matrix

    onehot = csr_matrix((np.ones(len(word), np.float32), (word, np.arange(len(word)))), shape=(words, len(word)))
    return np.asarray(onehot @ x, dtype=np.float32)


def _nearest_word(desc: np.ndarray, codebook: np.ndarray) -> np.ndarray:
    """Index of the nearest codebook word of each descriptor (squared distance |x|² − 2x·c + |c|²,
    |x|² being the same for every word)."""
    return np.argmin((codebook ** 2).sum(axis=1)[None, :] - 2.0 * desc @ codebook.T, axis=1)


def vlad(desc: np.ndarray, codebook: np.ndarray) -> np.ndarray:
    """The VLAD vector (``words * 128``) of one image's RootSIFT descriptors: residuals to the
    nearest word summed per word, each word's sum L2-normalised, the signed square root taken
    and the whole vector L2-normalised (zero for an image without features)."""
    k, dim = codebook.shape
    v = np.zeros((k, dim), dtype=np.float32)
    if len(desc):
        nearest = _nearest_word(desc, codebook)
        v = _sum_by_word(desc - codebook[nearest], nearest, k)
    v /= np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-12)
    v = np.sign(v) * np.sqrt(np.abs(v))
    flat = v.ravel()
    return flat / max(float(np.linalg.norm(flat)), 1e-12)


def nearest_images(vectors: np.ndarray, k: int) -> np.ndarray:
    """``(n, min(k, n-1))`` indices of each image's most similar other images (cosine of the
    global vectors), most similar first.

    >>> v = np.array([[1, 0], [0.9, 0.1], [0, 1]], dtype=float)
    >>> nearest_images(v / np.linalg.norm(v, axis=1, keepdims=True), 1).ravel().tolist()
    [1, 0, 1]
    """
    n = len(vectors)
    k = min(int(k), n - 1)
    if k <= 0:
        return np.zeros((n, 0), dtype=int)
    sim = vectors @ vectors.T
    np.fill_diagonal(sim, -np.inf)
    top = np.argpartition(-sim, k - 1, axis=1)[:, :k]
    order = np.argsort(-np.take_along_axis(sim, top, axis=1), axis=1)
    return np.take_along_axis(top, order, axis=1)


def database_vectors(db: Path, pycolmap, words: int, seed: int = 0) -> tuple[list[int], np.ndarray]:
    """Image ids and VLAD vectors (:func:`vlad`) of the images of a COLMAP database, in image
    name order, on a codebook of ``words`` learned by :func:`kmeans` from up to
    :data:`SAMPLE_PER_IMAGE` descriptors drawn from each image (:data:`SAMPLE_MAX` in all).
    Each image's descriptors are read twice (for the sample, then for its vector), so only one
    image's are held at a time. Name order, not id order, makes the codebook the same in every
    run with the same seed: threaded feature extraction numbers images as they finish."""
    rng = np.random.default_rng(seed if seed >= 0 else None)
    with pycolmap.Database.open(str(db)) as d:
        ids = [int(im.image_id) for im in sorted(d.read_all_images(), key=lambda im: im.name)]
        per = _per_image(len(ids))
        descs = (unit_rows(d.read_descriptors(i).data) for i in ids)
        codebook = kmeans([_draw(x, per, rng) for x in descs if len(x)], words, rng)
        vectors = np.stack([vlad(unit_rows(d.read_descriptors(i).data), codebook) for i in ids])
    return ids, vectors


def retrieval_pairs(db: Path, pycolmap, k: int, words: int, seed: int = 0) -> list[tuple[int, int]]:
    """Image-id pairs ``(a, b)``, ``a``'s name before ``b``'s, joining each image of the
    database to its ``k`` most similar images by VLAD retrieval (:func:`database_vectors`),
    without repeats."""
    ids, vectors = database_vectors(db, pycolmap, words, seed)
    nn = nearest_images(vectors, k)
    a = np.repeat(np.arange(len(ids)), nn.shape[1])
    b = nn.ravel()
    uniq = np.unique(np.stack([np.minimum(a, b), np.maximum(a, b)], axis=1), axis=0)
    idx = np.asarray(ids)
    return [(int(p), int(q)) for p, q in zip(idx[uniq[:, 0]], idx[uniq[:, 1]])]
