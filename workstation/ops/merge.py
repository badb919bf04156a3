"""Merge plain files (PDAL ``filters.merge``): concatenate their points, streamed, into one output.

The output has the union of the inputs' attributes (an attribute an input lacks is 0 for
its points, NaN for free float attributes), the finest of the inputs' LAS scales on each
axis, offsets that fit all of them, and a point format holding every standard attribute
(format 1 + a colour input -> format 3). ``point_source_id`` is kept as in the inputs (flight
line numbers, as PDAL keeps them) when any input has non-zero ids ("auto", judged on each
input's first chunk), or set to the input's number 1, 2, ... ("input"; the rule of
registered scans). Inputs must share their CRS (or have none).
"""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError, StageError

from .stream import CHUNK, chain_first, cloud_sink, input_bounds, input_chunks, union_bounds

SOURCE_IDS = ("auto", "input", "keep")


def _template(firsts: list[Cloud], number_inputs: bool) -> Cloud:
    """An empty cloud with the union schema, the first input's metadata, the finest scales and
    the extra-byte definitions of every input."""
    schema = concatenate([f[:1] for f in firsts], check_crs=False)[:0]
    if number_inputs:
        schema = schema.with_attrs(point_source_id=np.zeros(0, np.uint16))
    las = dict(firsts[0].meta.get("las", {}))
    scales = [f.meta["las"]["scales"] for f in firsts if f.meta.get("las", {}).get("scales")]
    if scales:
        las["scales"] = np.min(scales, axis=0).tolist()
    defs = {}
    for f in firsts:
        for d in f.meta.get("las", {}).get("extra_dims", []):
            defs.setdefault(d["name"], d)
    las["extra_dims"] = list(defs.values())
    return schema.with_meta(las=las)


def merge_files(inputs, output, *, source_ids: str = "auto", overwrite: bool = False, chunk_size: int = CHUNK,
                read_opts: dict | None = None, **write_opts) -> dict:
    """Concatenate the points of ``inputs`` into ``output`` chunk by chunk; returns a summary.

    Parameters
    ----------
    source_ids : {"auto", "input", "keep"}
        What ``point_source_id`` becomes (see the module docstring).
    read_opts : dict, optional
        ``bounds``/``resolution``/``level``: the points read from each input
        (:func:`~workstation.ops.stream.input_chunks`).
    """
    if source_ids not in SOURCE_IDS:
        raise InvalidInputError(f"unknown source id rule '{source_ids}'", f"one of {', '.join(SOURCE_IDS)}",
                                field="source_ids")
    streams = [input_chunks(p, chunk_size, **(read_opts or {})) for p in inputs]
    firsts = [next(it, None) for it in streams]  # each input is read once: its first chunk is kept
    if any(f is None for f in firsts):
        raise InvalidInputError("has no points", path=inputs[[f is None for f in firsts].index(True)])
    crs_set = {f.crs for f in firsts if f.crs}
    if len(crs_set) > 1:
        raise InvalidInputError(f"inputs have {len(crs_set)} different CRSs",
                                "reproject them to one CRS first (ws convert --to-crs)", field="crs")
    nonzero = any(np.any(f.attrs["point_source_id"]) for f in firsts if "point_source_id" in f.attrs)
    number = source_ids == "input" or (source_ids == "auto" and not nonzero)
    template = _template(firsts, number)
    bounds = union_bounds(input_bounds(p) for p in inputs)
    counts = []
    with cloud_sink(output, template, overwrite=overwrite, inputs=inputs, bounds=bounds, **write_opts) as sink:
        for k in range(len(inputs)):
            before = sink.count
            for chunk in chain_first(firsts[k], streams[k]):
                c = concatenate([template, chunk], check_crs=False)
                if number:
                    c = c.with_attrs(point_source_id=np.full(c.n, k + 1, np.uint16))
                sink.write(c)
            counts.append(sink.count - before)
    if sum(counts) == 0:
        raise StageError("merge", "the merged cloud is empty", "check the inputs")
    return {"points": sum(counts), "points_per_input": counts, "attributes": template.dims,
            "source_ids": "input number" if number else "kept"}
