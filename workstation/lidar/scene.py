"""Deterministic synthetic scenes: a labelled triangle mesh from a recipe and a seed.

A scene is one triangle mesh whose faces carry an ASPRS class, a material id (see
:mod:`workstation.lidar.materials`) and an object id (0 = terrain, then one id per building,
tree, car, pylon, ...). :func:`build_scene` makes it from a :class:`SceneRecipe` (read from
TOML with :func:`load_recipe`; the shipped ones live in ``datasets_synth/``) and a seed;
the same pair always gives the same mesh, bit for bit.

Contents: a heightfield terrain (regional slope, a ridge, a breakline where the slope changes
abruptly, a roadside ditch, a steep embankment, fractal roughness, optional mountain relief,
optional earthworks: embankments and cuttings with a flat crest or floor and planar sides),
a road with cars, a stream with a bridge, a pond, buildings with flat, gabled and hipped roofs
with overhangs, courtyard blocks, a heritage church (nave, portico with columns, tower and
spire), trees whose crowns are clouds of small leaf triangles (so part of a beam passes
through), low and medium vegetation, and a power line (pylons and catenary conductors).
Coordinates of the exported :class:`~workstation.core.products.Mesh` are absolute map
coordinates (EPSG:32632 by default, the scene centred on the recipe's origin).
"""

from __future__ import annotations

import dataclasses
import hashlib
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.core.products import Mesh

from workstation.io.textfile import read_text

from . import shapes as S
from .materials import MATERIAL_ID as M
from .materials import MATERIALS, Material

log = get_logger(__name__)

RECIPE_DIR = Path(__file__).resolve().parents[2] / "datasets_synth"


# ---------------------------------------------------------------------------------------------
# recipe
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class TerrainSpec:
    """Terrain shape; every length in metres, slopes in percent.

    Attributes
    ----------
    resolution : float
        Heightfield grid spacing (m).
    base_height : float
        Mean terrain height above the vertical datum (m).
    slope_percent : float
        Regional planar slope (%), in a random direction.
    relief : float
        Amplitude of large smooth hills (m); mountains use tens of metres.
    roughness : float
        Amplitude of short-wavelength fractal roughness (m).
    ridge_height, ridge_width : float
        Height and 1-sigma half-width of a Gaussian ridge (m); 0 disables it.
    breakline_slope_percent : float
        Slope change across a straight breakline (%), a crease in the terrain; 0 disables it.
    ditch_depth, ditch_width : float
        V-shaped roadside ditch depth and top width (m); 0 disables it.
    embankment_height, embankment_slope_deg : float
        A levee beside the stream, its height (m) and side steepness (degrees).
    """

    resolution: float = 1.0
    base_height: float = 120.0
    slope_percent: float = 2.0
    relief: float = 0.0
    roughness: float = 0.15
    ridge_height: float = 4.0
    ridge_width: float = 15.0
    breakline_slope_percent: float = 8.0
    ditch_depth: float = 0.8
    ditch_width: float = 3.0
    embankment_height: float = 2.5
    embankment_slope_deg: float = 40.0


@dataclass(frozen=True)
class SceneRecipe:
    """What to put in a scene. Lengths in metres, counts are numbers of objects.

    Attributes
    ----------
    name : str
    extent : (float, float)
        Size in x (east) and y (north), metres.
    origin : (float, float)
        Map coordinates (easting, northing) of the scene centre, metres.
    crs : str
    terrain : TerrainSpec
    buildings : int
        Ordinary buildings (flat, gabled, hipped roofs, random mix).
    courtyards : int
        Courtyard blocks (four flat-roofed wings around an open yard).
    building_height : (float, float)
        Eave height range of ordinary buildings (m).
    building_length, building_width : (float, float)
        Footprint ranges of ordinary buildings (m, long and short side).
    large_buildings : int
        Large flat-roofed blocks (halls, department stores, schools) with roof furniture
        (HVAC boxes, stairwells, skylight rows) on the roof.
    large_size : (float, float)
        Side range of the large blocks (m).
    large_height : (float, float)
        Roof height range of the large blocks (m).
    houses : int
        Small detached houses and sheds with gabled, hipped or flat roofs, each with one to
        three garden trees planted beside its walls so their crowns overhang the roof.
    house_size : (float, float)
        Side range of the houses (m).
    house_height : (float, float)
        Eave height range of the houses (m).
    heritage : bool
        Add the church (nave, portico with columns, tower with spire).
    trees : int
        Number of trees; ``forest_fraction`` of them are clustered into stands.
    forest_fraction : float
    conifer_fraction : float
    bushes : int
        Medium-vegetation shrubs.
    grass_patches : int
        Low-vegetation patches.
    road : bool
    cars : int
    stream : bool
        Stream with water surface; with ``road`` also a bridge carrying the road over it.
    pond : bool
    powerline : bool
    embankments : int
        Earth embankments on the terrain: dikes, levees, road and railway embankments, long
        straight or gently curved ridges with a flat crest and planar side slopes, some
        crossing the whole scene, some ending in ramps, about half carrying a road or track
        on the crest (see :func:`_draw_earthworks`).
    cuttings : int
        Cuttings: the same shape carved into the terrain (a flat floor between side slopes).
    earthwork_height : (float, float)
        Embankment height and cutting depth range (m).
    earthwork_crest : (float, float)
        Crest (cutting floor) width range (m).
    earthwork_side : (float, float)
        Side slope range as horizontal run per metre of rise (1.5: a 1:1.5 slope).
    """

    name: str = "mixed"
    extent: tuple = (300.0, 300.0)
    origin: tuple = (500000.0, 5000000.0)
    crs: str = "EPSG:32632"
    terrain: TerrainSpec = field(default_factory=TerrainSpec)
    buildings: int = 8
    courtyards: int = 1
    building_height: tuple = (5.0, 12.0)
    building_length: tuple = (8.0, 20.0)
    building_width: tuple = (7.0, 12.0)
    large_buildings: int = 0
    large_size: tuple = (30.0, 90.0)
    large_height: tuple = (6.0, 30.0)
    houses: int = 0
    house_size: tuple = (4.0, 12.0)
    house_height: tuple = (2.5, 6.0)
    heritage: bool = True
    trees: int = 120
    forest_fraction: float = 0.5
    conifer_fraction: float = 0.3
    bushes: int = 40
    grass_patches: int = 40
    road: bool = True
    cars: int = 8
    stream: bool = True
    pond: bool = True
    powerline: bool = True
    embankments: int = 0
    cuttings: int = 0
    earthwork_height: tuple = (2.0, 8.0)
    earthwork_crest: tuple = (3.0, 15.0)
    earthwork_side: tuple = (1.5, 3.0)


def _from_dict(cls, data: dict, where: str):
    names = {f.name: f for f in dataclasses.fields(cls)}
    kw = {}
    for k, v in data.items():
        if k not in names:
            raise InvalidInputError(f"unknown key '{k}' in [{where}]", "keys: " + ", ".join(names), field=k)
        if k == "terrain":
            v = _from_dict(TerrainSpec, v, "terrain")
        elif isinstance(v, list):
            v = tuple(v)
        kw[k] = v
    return cls(**kw)


def load_recipe(path_or_name: str | Path) -> SceneRecipe:
    """Read a recipe TOML (a path, or the name of a shipped one: urban, rural, forest, ...).

    The file has a ``[scene]`` table with :class:`SceneRecipe` keys and a ``[scene.terrain]``
    table with :class:`TerrainSpec` keys; missing keys take their defaults.
    """
    p = Path(path_or_name)
    if not p.exists() and (RECIPE_DIR / f"{path_or_name}.toml").exists():
        p = RECIPE_DIR / f"{path_or_name}.toml"
    if not p.exists():
        raise InvalidInputError("recipe not found", f"give a TOML path or one of {recipe_names()}", path=p)
    try:
        data = tomllib.loads(read_text(p))
    except tomllib.TOMLDecodeError as e:
        raise InvalidInputError(f"not valid TOML: {e}", path=p) from None
    if "scene" not in data:
        raise InvalidInputError("no [scene] table", "see datasets_synth/mixed.toml", path=p)
    return _from_dict(SceneRecipe, data["scene"], "scene")


