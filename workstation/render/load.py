"""Load a product file for rendering or reporting: a cloud or a mesh, decided by the file."""

from __future__ import annotations

from pathlib import Path

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Mesh

MESH_ONLY = (".obj", ".glb", ".gltf", ".off")


def ply_face_count(path) -> int:
    """Number of faces declared in a PLY header (0 for a point cloud)."""
    with open(path, "rb") as fh:
        head = fh.read(65536).split(b"end_header")[0].decode("ascii", "replace")
    for line in head.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[0] == "element" and parts[1] == "face":
            if not parts[2].isdigit():
                raise InvalidInputError(f"PLY header: face count {parts[2]!r} is not a whole number",
                                        "the file is damaged; re-export it", path=path, field="element face")
            return int(parts[2])
    return 0


def is_mesh_file(path) -> bool:
    p = Path(path)
    ext = p.suffix.lower()
    return ext in MESH_ONLY or (ext == ".ply" and ply_face_count(p) > 0)


def load_product(path, **read_opts) -> Cloud | Mesh:
    """A :class:`Mesh` for mesh files (PLY with faces, OBJ, glTF, OFF), else a :class:`Cloud`;
    ``read_opts`` (``bounds`` in CRS units, COPC ``resolution``/``level``) select the points read
    (:func:`workstation.io.read_cloud`) and apply to clouds only."""
    read_opts = {k: v for k, v in read_opts.items() if v is not None}
    if is_mesh_file(path):
        if read_opts:
            raise InvalidInputError("--bounds, --resolution and --level select points of a cloud; this is a mesh",
                                    "leave them out for a mesh", path=path, field="--" + next(iter(read_opts)))
        from workstation.io.mesh import read_mesh

        return read_mesh(path)
    from workstation.io import read_cloud

    return read_cloud(path, **read_opts)
