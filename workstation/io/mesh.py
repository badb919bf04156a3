"""Mesh files <-> :class:`~workstation.core.products.Mesh`: PLY, OBJ (+MTL and texture), GLB/glTF, OFF.

- PLY is written here with numpy (binary little-endian, float64 vertices so projected
  coordinates keep their millimetres, uchar colours, float normals, int32 faces); read with
  trimesh.
- OBJ, GLB/glTF and OFF go through trimesh. glTF stores float32 positions, so the mesh
  is written relative to its rounded bounding-box centre and that origin goes in the node's
  translation (float64 JSON): readers that apply node transforms get the true coordinates.
- A textured mesh carries per-vertex ``uv`` (n, 2) float32 in ``vertex_attrs`` and the image
  (h, w, 3|4) uint8 in ``meta["texture"]``; OBJ writes it as a PNG beside an MTL file. The
  material and its texture are named after the mesh file (``facade.obj`` -> ``facade.mtl``,
  material ``facade``, ``facade.png``; in GLB/glTF the material ``facade``), so two meshes in
  one folder never share a texture file, and ``overwrite`` applies to all three files.

Every file is written through :func:`workstation.io.atomic_path` (temporary file, rename).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workstation.core.color import rgb_to_u8
from workstation.core.errors import InvalidInputError, MissingDependencyError, UnsupportedFormatError
from workstation.core.geometry import default_origin
from workstation.core.products import Mesh

from .atomic import atomic_path, check_output

MESH_EXTENSIONS = (".ply", ".obj", ".glb", ".gltf", ".off")


def _trimesh():
    try:
        import trimesh
    except ImportError as e:  # pragma: no cover - declared dependency
        raise MissingDependencyError("trimesh", "mesh files (OBJ, glTF)", "pip install trimesh") from e
    return trimesh


def check_mesh_extension(path) -> str:
    ext = Path(path).suffix.lower()
    if ext not in MESH_EXTENSIONS:
        raise UnsupportedFormatError(f"unknown mesh extension '{ext or '(none)'}'",
                                     "use one of " + ", ".join(MESH_EXTENSIONS), path=path)
    return ext


def _rgb_u8(mesh: Mesh) -> np.ndarray | None:
    if "rgb" not in mesh.vertex_attrs:
        return None
    return rgb_to_u8(np.asarray(mesh.vertex_attrs["rgb"]))


def _write_ply(mesh: Mesh, path: Path) -> None:
    n, m = mesh.n_vertices, mesh.n_faces
    fields = [("x", "<f8"), ("y", "<f8"), ("z", "<f8")]
    props = ["property double x", "property double y", "property double z"]
    normal = mesh.vertex_attrs.get("normal")
    rgb = _rgb_u8(mesh)
    if normal is not None:
        fields += [("nx", "<f4"), ("ny", "<f4"), ("nz", "<f4")]
        props += ["property float nx", "property float ny", "property float nz"]
    if rgb is not None:
        fields += [("red", "u1"), ("green", "u1"), ("blue", "u1")]
        props += ["property uchar red", "property uchar green", "property uchar blue"]
    v = np.empty(n, dtype=fields)
    v["x"], v["y"], v["z"] = mesh.vertices.T
    if normal is not None:
        v["nx"], v["ny"], v["nz"] = np.asarray(normal, dtype=np.float32).T
    if rgb is not None:
        v["red"], v["green"], v["blue"] = rgb.T
    f = np.empty(m, dtype=[("k", "u1"), ("i", "<i4", (3,))])
    f["k"] = 3
    f["i"] = mesh.faces
    header = ["ply", "format binary_little_endian 1.0", "comment written by workstation"]
    if mesh.crs:
        header.append("comment crs " + " ".join(str(mesh.crs).split()))
    header += [f"element vertex {n}", *props, f"element face {m}", "property list uchar int vertex_indices",
               "end_header"]
    with open(path, "wb") as fh:
        fh.write(("\n".join(header) + "\n").encode("ascii"))
        fh.write(v.tobytes())
        fh.write(f.tobytes())


def textured_obj_files(path) -> list[Path]:
    """The files a textured ``OUT.obj`` is written as: ``OUT.obj``, ``OUT.mtl``, ``OUT.png``."""
    p = Path(path)
    return [p, p.with_suffix(".mtl"), p.with_suffix(".png")]


def _to_trimesh(mesh: Mesh, origin=None, name: str = "material", pbr: bool = False):
    """A trimesh of ``mesh``; a texture becomes the material ``name`` (OBJ names its image
    ``name.png``), white so that viewers, which multiply the texture by the material colour
    (MTL ``Kd``, glTF ``baseColorFactor``), show the photo colours; ``pbr`` for glTF (a
    metallic-roughness material: not metallic, fully rough)."""
    trimesh = _trimesh()
    v = mesh.vertices if origin is None else mesh.vertices - origin
    tm = trimesh.Trimesh(v, mesh.faces, process=False)
    tex = mesh.meta.get("texture")
    if "uv" in mesh.vertex_attrs and tex is not None:
        from PIL import Image as PILImage

        img = PILImage.fromarray(np.asarray(tex, dtype=np.uint8))
        white = [255, 255, 255, 255]
        if pbr:
            material = trimesh.visual.material.PBRMaterial(name=name, baseColorTexture=img, baseColorFactor=white,
                                                            metallicFactor=0.0, roughnessFactor=1.0)
        else:
            material = trimesh.visual.material.SimpleMaterial(image=img, name=name, diffuse=white)
        tm.visual = trimesh.visual.TextureVisuals(uv=np.asarray(mesh.vertex_attrs["uv"], dtype=np.float64),
                                                  material=material)
    else:
        rgb = _rgb_u8(mesh)
        if rgb is not None:
            tm.visual = trimesh.visual.ColorVisuals(tm, vertex_colors=np.column_stack([rgb, np.full(len(rgb), 255, np.uint8)]))
    return tm


def write_mesh(mesh: Mesh, path, *, overwrite: bool = False, inputs=()) -> Path:
    """Write a mesh; the format follows the extension.

    Parameters
    ----------
    mesh : Mesh
        ``rgb`` vertex colours (u8 or u16) and ``normal`` travel where the format allows.
    path : path-like
        .ply, .obj (+ .mtl and .png when textured), .glb, .gltf (single file, buffers
        embedded), .off.
    overwrite : bool
        Replace existing files.

    Returns
    -------
    Path
    """
    ext = check_mesh_extension(path)
    p = Path(path)
    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces", "meshing failed upstream", path=p)
    if ext == ".ply":
        with atomic_path(p, overwrite=overwrite, inputs=inputs) as tmp:
            _write_ply(mesh, tmp)
        return p
    trimesh = _trimesh()
    if ext == ".obj":
        tm = _to_trimesh(mesh, name=p.stem)
        textured = isinstance(tm.visual, trimesh.visual.TextureVisuals)
        from .atomic import check_outputs

        check_outputs(textured_obj_files(p) if textured else [p], overwrite, inputs)
        mtl_name = p.stem + ".mtl"
        text, files = trimesh.exchange.obj.export_obj(
            tm, include_normals="normal" in mesh.vertex_attrs, include_color=not textured,
            include_texture=textured, return_texture=True, mtl_name=mtl_name, digits=9)
        for name, data in (files or {}).items():
            with atomic_path(p.parent / name, overwrite=overwrite, inputs=inputs) as tmp:
                tmp.write_bytes(data)
        with atomic_path(p, overwrite=overwrite, inputs=inputs) as tmp:
            tmp.write_text(text)
        return p
    if ext in (".glb", ".gltf"):
        origin = default_origin(mesh.vertices)
        tm = _to_trimesh(mesh, origin, name=p.stem, pbr=True)
        T = np.eye(4)
        T[:3, 3] = origin
        scene = trimesh.Scene()
        scene.add_geometry(tm, node_name="mesh", geom_name="mesh", transform=T)
        with atomic_path(p, overwrite=overwrite, inputs=inputs) as tmp:
            if ext == ".glb":
                tmp.write_bytes(scene.export(file_type="glb"))
            else:
                data = trimesh.exchange.gltf.export_gltf(scene, embed_buffers=True)
                tmp.write_bytes(data["model.gltf"])
        return p
    tm = _to_trimesh(mesh)
    with atomic_path(p, overwrite=overwrite, inputs=inputs) as tmp:
        tm.export(tmp, file_type=ext[1:])
    return p


def _ply_has_normals(path: Path) -> bool:
    with open(path, "rb") as fh:
        head = fh.read(4096).split(b"end_header")[0]
    return b" nx" in head


def read_mesh(path) -> Mesh:
    """Read a mesh file (PLY, OBJ, GLB/glTF, OFF) into a :class:`Mesh`.

    Vertex colours become ``rgb`` (n, 3) uint8; a texture becomes ``uv`` and
    ``meta["texture"]``. Scenes are flattened with their node transforms applied.
    """
    p = Path(path)
    check_mesh_extension(p)
    if not p.exists():
        raise InvalidInputError("file not found", "check the path", path=p)
    if p.is_dir():
        raise InvalidInputError("is a folder, not a mesh file", path=p)
    if p.stat().st_size == 0:
        raise InvalidInputError("file is empty (0 bytes)", "the file was not written completely; get it again", path=p)
    trimesh = _trimesh()
    try:
        loaded = trimesh.load(p, process=False, maintain_order=True)
    except Exception as e:  # trimesh raises many types on malformed files
        raise InvalidInputError(f"cannot read mesh: {e}", "check the file is a complete mesh", path=p) from e
    try:
        return _mesh_from_loaded(trimesh, loaded, p)
    except InvalidInputError as e:
        if e.path is not None:
            raise
        raise InvalidInputError(e.message, e.hint or "check the file is a complete mesh", path=p, field=e.field) from None
    except Exception as e:  # noqa: BLE001 - trimesh computes colours lazily and fails there on bad indices
        raise InvalidInputError(f"cannot read mesh: {type(e).__name__}: {e}", "check the file is a complete mesh",
                                path=p) from None


def _mesh_from_loaded(trimesh, loaded, p: Path) -> Mesh:
    """The :class:`Mesh` of what ``trimesh.load`` returned for file ``p`` (scenes flattened)."""
    if isinstance(loaded, trimesh.Scene):
        geoms = [g for g in loaded.dump() if isinstance(g, trimesh.Trimesh)] if hasattr(loaded, "dump") else []
        if not geoms:
            raise InvalidInputError("the file holds no triangle mesh", path=p)
        loaded = geoms[0] if len(geoms) == 1 else trimesh.util.concatenate(geoms)
    if not isinstance(loaded, trimesh.Trimesh) or len(loaded.faces) == 0:
        raise InvalidInputError("the file holds no triangles (a point cloud?)", "read it with read_cloud", path=p)
    attrs: dict = {}
    meta: dict = {"source": str(p)}
    vis = loaded.visual
    if isinstance(vis, trimesh.visual.TextureVisuals) and vis.uv is not None and len(vis.uv) == len(loaded.vertices):
        attrs["uv"] = np.asarray(vis.uv, dtype=np.float32)
        img = getattr(vis.material, "image", None) or getattr(vis.material, "baseColorTexture", None)
        if img is not None:
            meta["texture"] = np.asarray(img.convert("RGB"))
    elif vis.kind == "vertex":
        attrs["rgb"] = np.asarray(vis.vertex_colors)[:, :3].astype(np.uint8)
    if p.suffix.lower() == ".ply" and _ply_has_normals(p):
        attrs["normal"] = np.asarray(loaded.vertex_normals, dtype=np.float32)
    return Mesh(np.asarray(loaded.vertices, dtype=np.float64), np.asarray(loaded.faces, dtype=np.int64), attrs, meta=meta)