def recipe_names() -> list[str]:
    """Names of the recipes shipped in ``datasets_synth/``."""
    return sorted(p.stem for p in RECIPE_DIR.glob("*.toml")) if RECIPE_DIR.is_dir() else []


# ---------------------------------------------------------------------------------------------
# scene
# ---------------------------------------------------------------------------------------------
#: Finer per-face labels than the ASPRS class (``part`` face attribute and point dimension).
PARTS: dict[int, str] = {
    0: "other", 1: "terrain", 2: "road", 3: "roof", 4: "wall", 5: "trunk", 6: "crown", 7: "shrub",
    8: "grass", 9: "water", 10: "bridge", 11: "wire", 12: "pylon", 13: "vehicle",
}
PART_ID: dict[str, int] = {v: k for k, v in PARTS.items()}


def face_parts(vertices: np.ndarray, faces: np.ndarray, classification: np.ndarray, material: np.ndarray) -> np.ndarray:
    """Part code (:data:`PARTS`) of each face from its class, material and orientation.

    Building faces facing up (normal z > 0.3, roofs and flat tops) are ``roof``, the others
    ``wall``; high vegetation is ``trunk`` (bark) or ``crown``; unclassified car paint is a
    ``vehicle``.
    """
    tri = vertices[faces]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nz = n[:, 2] / np.maximum(np.linalg.norm(n, axis=1), 1e-12)
    cls = classification
    out = np.zeros(len(faces), np.uint8)
    table = {C.GROUND: "terrain", C.ROAD_SURFACE: "road", C.MEDIUM_VEGETATION: "shrub", C.LOW_VEGETATION: "grass",
             C.WATER: "water", C.BRIDGE_DECK: "bridge", C.WIRE_CONDUCTOR: "wire", C.TRANSMISSION_TOWER: "pylon"}
    for c, name in table.items():
        out[cls == c] = PART_ID[name]
    bld = cls == C.BUILDING
    out[bld] = np.where(np.abs(nz[bld]) > 0.3, PART_ID["roof"], PART_ID["wall"])
    hv = cls == C.HIGH_VEGETATION
    out[hv] = np.where(material[hv] == M["bark"], PART_ID["trunk"], PART_ID["crown"])
    out[(cls == C.UNCLASSIFIED) & (material == M["car_paint"])] = PART_ID["vehicle"]
    return out


@dataclass(frozen=True)
class Scene:
    """A labelled triangle mesh in local coordinates plus its map origin.

    Attributes
    ----------
    vertices : (n, 3) float64
        Local coordinates (m): x east, y north, z up, relative to ``origin``.
    faces : (m, 3) int64
    classification : (m,) uint8
        ASPRS class per face.
    material : (m,) uint16
        Index into ``materials``.
    object_id : (m,) uint32
        0 for terrain, one id per object.
    face_rgb : (m, 3) uint8
        Visible colour per face (material albedo with per-object variation).
    origin : (3,) float64
        Map coordinates of the local origin (easting, northing, 0).
    crs : str
    materials : tuple of Material
    meta : dict
        Recipe name, seed, object list (id -> kind).
    """

    vertices: np.ndarray
    faces: np.ndarray
    classification: np.ndarray
    material: np.ndarray
    object_id: np.ndarray
    face_rgb: np.ndarray
    origin: np.ndarray
    crs: str = "EPSG:32632"
    materials: tuple = MATERIALS
    meta: dict = field(default_factory=dict)

    @property
    def n_faces(self) -> int:
        return int(self.faces.shape[0])

    @property
    def part(self) -> np.ndarray:
        """(m,) uint8 part code per face (:data:`PARTS`), computed on first use."""
        p = self.__dict__.get("_part")
        if p is None:
            p = face_parts(self.vertices, self.faces, self.classification, self.material)
            object.__setattr__(self, "_part", p)
        return p

    def bounds_local(self) -> tuple[np.ndarray, np.ndarray]:
        return self.vertices.min(axis=0), self.vertices.max(axis=0)

    def to_mesh(self) -> Mesh:
        """The scene as a core :class:`Mesh` in map coordinates.

        ``face_attrs``: ``classification`` u8, ``material`` u16, ``object_id`` u32, ``part``
        u8 (:data:`PARTS`), ``rgb`` (m, 3) u8; ``meta`` holds the material table, the part
        names and the recipe/seed.
        """
        return Mesh(
            self.vertices + self.origin,
            self.faces,
            face_attrs={"classification": self.classification, "material": self.material,
                        "object_id": self.object_id, "part": self.part, "rgb": self.face_rgb},
            crs=self.crs,
            meta={**self.meta, "materials": [dataclasses.asdict(m) for m in self.materials],
                  "parts": {str(k): v for k, v in PARTS.items()}},
        )

    @classmethod
    def from_mesh(cls, mesh: Mesh, origin=None) -> "Scene":
        """A scene from a core :class:`Mesh` with ``classification`` / ``material`` / ``object_id``
        face attributes (missing ones default to unclassified / concrete / 0)."""
        m = mesh.n_faces
        origin = np.array([*np.floor(mesh.vertices[:, :2].mean(0)), 0.0]) if origin is None else np.asarray(origin, float)
        fa = mesh.face_attrs
        mat = np.asarray(fa.get("material", np.full(m, M["concrete"])), np.uint16)
        if mat.size and mat.max() >= len(MATERIALS):
            raise InvalidInputError(f"material id {int(mat.max())} is not in the table", field="material")
        rgb = fa.get("rgb")
        if rgb is None:
            rgb = np.array([x.albedo for x in MATERIALS], np.uint8)[mat]
        return cls(mesh.vertices - origin, mesh.faces,
                   np.asarray(fa.get("classification", np.full(m, C.UNCLASSIFIED)), np.uint8), mat,
                   np.asarray(fa.get("object_id", np.zeros(m)), np.uint32), np.asarray(rgb, np.uint8),
                   origin, mesh.crs or "EPSG:32632", MATERIALS, dict(mesh.meta))


class _Builder:
    """Accumulates labelled parts; one Python call per object (never per point)."""

    def __init__(self):
        self.v: list[np.ndarray] = []
        self.f: list[np.ndarray] = []
        self.cls: list[np.ndarray] = []
        self.mat: list[np.ndarray] = []
        self.obj: list[np.ndarray] = []
        self.rgb: list[np.ndarray] = []
        self.nv = 0
        self.next_id = 1
        self.kinds: dict[int, str] = {0: "terrain"}

    def new_object(self, kind: str) -> int:
        i = self.next_id
        self.next_id += 1
        self.kinds[i] = kind
        return i

    def add(self, vf, cls, mat, obj: int, rgb=None):
        v, f = vf
        m = len(f)
        self.v.append(np.asarray(v, float))
        self.f.append(np.asarray(f, np.int64) + self.nv)
        self.nv += len(v)
        self.cls.append(np.broadcast_to(np.asarray(cls, np.uint8), (m,)))
        self.mat.append(np.broadcast_to(np.asarray(mat, np.uint16), (m,)))
        self.obj.append(np.full(m, obj, np.uint32))
        mat_arr = np.broadcast_to(np.asarray(mat, np.uint16), (m,))
        base = np.array([x.albedo for x in MATERIALS], np.uint8)[mat_arr]
        if rgb is not None:
            base = np.broadcast_to(np.asarray(rgb, np.uint8), (m, 3))
        self.rgb.append(base)

    def finish(self):
        return (np.vstack(self.v), np.vstack(self.f), np.concatenate(self.cls), np.concatenate(self.mat),
                np.concatenate(self.obj), np.ascontiguousarray(np.vstack(self.rgb)))


