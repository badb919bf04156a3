"""``run.json``: what each task of a project run did, so a re-run does only what changed.

As ODM's stage records, each task (a stage on a chunk, or a mosaic) has a key: the hash of its
stage, parameters, input files' contents and upstream tasks' keys. A task whose key is recorded
as done, with every output still on disk, is skipped; a changed parameter changes the key of
that stage's tasks and, through the upstream keys, of everything after them. Files are hashed
once (SHA-256) and the hash reused while their size and modification time are unchanged.
"""

from __future__ import annotations

import hashlib
import json
import os
import time
from pathlib import Path

from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)

FORMAT = 1  # bumped when task outputs change meaning, so an older run.json reruns everything


def task_key(stage: str, params, inputs=(), upstream=()) -> str:
    """The content key of a task: stage, parameters, input hashes and upstream keys."""
    from workstation import __version__

    doc = {"format": FORMAT, "version": __version__, "stage": stage, "params": params,
           "inputs": sorted(inputs), "upstream": sorted(upstream)}
    return hashlib.sha256(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()


def file_sha256(path: Path, block: int = 8 << 20) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        while chunk := f.read(block):
            h.update(chunk)
    return h.hexdigest()


class Manifest:
    """The records of ``run.json`` in a project's output folder.

    Attributes
    ----------
    path : Path
    tasks : dict
        Task id -> record (stage, chunk, key, status, params, inputs, outputs, seconds ...).
    files : dict
        Input path -> {"size", "mtime_ns", "sha256"}.
    """

    def __init__(self, path: Path):
        self.path = Path(path)
        self.tasks: dict[str, dict] = {}
        self.files: dict[str, dict] = {}
        self.info: dict = {}
        self._saved = 0.0
        if self.path.exists():
            try:
                doc = json.loads(self.path.read_text())
                if doc.get("format") == FORMAT:
                    self.tasks, self.files = dict(doc.get("tasks", {})), dict(doc.get("files", {}))
            except (json.JSONDecodeError, UnicodeDecodeError, AttributeError):
                log.warning("%s is unreadable; every task runs again", self.path)

    def file_hash(self, path: Path) -> str:
        """SHA-256 of ``path``, reused from the last run while size and mtime are unchanged."""
        st = os.stat(path)
        rec = self.files.get(str(path))
        if rec and rec["size"] == st.st_size and rec["mtime_ns"] == st.st_mtime_ns:
            return rec["sha256"]
        try:
            digest = file_sha256(path)
        except OSError as e:
            raise InvalidInputError(f"cannot read: {e.strerror}", path=path) from None
        self.files[str(path)] = {"size": st.st_size, "mtime_ns": st.st_mtime_ns, "sha256": digest}
        return digest

    def is_done(self, task_id: str, key: str) -> bool:
        rec = self.tasks.get(task_id)
        return bool(rec and rec.get("key") == key and rec.get("status") == "done"
                    and all(Path(p).exists() for p in self._absolute(rec.get("outputs", []))))

    def _absolute(self, paths) -> list[str]:
        return [str(self.path.parent / p) for p in paths]  # an absolute p stays as it is

    def record(self, task_id: str, rec: dict) -> None:
        """Keep a task's record; its outputs are stored relative to the output folder, so the
        folder can be moved or shared between machines."""
        out = []
        for p in rec.get("outputs", []):
            try:
                out.append(str(Path(p).relative_to(self.path.parent)))
            except ValueError:
                out.append(str(p))
        self.tasks[task_id] = {**rec, "outputs": out}
        if time.monotonic() - self._saved > 2.0:  # bounded cost on thousands of tasks
            self.save()

    def outputs_of(self, task_ids) -> list[str]:
        """The absolute paths of the outputs recorded for ``task_ids``."""
        return [p for t in task_ids for p in self._absolute(self.tasks.get(t, {}).get("outputs", []))]

    def save(self, **info) -> None:
        """Write ``run.json`` atomically (a temporary file renamed over it)."""
        from workstation.io import atomic_path

        self.info.update(info)
        doc = {"format": FORMAT, **self.info, "files": self.files, "tasks": self.tasks}
        self.path.parent.mkdir(parents=True, exist_ok=True)
        with atomic_path(self.path, overwrite=True) as tmp:
            tmp.write_text(json.dumps(doc, indent=1, default=str))
        self._saved = time.monotonic()
