"""Mesh cleaning with MeshLab filters, each recorded with its parameters and counts.

Duplicate vertices and faces, zero-area faces, non-manifold edges and vertices, small
disconnected pieces, a count of self-intersecting faces (reported, not changed), and hole
filling up to a size (Liepa, "Filling holes in meshes", SGP 2003, as implemented by VCG).
"""

from __future__ import annotations

from dataclasses import dataclass

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Mesh

from .steps import StepRecord, Timer, import_pymeshlab

log = get_logger(__name__)


@dataclass(frozen=True)
class CleanParams:
    """Cleaning parameters.

    Attributes
    ----------
    remove_duplicates : bool
        Merge vertices with identical coordinates and remove repeated faces.
    remove_zero_area : bool
        Remove faces with zero area.
    repair_non_manifold : bool
        Remove faces on non-manifold edges, then split non-manifold vertices.
    min_piece_fraction : float
        Connected pieces whose bounding-box diagonal is below this fraction of the whole
        mesh's diagonal are removed (dimensionless; 0 = keep all).
    min_piece_faces : int
        Connected pieces with fewer faces are removed (count; 0 = keep all).
    max_hole_edges : int
        Holes bounded by at most this many edges are closed (count; 0 = no hole filling).
    report_self_intersections : bool
        Count faces that intersect another face (O(F log F); reported only).
    """

    remove_duplicates: bool = True
    remove_zero_area: bool = True
    repair_non_manifold: bool = True
    min_piece_fraction: float = 0.0
    min_piece_faces: int = 0
    max_hole_edges: int = 0
    report_self_intersections: bool = True

    def __post_init__(self):
        if not 0.0 <= self.min_piece_fraction < 1.0:
            raise InvalidInputError("min_piece_fraction must be in [0, 1)", field="min_piece_fraction")
        if self.max_hole_edges < 0 or self.min_piece_faces < 0:
            raise InvalidInputError("counts must be >= 0", field="max_hole_edges")


def _counts(ms) -> dict:
    m = ms.current_mesh()
    return {"faces": int(m.face_number()), "vertices": int(m.vertex_number())}


def clean(mesh: Mesh, params: CleanParams = CleanParams()) -> tuple[Mesh, StepRecord]:
    """Clean a mesh; returns the new mesh and a record of what each filter removed.

    Vertex colours, normals and quality travel through; face attributes are dropped when
    faces are removed or added (their correspondence is lost).

    Returns
    -------
    (Mesh, StepRecord)
        ``summary["removed"]`` has, per filter, the faces and vertices it removed; ``self_intersecting_faces``,
        ``holes_closed_faces`` and the final ``non_manifold_edges``.
    """
    pml = import_pymeshlab()
    from workstation.interop.pymeshlab import mesh_to_pymeshlab, meshset_with, pymeshlab_to_mesh

    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces to clean")
    removed: dict[str, dict] = {}
    summary: dict = {}
    with Timer() as t:
        m, origin = mesh_to_pymeshlab(mesh)
        ms = meshset_with(m)

        def run(name, fn, **kw):
            before = _counts(ms)
            fn(**kw)
            after = _counts(ms)
            prev = removed.get(name, {"faces": 0, "vertices": 0})
            removed[name] = {"faces": prev["faces"] + before["faces"] - after["faces"],
                             "vertices": prev["vertices"] + before["vertices"] - after["vertices"]}

        if params.remove_duplicates:
            run("duplicate_vertices", ms.meshing_remove_duplicate_vertices)
            run("duplicate_faces", ms.meshing_remove_duplicate_faces)
        if params.remove_zero_area:
            run("zero_area_faces", ms.meshing_remove_null_faces)
        if params.repair_non_manifold:
            for _ in range(3):
                topo = ms.get_topological_measures()
                if topo["non_two_manifold_edges"] == 0 and topo["non_two_manifold_vertices"] == 0:
                    break
                run("non_manifold_edges", ms.meshing_repair_non_manifold_edges, method="Remove Faces")
                run("non_manifold_vertices", ms.meshing_repair_non_manifold_vertices, vertdispratio=0.0)
        if params.min_piece_fraction > 0:
            run("small_pieces_by_diameter", ms.meshing_remove_connected_component_by_diameter,
                mincomponentdiag=pml.PercentageValue(100.0 * params.min_piece_fraction), removeunref=True)
        if params.min_piece_faces > 0:
            run("small_pieces_by_faces", ms.meshing_remove_connected_component_by_face_number,
                mincomponentsize=int(params.min_piece_faces), removeunref=True)
        run("unreferenced_vertices", ms.meshing_remove_unreferenced_vertices)
        if params.max_hole_edges > 0:
            before = _counts(ms)["faces"]
            try:
                ms.meshing_close_holes(maxholesize=int(params.max_hole_edges), newfaceselected=False,
                                       selfintersection=False)
            except pml.PyMeshLabException as e:  # raised on non-manifold input
                raise StageError("clean", f"hole filling failed: {e}", "repair non-manifold edges first") from e
            summary["holes_closed_faces"] = _counts(ms)["faces"] - before
        if params.report_self_intersections and ms.current_mesh().face_number():
            ms.compute_selection_by_self_intersections_per_face()
            summary["self_intersecting_faces"] = int(ms.current_mesh().selected_face_number())
            ms.set_selection_none()
        topo = ms.get_topological_measures()
        summary["non_manifold_edges"] = int(topo["non_two_manifold_edges"])
        summary["non_manifold_vertices"] = int(topo["non_two_manifold_vertices"])
        out = pymeshlab_to_mesh(ms.current_mesh(), origin, crs=mesh.crs, meta=mesh.meta,
                                quality_name="quality" if "quality" in mesh.vertex_attrs else None)
        unchanged = (out.n_faces == mesh.n_faces and not any(r["faces"] or r["vertices"] for r in removed.values())
                     and not summary.get("holes_closed_faces"))
        if unchanged and mesh.face_attrs:
            out = Mesh(out.vertices, out.faces, out.vertex_attrs, mesh.face_attrs, crs=out.crs, meta=out.meta)
    summary["removed"] = removed
    summary.update({"faces": out.n_faces, "vertices": out.n_vertices})
    rec = StepRecord("clean", {"remove_duplicates": params.remove_duplicates, "remove_zero_area": params.remove_zero_area,
                               "repair_non_manifold": params.repair_non_manifold,
                               "min_piece_fraction": params.min_piece_fraction, "min_piece_faces": params.min_piece_faces,
                               "max_hole_edges": params.max_hole_edges}, t.seconds, summary)
    if out.n_faces == 0:
        raise StageError("clean", "cleaning removed every face", "lower min_piece_fraction / min_piece_faces")
    return out, rec