@dataclass(frozen=True)
class _Line:
    """A straight line through ``p`` with unit direction ``d`` (2-D)."""

    p: np.ndarray
    d: np.ndarray

    def signed(self, x, y):
        """Signed perpendicular distance (left positive) of points (x, y) to the line."""
        return (x - self.p[0]) * -self.d[1] + (y - self.p[1]) * self.d[0]

    def along(self, x, y):
        return (x - self.p[0]) * self.d[0] + (y - self.p[1]) * self.d[1]

    def point(self, s, off=0.0):
        n = np.array([-self.d[1], self.d[0]])
        return self.p + np.multiply.outer(s, self.d) + np.multiply.outer(off, n)

    @property
    def angle(self) -> float:
        return float(np.arctan2(self.d[1], self.d[0]))


@dataclass(frozen=True)
class _Earthwork:
    """An embankment (``sign`` +1) or a cutting (-1) of trapezoidal cross-section.

    The centre line is ``line`` bent sideways by ``amp * sin(2 pi s / wavelength + phase)``
    (``s`` along the line); the crest (a cutting's floor) is ``crest`` wide, ``height`` above
    (below) the terrain, with planar sides of ``side`` metres run per metre of rise. It runs
    from ``s0`` to ``s1`` along the line (infinite: across the scene) and its height falls to
    nought over ``ramp`` metres at each end. ``road``: half width of the road or track on
    the crest (0: none), of material ``road_mat``.
    """

    line: _Line
    sign: float
    height: float
    crest: float
    side: float
    amp: float
    wavelength: float
    phase: float
    s0: float
    s1: float
    ramp: float
    road: float
    road_mat: int

    def offset(self, x, y):
        """Distance (m) of points (x, y) across the bent centre line, and their position along it."""
        s = self.line.along(x, y)
        bend = self.amp * np.sin(2 * np.pi * s / self.wavelength + self.phase)
        return np.abs(self.line.signed(x, y) - bend), s

    def rise(self, x, y) -> np.ndarray:
        """Height (m, >= 0) the earthwork adds to (an embankment) or takes from (a cutting) the
        terrain at (x, y): the crest height inside the crest, falling at 1:``side`` outside."""
        d, s = self.offset(x, y)
        h = self.height * np.clip(np.minimum(s - self.s0, self.s1 - s) / self.ramp, 0.0, 1.0)
        return np.clip(self.crest / 2 + self.side * h - d, 0.0, self.side * h) / self.side

    def covers(self, x, y, margin: float) -> bool:
        """Whether (x, y) lies within ``margin`` m of the earthwork's footprint."""
        d, s = self.offset(x, y)
        return bool(d < self.crest / 2 + self.side * self.height + margin and self.s0 - margin < s < self.s1 + margin)

    def to_meta(self) -> dict:
        return {"kind": "embankment" if self.sign > 0 else "cutting", "p": self.line.p.tolist(),
                "d": self.line.d.tolist(), "height": self.height, "crest": self.crest, "side": self.side,
                "amp": self.amp, "wavelength": self.wavelength, "phase": self.phase,
                "s0": self.s0 if np.isfinite(self.s0) else None, "s1": self.s1 if np.isfinite(self.s1) else None,
                "ramp": self.ramp, "road_half_width": self.road}


def _draw_earthworks(recipe: "SceneRecipe", rng: np.random.Generator, ext: float) -> tuple:
    """The recipe's embankments then cuttings (:class:`_Earthwork`), a fixed number of draws
    each: centre point within 0.6 of the half extent and direction uniform; height, crest and
    side run uniform in the recipe's ranges; bend wavelength 150-600 m with an amplitude of
    up to 5 % of it (gently curved); half of them cross the whole scene, the others are
    0.6-2 half extents long with end ramps 1-6 times the side run long (dam ends to road
    approaches); half carry a road (asphalt) or track (gravel) 4-7 m wide on a crest of 4 m
    or more, narrowed to leave 0.3 m of crest on each side."""
    out = []
    for i in range(recipe.embankments + recipe.cuttings):
        line = _Line(rng.uniform(-0.6, 0.6, 2) * ext, _unit(rng.uniform(0, np.pi)))
        height, crest, side = (rng.uniform(*recipe.earthwork_height), rng.uniform(*recipe.earthwork_crest),
                               rng.uniform(*recipe.earthwork_side))
        wavelength = rng.uniform(150.0, 600.0)
        amp, phase = rng.uniform(0.0, 0.05) * wavelength, rng.uniform(0, 2 * np.pi)
        finite, half, mid = rng.uniform() < 0.5, rng.uniform(0.3, 1.0) * ext, rng.uniform(-0.3, 0.3) * ext
        ramp = side * height * rng.uniform(1.0, 6.0)
        with_road, road, track = rng.uniform() < 0.5, rng.uniform(2.0, 3.5), rng.uniform() < 0.4
        s0, s1 = (mid - half, mid + half) if finite else (-np.inf, np.inf)
        road = min(road, crest / 2 - 0.3) if with_road and crest >= 4.0 else 0.0
        out.append(_Earthwork(line, 1.0 if i < recipe.embankments else -1.0, float(height), float(crest), float(side),
                              float(amp), float(wavelength), float(phase), float(s0), float(s1), float(ramp),
                              float(road), int(M["gravel"] if track else M["asphalt"])))
    return tuple(out)


def _check_earthworks(recipe: "SceneRecipe") -> None:
    """Refuse earthwork ranges that give no shape: counts below 0, heights and side runs
    that are not positive, crests below 0, a range whose low end exceeds its high end, ends
    that are not finite."""
    if recipe.embankments < 0 or recipe.cuttings < 0:
        field = "embankments" if recipe.embankments < 0 else "cuttings"
        raise InvalidInputError(f"{field} must be 0 or more", field=field)
    for field, zero_ok in (("earthwork_height", False), ("earthwork_crest", True), ("earthwork_side", False)):
        lo, hi = (float(v) for v in getattr(recipe, field))
        if not (np.isfinite(lo) and np.isfinite(hi)) or not (lo >= 0.0 if zero_ok else lo > 0.0) or hi < lo:
            what = "0 or more" if zero_ok else "positive"
            raise InvalidInputError(f"{field} [{lo}, {hi}] must be {what}, low end first", field=field)


def _unit(a):
    return np.array([np.cos(a), np.sin(a)])


# Recipe fields added after the first release. At their default values they are left out of
# the recipe's digest, so that a (recipe, seed) pair keeps building the same scene when new
# options appear; only a recipe that uses them gets a different random stream.
_LATER_FIELDS = frozenset({
    "building_length", "building_width", "large_buildings", "large_size", "large_height",
    "houses", "house_size", "house_height", "embankments", "cuttings", "earthwork_height", "earthwork_crest",
    "earthwork_side",
})


def _recipe_key(recipe: SceneRecipe) -> str:
    """The recipe's dataclass repr without later fields that are at their defaults."""
    parts = []
    for f in dataclasses.fields(recipe):
        if not f.repr:
            continue
        value = getattr(recipe, f.name)
        if f.name in _LATER_FIELDS and value == f.default:
            continue
        parts.append(f"{f.name}={value!r}")
    return f"{type(recipe).__qualname__}({', '.join(parts)})"


def _seed_for(recipe: SceneRecipe, seed: int) -> np.random.Generator:
    digest = hashlib.sha256(_recipe_key(recipe).encode()).digest()
    return np.random.default_rng([int(seed), int.from_bytes(digest[:8], "little")])


class _Layout:
    """Terrain function and the free-space bookkeeping for object placement."""

    def __init__(self, recipe: SceneRecipe, rng: np.random.Generator):
        t = recipe.terrain
        self.r = recipe
        self.t = t
        self.hx, self.hy = recipe.extent[0] / 2, recipe.extent[1] / 2
        ext = min(self.hx, self.hy)
        a_road = rng.uniform(0, np.pi)
        self.road = _Line(rng.uniform(-0.15, 0.15, 2) * ext, _unit(a_road))
        self.stream = _Line(self.road.p + rng.uniform(-0.3, 0.3) * ext * _unit(a_road), _unit(a_road + np.pi / 2 + rng.uniform(-0.4, 0.4)))
        self.stream_width = 7.0
        self.levee_offset = 16.0
        self.ridge = _Line(rng.uniform(-0.5, 0.5, 2) * ext, _unit(rng.uniform(0, np.pi)))
        self.breakline = _Line(rng.uniform(-0.5, 0.5, 2) * ext, _unit(rng.uniform(0, np.pi)))
        self.power = _Line(np.zeros(2), _unit(rng.uniform(0, np.pi)))
        self.power = _Line(self.power.point(0.0, rng.choice([-1, 1]) * 0.62 * ext), self.power.d)
        self.slope = t.slope_percent / 100.0 * _unit(rng.uniform(0, 2 * np.pi))
        self.pond_c = None
        self.pond_r = 0.0
        self.pond_level = 0.0
        self._wl = None
        # smooth relief and roughness as sums of random plane waves (deterministic, vectorised)
        k = 24
        self.waves_relief = (rng.uniform(0.004, 0.015, k), rng.uniform(0, 2 * np.pi, k), rng.uniform(0, 2 * np.pi, k))
        self.waves_rough = (rng.uniform(0.08, 0.6, k), rng.uniform(0, 2 * np.pi, k), rng.uniform(0, 2 * np.pi, k))
        self._occ = np.zeros((64, 3))  # (x, y, radius) of occupied discs
        self._n_occ = 0
        # drawn last, and only when asked for, so that recipes without them keep their stream
        self.earthworks = _draw_earthworks(recipe, rng, ext) if recipe.embankments + recipe.cuttings else ()

    @staticmethod
    def _waves(x, y, waves, amp):
        freq, ang, ph = waves
        z = np.zeros_like(x)
        for f, a, p in zip(freq, ang, ph):
            z += np.sin(2 * np.pi * f * (x * np.cos(a) + y * np.sin(a)) + p) / np.sqrt(f / freq.min())
        return amp * z / np.sqrt(len(freq))

    def height(self, x, y, with_water_cuts: bool = True) -> np.ndarray:
        """Terrain height (m, local datum = base_height) at local (x, y)."""
        t = self.t
        x = np.asarray(x, float)
        y = np.asarray(y, float)
        z = t.base_height + self.slope[0] * x + self.slope[1] * y
        if t.relief:
            z = z + self._waves(x, y, self.waves_relief, t.relief)
        if t.roughness:
            z = z + self._waves(x, y, self.waves_rough, t.roughness)
        if t.ridge_height:
            z = z + t.ridge_height * np.exp(-0.5 * (self.ridge.signed(x, y) / t.ridge_width) ** 2)
        if t.breakline_slope_percent:
            z = z + t.breakline_slope_percent / 100.0 * np.maximum(self.breakline.signed(x, y), 0.0)
        if self.r.road and t.ditch_depth:
            d = np.abs(self.road.signed(x, y) - 7.5)
            z = z - t.ditch_depth * np.clip(1 - d / (t.ditch_width / 2), 0, None)
        if self.earthworks:
            z = z + self.earthwork_relief(x, y)
        if self.r.stream and with_water_cuts:
            # carve the channel below the (level, downhill-only) water surface; 45 degree banks
            d = np.abs(self.stream.signed(x, y))
            hw = self.stream_width / 2
            lvl = self.stream_level(self.stream.along(x, y))
            z = np.minimum(z, lvl + np.where(d <= hw, -1.0 + 0.8 * d / hw, -0.2 + (d - hw)))
            if t.embankment_height:
                run = t.embankment_height / np.tan(np.radians(t.embankment_slope_deg))
                de = np.abs(self.stream.signed(x, y) - self.levee_offset)
                z = z + t.embankment_height * np.clip((2.0 + run - de) / run, 0, 1)
        if self.pond_c is not None and with_water_cuts:
            d = np.hypot(x - self.pond_c[0], y - self.pond_c[1])
            r = self.pond_r
            z = np.minimum(z, self.pond_level + np.where(d <= r, -1.5 + 1.3 * d / r, -0.2 + (d - r)))
        return z

    def earthwork_relief(self, x, y) -> np.ndarray:
        """Height (m) the earthworks add at (x, y): the highest embankment there less the deepest
        cutting (crossing embankments meet at the higher crest)."""
        up = np.zeros(np.shape(x))
        down = np.zeros(np.shape(x))
        for e in self.earthworks:
            if e.sign > 0:
                up = np.maximum(up, e.rise(x, y))
            else:
                down = np.maximum(down, e.rise(x, y))
        return up - down

    def _stream_profile(self) -> tuple[np.ndarray, np.ndarray]:
        """Water level along the stream: the centreline ground 0.6 m down, never rising downstream."""
        if self._wl is None:
            s = np.arange(-2.0 * (self.hx + self.hy), 2.0 * (self.hx + self.hy) + 1.0, 1.0)
            h0 = self.height(*self.stream.point(s).T, with_water_cuts=False) - 0.6
            level = np.minimum.accumulate(h0) if h0[-1] < h0[0] else np.minimum.accumulate(h0[::-1])[::-1]
            self._wl = (s, level)
        return self._wl

    def stream_level(self, s) -> np.ndarray:
        """Water surface height (m) at along-stream positions ``s``."""
        grid, level = self._stream_profile()
        return np.interp(s, grid, level)

    def free(self, x: float, y: float, radius: float) -> bool:
        """Whether a disc is inside the scene and clear of roads, water, lines and objects."""
        m = radius + 2.0
        if abs(x) > self.hx - m or abs(y) > self.hy - m:
            return False
        r = self.r
        if r.road and abs(self.road.signed(x, y)) < radius + 10.0:
            return False
        if r.stream and (abs(self.stream.signed(x, y)) < radius + self.stream_width / 2 + 3
                         or abs(self.stream.signed(x, y) - self.levee_offset) < radius + 6.0):
            return False
        if r.powerline and abs(self.power.signed(x, y)) < radius + 6.0:
            return False
        if self.pond_c is not None and np.hypot(x - self.pond_c[0], y - self.pond_c[1]) < radius + self.pond_r + 3:
            return False
        if any(e.covers(x, y, radius + 2.0) for e in self.earthworks):
            return False
        o = self._occ[: self._n_occ]
        return not bool(np.any(np.hypot(o[:, 0] - x, o[:, 1] - y) < radius + o[:, 2] + 1.5))

    def occupy(self, x: float, y: float, radius: float) -> None:
        if self._n_occ == len(self._occ):
            self._occ = np.vstack([self._occ, np.zeros_like(self._occ)])
        self._occ[self._n_occ] = (x, y, radius)
        self._n_occ += 1

    def find_spot(self, rng, radius: float, tries: int = 200, center=None, spread=None):
        for _ in range(tries):
            if center is None:
                x, y = rng.uniform(-self.hx, self.hx), rng.uniform(-self.hy, self.hy)
            else:
                x, y = center + rng.normal(0, spread, 2)
            if self.free(x, y, radius):
                self.occupy(x, y, radius)
                return float(x), float(y)
        return None


# -- objects -----------------------------------------------------------------------------------
def _terrain(b: _Builder, L: _Layout, rng):
    t = L.t
    nx = int(np.ceil(2 * L.hx / t.resolution)) + 1
    ny = int(np.ceil(2 * L.hy / t.resolution)) + 1
    xs = np.linspace(-L.hx, L.hx, nx)
    ys = np.linspace(-L.hy, L.hy, ny)
    X, Y = np.meshgrid(xs, ys)
    Z = L.height(X, Y)
    f = S.grid(nx, ny)
    v = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
    cen = v[f].mean(axis=1)
    cls = np.full(len(f), C.GROUND, np.uint8)
    # ground materials: grass with patches of soil and gravel (smooth noise, deterministic)
    noise = L._waves(cen[:, 0], cen[:, 1], L.waves_relief, 1.0)
    mat = np.where(noise > 0.5, M["soil"], M["grass"]).astype(np.uint16)
    if t.relief > 20:
        slope = np.abs(np.gradient(Z, t.resolution)[0]).ravel()[f[:, 0]]
        mat = np.where(slope > 0.6, M["rock"], mat).astype(np.uint16)
    if L.r.road:
        on_road = np.abs(L.road.signed(cen[:, 0], cen[:, 1])) < 3.5
        cls[on_road] = C.ROAD_SURFACE
        mat[on_road] = M["asphalt"]
        shoulder = (np.abs(L.road.signed(cen[:, 0], cen[:, 1])) >= 3.5) & (np.abs(L.road.signed(cen[:, 0], cen[:, 1])) < 4.5)
        mat[shoulder] = M["gravel"]
    for e in L.earthworks:  # roads and tracks along the crests (cutting floors)
        if e.road:
            d, s = e.offset(cen[:, 0], cen[:, 1])
            on = (d < e.road) & (s > e.s0) & (s < e.s1)
            cls[on] = C.ROAD_SURFACE
            mat[on] = e.road_mat
    b.add((v, f), cls, mat, 0)
    return Z


def _water(b: _Builder, L: _Layout, rng):
    r = L.r
    if r.stream:
        along = L.stream.along(np.array([-L.hx, L.hx, L.hx, -L.hx]), np.array([-L.hy, -L.hy, L.hy, L.hy]))
        s = np.linspace(along.min() - 5, along.max() + 5, 60)
        left = L.stream.point(s, L.stream_width / 2 + 0.2)
        right = L.stream.point(s, -L.stream_width / 2 - 0.2)
        zc = L.stream_level(s)
        v = np.vstack([np.column_stack([right, zc]), np.column_stack([left, zc])])
        v[:, 0] = np.clip(v[:, 0], -L.hx, L.hx)
        v[:, 1] = np.clip(v[:, 1], -L.hy, L.hy)
        f = S.grid(len(s), 2)
        b.add((v, f), C.WATER, M["water"], b.new_object("stream"))
    if r.pond:
        L.pond_r = 14.0
        for _ in range(200):
            c = rng.uniform(-0.6, 0.6, 2) * np.array([L.hx, L.hy])
            if L.free(c[0], c[1], L.pond_r + 4):
                L.pond_c = c
                break
        if L.pond_c is not None:
            a = np.linspace(0, 2 * np.pi, 72, endpoint=False)
            rim = L.pond_c + (L.pond_r + 2.0) * np.column_stack([np.cos(a), np.sin(a)])
            L.pond_level = float(L.height(rim[:, 0], rim[:, 1], with_water_cuts=False).min()) - 0.3
            z = L.pond_level
            v, f = S.disc(L.pond_r + 0.2, z, sides=48)
            v[:, :2] += L.pond_c
            b.add((v, f), C.WATER, M["water"], b.new_object("pond"))


def _bridge(b: _Builder, L: _Layout):
    if not (L.r.road and L.r.stream):
        return
    # crossing point of road and stream
    A = np.column_stack([L.road.d, -L.stream.d])
    s, _ = np.linalg.solve(A, L.stream.p - L.road.p)
    c = L.road.point(s)
    if abs(c[0]) > L.hx - 20 or abs(c[1]) > L.hy - 20:
        return
    sin_cross = abs(L.road.d[0] * L.stream.d[1] - L.road.d[1] * L.stream.d[0])
    length = (L.stream_width + 8.0) / max(sin_cross, 0.3)
    zr = float(L.height(*(c + L.road.d * length / 2))), float(L.height(*(c - L.road.d * length / 2)))
    z_deck = max(zr) + 0.4
    oid = b.new_object("bridge")
    deck = S.box(length, 8.0, 0.6, bottom=True)
    v = S.place(deck[0], [c[0], c[1], z_deck - 0.6], L.road.angle)
    b.add((v, deck[1]), C.BRIDGE_DECK, M["concrete"], oid)
    for side in (-1, 1):
        rail = S.box(length, 0.3, 1.0)
        v = S.place(rail[0] + [0, side * 3.85, 0], [c[0], c[1], z_deck], L.road.angle)
        b.add((v, rail[1]), C.BRIDGE_DECK, M["steel"], oid)
        pier = S.box(1.0, 6.0, 3.0)
        p = c + side * L.road.d * (length / 2 - 2.0)
        zp = float(L.height(*p)) - 0.5
        b.add((S.place(pier[0] * [1, 1, (z_deck - 0.6 - zp) / 3.0], [p[0], p[1], zp], L.road.angle), pier[1]),
              C.BRIDGE_DECK, M["concrete"], oid)
    L.occupy(*(float(c[0]), float(c[1]), length / 2))


def _building(b: _Builder, L: _Layout, rng, x, y, lx, ly, yaw, kind: str, height=None):
    zg = float(L.height(np.array([x - lx / 2, x + lx / 2, x, x]), np.array([y, y, y - ly / 2, y + ly / 2])).min()) - 0.3
    h = rng.uniform(*(L.r.building_height if height is None else height)) + 0.3
    oid = b.new_object(f"building_{kind}")
    walls = rng.choice([M["brick"], M["plaster"], M["concrete"]])
    wv, wf = S.box(lx, ly, h)
    b.add((S.place(wv, [x, y, zg], yaw), wf[2:] if kind != "flat" else wf), C.BUILDING, walls, oid)
    over = rng.uniform(0.3, 0.8)
    rise = min(lx, ly) / 2 * np.tan(np.radians(rng.uniform(25, 45)))
    roof_mat = rng.choice([M["roof_tiles"], M["roof_metal"]])
    if kind == "gabled":
        if lx >= ly:
            rv, rf = S.gable_roof(lx, ly, rise, over)
            b.add((S.place(rv, [x, y, zg + h], yaw), rf), C.BUILDING, roof_mat, oid)
        else:
            rv, rf = S.gable_roof(ly, lx, rise, over)
            b.add((S.place(rv, [x, y, zg + h], yaw + np.pi / 2), rf), C.BUILDING, roof_mat, oid)
    elif kind == "hipped":
        if lx >= ly:
            rv, rf = S.hip_roof(lx, ly, rise, over)
            b.add((S.place(rv, [x, y, zg + h], yaw), rf), C.BUILDING, roof_mat, oid)
        else:
            rv, rf = S.hip_roof(ly, lx, rise, over)
            b.add((S.place(rv, [x, y, zg + h], yaw + np.pi / 2), rf), C.BUILDING, roof_mat, oid)
    else:  # flat roof with a parapet and a roof box (stairwell / HVAC)
        pv, pf = S.box(lx + 0.2, ly + 0.2, 0.8)
        b.add((S.place(pv, [x, y, zg + h], yaw), pf), C.BUILDING, M["concrete"], oid)
        hv, hf = S.box(min(3.0, lx / 3), min(3.0, ly / 3), 2.2)
        b.add((S.place(hv + [lx / 5, 0, 0], [x, y, zg + h], yaw), hf), C.BUILDING, M["roof_metal"], oid)


def _large_block(b: _Builder, L: _Layout, rng, x, y, lx, ly, yaw):
    """A large flat-roofed block with a parapet and roof furniture (HVAC boxes, stairwells,
    a row of skylight ridges)."""
    corners = np.array([[-lx, -ly], [lx, -ly], [-lx, ly], [lx, ly], [0, 0]]) / 2 @ S.rot_z(yaw)[:2, :2].T
    zg = float(L.height(x + corners[:, 0], y + corners[:, 1]).min()) - 0.3
    h = rng.uniform(*L.r.large_height) + 0.3
    oid = b.new_object("building_large")
    wv, wf = S.box(lx, ly, h)
    b.add((S.place(wv, [x, y, zg], yaw), wf), C.BUILDING, rng.choice([M["concrete"], M["plaster"], M["brick"]]), oid)
    pv, pf = S.box(lx + 0.3, ly + 0.3, rng.uniform(0.3, 1.2))
    b.add((S.place(pv, [x, y, zg + h], yaw), pf), C.BUILDING, M["concrete"], oid)
    for _ in range(int(rng.integers(2, 9))):
        bx, by, bz = rng.uniform(1.5, 6.0), rng.uniform(1.5, 6.0), rng.uniform(0.8, 3.5)
        cx = rng.uniform(-lx / 2 + bx, lx / 2 - bx)
        cy = rng.uniform(-ly / 2 + by, ly / 2 - by)
        v, f = S.box(bx, by, bz)
        b.add((S.place(v + [cx, cy, 0], [x, y, zg + h], yaw), f), C.BUILDING, M["roof_metal"], oid)
    if rng.uniform() < 0.5:  # skylight ridges: small gables in a row
        n = int(rng.integers(3, 8))
        for cx in np.linspace(-lx / 3, lx / 3, n):
            v, f = S.gable_roof(ly * 0.5, 2.5, 1.0)
            b.add((S.place(v, [x + cx * np.cos(yaw), y + cx * np.sin(yaw), zg + h], yaw + np.pi / 2), f),
                  C.BUILDING, M["roof_metal"], oid)


def _house(b: _Builder, L: _Layout, rng, x, y, size, yaw):
    """A small house or shed and garden trees beside its walls (crowns over the roof)."""
    lx = size
    ly = size * rng.uniform(0.6, 1.0)
    _building(b, L, rng, x, y, lx, ly, yaw, str(rng.choice(["gabled", "hipped", "flat"])), height=L.r.house_height)
    for _ in range(int(rng.integers(1, 4))):
        a = rng.uniform(0, 2 * np.pi)
        d = 0.5 * np.hypot(lx, ly) + rng.uniform(0.5, 3.0)
        tx, ty = x + d * np.cos(a), y + d * np.sin(a)
        if abs(tx) < L.hx - 3 and abs(ty) < L.hy - 3:
            _tree(b, L, rng, tx, ty, bool(rng.uniform() < L.r.conifer_fraction))


def _courtyard(b: _Builder, L: _Layout, rng, x, y, size, yaw):
    zg = float(L.height(x, y)) - 1.0
    h = rng.uniform(*L.r.building_height) + 3.0
    w = rng.uniform(7.0, 10.0)
    oid = b.new_object("building_courtyard")
    for dx, dy, lx, ly in ((0, (size - w) / 2, size, w), (0, -(size - w) / 2, size, w),
                           ((size - w) / 2, 0, w, size - 2 * w), (-(size - w) / 2, 0, w, size - 2 * w)):
        v, f = S.box(lx, ly, h)
        b.add((S.place(v + [dx, dy, 0], [x, y, zg], yaw), f), C.BUILDING, M["plaster"], oid)


def _church(b: _Builder, L: _Layout, rng):
    spot = L.find_spot(rng, 24.0)
    if spot is None:
        return
    x, y = spot
    yaw = L.road.angle + rng.choice([0, np.pi / 2])
    zg = float(L.height(x, y)) - 0.5
    oid = b.new_object("heritage_church")
    stone = M["sandstone"]
    nave_l, nave_w, wall_h = 26.0, 12.0, 11.0
    v, f = S.box(nave_l, nave_w, wall_h)
    b.add((S.place(v, [x, y, zg], yaw), f[2:]), C.BUILDING, stone, oid)
    v, f = S.gable_roof(nave_l, nave_w, 6.0, 0.5)
    b.add((S.place(v, [x, y, zg + wall_h], yaw), f), C.BUILDING, M["roof_tiles"], oid)
    # apse: a half-octagon prism at the east end
    a = np.linspace(-np.pi / 2, np.pi / 2, 6)
    poly = np.column_stack([nave_l / 2 + 5.0 * np.cos(a), 5.0 * np.sin(a)])
    v, f = S.prism(poly, 0.0, wall_h - 2.0)
    b.add((S.place(v, [x, y, zg], yaw), f), C.BUILDING, stone, oid)
    # tower with a spire at the west end
    tv, tf = S.box(6.0, 6.0, 30.0)
    b.add((S.place(tv - [nave_l / 2 + 3.0, 0, 0], [x, y, zg], yaw), tf), C.BUILDING, stone, oid)
    sv, sf = S.pyramid(6.4, 6.4, 12.0)
    b.add((S.place(sv - [nave_l / 2 + 3.0, 0, -30.0], [x, y, zg], yaw), sf), C.BUILDING, M["roof_metal"], oid)
    # portico: six columns along the south side and a pediment roof on them
    col_h = 7.0
    for cx in np.linspace(-nave_l / 2 + 4, nave_l / 2 - 4, 6):
        cv, cf = S.tube(np.array([[cx, -nave_w / 2 - 3.0, 0.0], [cx, -nave_w / 2 - 3.0, col_h / 2], [cx, -nave_w / 2 - 3.0, col_h]]), 0.45, sides=10)
        b.add((S.place(cv, [x, y, zg], yaw), cf), C.BUILDING, stone, oid)
    ev, ef = S.box(nave_l - 4.0, 4.6, 0.8, bottom=True)
    b.add((S.place(ev + [0, -nave_w / 2 - 2.5, col_h], [x, y, zg], yaw), ef), C.BUILDING, stone, oid)
    L.occupy(*(x - np.cos(yaw) * (nave_l / 2 + 3), y - np.sin(yaw) * (nave_l / 2 + 3), 5.0))


def _tree(b: _Builder, L: _Layout, rng, x, y, conifer: bool):
    h = rng.uniform(9.0, 22.0) if not conifer else rng.uniform(12.0, 28.0)
    zg = float(L.height(x, y)) - 0.2
    oid = b.new_object("tree_conifer" if conifer else "tree_broadleaf")
    trunk_r = 0.012 * h + rng.uniform(0.05, 0.12)
    crown_base = h * (0.35 if not conifer else 0.25)
    tv, tf = S.tube(np.array([[0, 0, 0], [0, 0, h * 0.5], [0, 0, h * 0.85]]), trunk_r, sides=6)
    b.add((tv + [x, y, zg], tf), C.HIGH_VEGETATION, M["bark"], oid)
    crown_h = h - crown_base
    if conifer:
        rad = rng.uniform(0.18, 0.25) * crown_h
        n = int(3.2 * rad * rad * crown_h)
        u = rng.uniform(0, 1, n)
        zz = crown_h * (1 - np.sqrt(1 - u))  # more leaves low where the cone is wide
        rr = rad * (1 - zz / crown_h) * np.sqrt(rng.uniform(0, 1, n))
        mat = M["needles"]
    else:
        rad = rng.uniform(0.3, 0.45) * crown_h
        n = int(1.6 * rad * rad * crown_h)
        d = rng.normal(size=(n, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        rel = d * rng.uniform(0, 1, (n, 1)) ** (1 / 3)
        zz = crown_h / 2 * (1 + rel[:, 2])
        rr = rad * np.hypot(rel[:, 0], rel[:, 1])
        mat = M["leaves"]
    a = rng.uniform(0, 2 * np.pi, len(zz))
    centers = np.column_stack([x + rr * np.cos(a), y + rr * np.sin(a), zg + crown_base + zz])
    b.add(S.leaf_cloud(rng, centers, 0.45), C.HIGH_VEGETATION, mat, oid)


def _bush(b: _Builder, L: _Layout, rng, x, y):
    rad = rng.uniform(0.7, 1.6)
    zg = float(L.height(x, y))
    oid = b.new_object("bush")
    n = int(40 * rad ** 3)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    c = d * rng.uniform(0, 1, (n, 1)) ** (1 / 3) * [rad, rad, rad * 0.8] + [x, y, zg + rad * 0.8]
    b.add(S.leaf_cloud(rng, c, 0.3), C.MEDIUM_VEGETATION, M["shrub"], oid)


def _grass(b: _Builder, L: _Layout, rng, x, y):
    rad = rng.uniform(2.0, 5.0)
    n = int(6 * rad * rad)
    a = rng.uniform(0, 2 * np.pi, n)
    r = rad * np.sqrt(rng.uniform(0, 1, n))
    px, py = x + r * np.cos(a), y + r * np.sin(a)
    c = np.column_stack([px, py, L.height(px, py) + rng.uniform(0.1, 0.5, n)])
    b.add(S.leaf_cloud(rng, c, 0.25), C.LOW_VEGETATION, M["grass_blades"], b.new_object("low_vegetation"))


_CAR_COLOURS = np.array([[150, 30, 30], [30, 50, 140], [200, 200, 200], [30, 30, 30], [90, 90, 95], [210, 180, 40]], np.uint8)


def _cars(b: _Builder, L: _Layout, rng):
    s_all = np.sort(rng.uniform(-0.9, 0.9, L.r.cars)) * min(L.hx, L.hy)
    last = -1e9
    for s in s_all:
        if s - last < 8.0:
            continue
        last = s
        lane = rng.choice([-1.6, 1.6])
        p = L.road.point(s, lane)
        if abs(p[0]) > L.hx - 5 or abs(p[1]) > L.hy - 5:
            continue
        if L.r.stream and abs(L.stream.signed(*p)) < 15:
            continue
        z = float(L.height(*p))
        yaw = L.road.angle + (np.pi if lane < 0 else 0.0)
        oid = b.new_object("car")
        col = _CAR_COLOURS[rng.integers(len(_CAR_COLOURS))]
        v, f = S.box(4.4, 1.8, 0.8)
        b.add((S.place(v + [0, 0, 0.3], [p[0], p[1], z], yaw), f), C.UNCLASSIFIED, M["car_paint"], oid, rgb=col)
        v, f = S.box(2.4, 1.6, 0.6)
        b.add((S.place(v + [-0.3, 0, 1.1], [p[0], p[1], z], yaw), f), C.UNCLASSIFIED, M["car_paint"], oid, rgb=col)


def _powerline(b: _Builder, L: _Layout, rng):
    s_all = np.arange(-2 * (L.hx + L.hy), 2 * (L.hx + L.hy), 1.0)
    p_all = L.power.point(s_all)
    inside = (np.abs(p_all[:, 0]) < L.hx - 8) & (np.abs(p_all[:, 1]) < L.hy - 8)
    if inside.sum() < 40:
        return
    s_lo, s_hi = s_all[inside].min(), s_all[inside].max()
    n_pyl = max(2, int(np.ceil((s_hi - s_lo) / 90.0)) + 1)  # spans of at most 90 m
    pts = L.power.point(np.linspace(s_lo, s_hi, n_pyl))
    H = 24.0
    yaw = L.power.angle
    zs = L.height(pts[:, 0], pts[:, 1]) - 0.3
    arm_offsets = np.array([-4.5, 0.0, 4.5])
    for p, z in zip(pts, zs):
        oid = b.new_object("pylon")
        v, f = S.frustum(4.0, 4.0, 1.0, 1.0, H)
        b.add((S.place(v, [p[0], p[1], z], yaw), f), C.TRANSMISSION_TOWER, M["steel"], oid)
        v, f = S.box(0.6, 11.0, 0.6)
        b.add((S.place(v, [p[0], p[1], z + H - 2.5], yaw), f), C.TRANSMISSION_TOWER, M["steel"], oid)
        L.occupy(*(float(p[0]), float(p[1]), 4.0))
    n = np.array([-L.power.d[1], L.power.d[0]])
    oid = b.new_object("power_line")
    for i in range(len(pts) - 1):
        for off in arm_offsets:
            a = np.r_[pts[i] + off * n, zs[i] + H - 3.2]
            c = np.r_[pts[i + 1] + off * n, zs[i + 1] + H - 3.2]
            u = np.linspace(0, 1, 31)[:, None]
            path = a + u * (c - a)
            path[:, 2] -= 3.0 * 4 * u[:, 0] * (1 - u[:, 0])  # parabolic sag (catenary to 2nd order), 3 m
            b.add(S.tube(path, 0.025, sides=6), C.WIRE_CONDUCTOR, M["steel"], oid)


def _place_buildings(b: "_Builder", L: "_Layout", rng: np.random.Generator, recipe: SceneRecipe) -> None:
    """Place the recipe's courtyards, large blocks, houses and buildings, in that order.

    Each object asks the layout for a free spot of its footprint radius (m) and is skipped
    when none is left, so a crowded recipe yields fewer objects instead of overlaps. The order
    of the random draws is part of the scene's identity for a seed: it must not change.
    """
    kinds = ["flat", "gabled", "hipped"]
    for i in range(recipe.courtyards):
        size = rng.uniform(28.0, 40.0)
        spot = L.find_spot(rng, size * 0.72)
        if spot:
            _courtyard(b, L, rng, *spot, size, L.road.angle)
    for i in range(recipe.large_buildings):
        lx, ly = rng.uniform(*recipe.large_size), rng.uniform(*recipe.large_size)
        spot = L.find_spot(rng, 0.5 * np.hypot(lx, ly) + 1.0)
        if spot:
            _large_block(b, L, rng, *spot, lx, ly, L.road.angle + rng.uniform(-0.3, 0.3))
    for i in range(recipe.houses):
        size = rng.uniform(*recipe.house_size)
        spot = L.find_spot(rng, 0.7 * size + 4.0)
        if spot:
            _house(b, L, rng, *spot, size, rng.uniform(0, np.pi))
    for i in range(recipe.buildings):
        lx, ly = rng.uniform(*recipe.building_length), rng.uniform(*recipe.building_width)
        spot = L.find_spot(rng, 0.5 * np.hypot(lx, ly) + 1.0)
        if spot:
            _building(b, L, rng, *spot, lx, ly, L.road.angle + rng.choice([0.0, np.pi / 2]), kinds[i % 3])


def _place_vegetation(b: "_Builder", L: "_Layout", rng: np.random.Generator, recipe: SceneRecipe) -> None:
    """Place the trees (a ``forest_fraction`` share clustered in stands of ~40 trees within
    18 m of a stand centre, the rest scattered), then the bushes and grass patches, each on a
    free spot of the layout (skipped when none is left)."""
    n_forest = int(round(recipe.trees * recipe.forest_fraction))
    stands = [L.find_spot(rng, 3.0) for _ in range(max(1, n_forest // 40))] if n_forest else []
    stands = [s for s in stands if s]
    for i in range(recipe.trees):
        if i < n_forest and stands:
            c = np.array(stands[i % len(stands)])
            spot = L.find_spot(rng, 2.0, center=c, spread=18.0)
        else:
            spot = L.find_spot(rng, 2.0)
        if spot:
            _tree(b, L, rng, *spot, bool(rng.uniform() < recipe.conifer_fraction))
    for _ in range(recipe.bushes):
        spot = L.find_spot(rng, 1.5)
        if spot:
            _bush(b, L, rng, *spot)
    for _ in range(recipe.grass_patches):
        spot = L.find_spot(rng, 3.0)
        if spot:
            _grass(b, L, rng, *spot)


def _scene_meta(recipe: SceneRecipe, seed: int, b: "_Builder", L: "_Layout") -> dict:
    """The scene's ``meta``: recipe name, seed, objects per kind, extent (m) and, when present,
    the road and stream axes (point ``p`` and direction ``d`` in local metres, half width m)."""
    meta = {"recipe": recipe.name, "seed": int(seed), "objects": {str(k): v for k, v in b.kinds.items()},
            "extent": list(recipe.extent)}
    if recipe.road:
        meta["road"] = {"p": L.road.p.tolist(), "d": L.road.d.tolist(), "half_width": 3.5}
    if recipe.stream:
        meta["stream"] = {"p": L.stream.p.tolist(), "d": L.stream.d.tolist(), "half_width": L.stream_width / 2}
    if L.earthworks:
        meta["earthworks"] = [e.to_meta() for e in L.earthworks]
    return meta


def build_scene(recipe: SceneRecipe | str | Path = "mixed", seed: int = 0) -> Scene:
    """Build the scene of a recipe and seed, deterministically.

    Parameters
    ----------
    recipe : SceneRecipe, or a TOML path / shipped recipe name
    seed : int
        Different seeds place different objects and terrain features.

    Returns
    -------
    Scene

    Examples
    --------
    >>> r = SceneRecipe(extent=(60.0, 60.0), buildings=1, courtyards=0, heritage=False, trees=2,
    ...                 bushes=1, grass_patches=1, cars=1, powerline=False, pond=False)
    >>> s = build_scene(r, seed=1)
    >>> bool(np.array_equal(s.faces, build_scene(r, seed=1).faces)), s.classification.dtype
    (True, dtype('uint8'))
    """
    if not isinstance(recipe, SceneRecipe):
        recipe = load_recipe(recipe)
    if recipe.extent[0] <= 0 or recipe.extent[1] <= 0:
        raise InvalidInputError(f"extent {recipe.extent} must be positive", field="extent")
    _check_earthworks(recipe)
    rng = _seed_for(recipe, seed)
    L = _Layout(recipe, rng)
    b = _Builder()
    _water(b, L, rng)  # places the pond first so the terrain gets its basin
    _terrain(b, L, rng)
    _bridge(b, L)
    if recipe.heritage:
        _church(b, L, rng)
    _place_buildings(b, L, rng, recipe)
    _place_vegetation(b, L, rng, recipe)
    if recipe.road and recipe.cars:
        _cars(b, L, rng)
    if recipe.powerline:
        _powerline(b, L, rng)
    v, f, cls, mat, obj, rgb = b.finish()
    origin = np.array([recipe.origin[0], recipe.origin[1], 0.0])
    meta = _scene_meta(recipe, seed, b, L)
    log.info("scene %s seed %d: %d triangles, %d objects", recipe.name, seed, len(f), len(b.kinds))
    return Scene(v, f, cls, mat, obj, rgb, origin, recipe.crs, MATERIALS, meta)


def plane_scene(size: float = 200.0, height: float = 100.0, material: str = "concrete",
                origin=(500000.0, 5000000.0), cls: int = C.GROUND) -> Scene:
    """A flat horizontal square (``size`` m, at ``height`` m) for geometry tests and planning checks."""
    v, f = S.flat_plate(size, size, height)
    m = len(f)
    return Scene(v, f, np.full(m, cls, np.uint8), np.full(m, M[material], np.uint16), np.zeros(m, np.uint32),
                 np.tile(np.array(MATERIALS[M[material]].albedo, np.uint8), (m, 1)),
                 np.array([origin[0], origin[1], 0.0]), meta={"recipe": "plane"})


def box_room_scene(lx: float = 12.0, ly: float = 8.0, lz: float = 3.5, origin=(500000.0, 5000000.0)) -> Scene:
    """A closed box room (floor at z = 0) centred on the local origin, normals facing inward."""
    v, f = S.box(lx, ly, lz, bottom=True)
    f = f[:, ::-1]
    m = len(f)
    cls = np.where(v[f][:, :, 2].max(1) == 0, C.GROUND, C.BUILDING).astype(np.uint8)
    return Scene(v, f, cls, np.full(m, M["plaster"], np.uint16), np.ones(m, np.uint32),
                 np.tile(np.array(MATERIALS[M["plaster"]].albedo, np.uint8), (m, 1)),
                 np.array([origin[0], origin[1], 0.0]), meta={"recipe": "box_room"})


def merge_scenes(a: Scene, b: Scene) -> Scene:
    """Both scenes in ``a``'s local frame (object ids of ``b`` shifted past ``a``'s)."""
    shift = b.origin - a.origin
    off = np.uint32(a.object_id.max() + 1 if a.n_faces else 0)
    return Scene(np.vstack([a.vertices, b.vertices + shift]), np.vstack([a.faces, b.faces + len(a.vertices)]),
                 np.concatenate([a.classification, b.classification]), np.concatenate([a.material, b.material]),
                 np.concatenate([a.object_id, b.object_id + off]), np.vstack([a.face_rgb, b.face_rgb]),
                 a.origin, a.crs, a.materials, dict(a.meta))


def save_scene(scene: Scene, path, overwrite: bool = False) -> Path:
    """Write a scene losslessly as ``.npz`` (arrays, origin, CRS, meta and material table as JSON).

    The photo renderer and tests read it back with :func:`load_scene`.
    """
    import json

    from workstation.io import atomic_path

    p = Path(path)
    if p.suffix != ".npz":
        raise InvalidInputError("scene files are .npz", "give a path ending in .npz", path=p)
    meta = json.dumps({"crs": scene.crs, "meta": scene.meta, "materials": [dataclasses.asdict(m) for m in scene.materials]})
    with atomic_path(p, overwrite=overwrite) as tmp:
        with open(tmp, "wb") as fh:
            np.savez_compressed(fh, vertices=scene.vertices, faces=scene.faces, classification=scene.classification,
                                material=scene.material, object_id=scene.object_id, face_rgb=scene.face_rgb,
                                origin=scene.origin, meta=np.array(meta))
    return p


def load_scene(path) -> Scene:
    """Read a scene written by :func:`save_scene`."""
    import json

    p = Path(path)
    if not p.exists():
        raise InvalidInputError("scene file not found", path=p)
    with np.load(p, allow_pickle=False) as z:
        info = json.loads(str(z["meta"]))
        mats = tuple(Material(**{**m, "albedo": tuple(m["albedo"])}) for m in info["materials"])
        return Scene(z["vertices"], z["faces"], z["classification"], z["material"], z["object_id"], z["face_rgb"],
                     z["origin"], info["crs"], mats, info["meta"])


def scene_summary(scene: Scene) -> dict[str, Any]:
    """Triangle counts per class and object counts per kind (for logs and --json)."""
    cls, cnt = np.unique(scene.classification, return_counts=True)
    kinds: dict[str, int] = {}
    for k in scene.meta.get("objects", {}).values():
        kinds[k] = kinds.get(k, 0) + 1
    return {"triangles": scene.n_faces, "triangles_per_class": {int(c): int(n) for c, n in zip(cls, cnt)},
            "objects": kinds}
