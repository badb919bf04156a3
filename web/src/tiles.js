// Meshes in the `ws publish` viewer: the 3D Tiles 1.1 tilesets that `ws publish --3d-tiles`
// writes for meshes (workstation/publish/tiles3d.py), drawn with three.js's GLTFLoader.
//
// A tileset's coordinates (those of its bounding boxes, z up) are placed in the viewer's frame
// (CRS units minus site.json's origin) by the 4x4 `matrix` of its site.json entry, which
// replaces the root tile's ENU -> ECEF `transform` (the viewer has no geodesy; site.py fits
// that matrix). Transforms of lower tiles are applied as the specification says, and each
// tile's glTF content is turned from glTF's y-up to the tileset's z-up (3D Tiles 1.1, "glTF
// transforms": a +90° rotation about x).
//
// Refinement follows the specification's screen-space error: a tile whose geometricError
// (metres, scaled into viewer units) covers more than MAX_SSE pixels at the distance of its
// bounding box is replaced by its children (REPLACE; the parent stays drawn until every child
// in view is loaded) or completed by them (ADD). Tiles outside the view frustum are neither
// drawn nor fetched; a tile once loaded is kept.

import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

export const MAX_SSE = 16; // pixels: CesiumJS's default maximumScreenSpaceError
const Y_UP_TO_Z_UP = new THREE.Matrix4().makeRotationX(Math.PI / 2);
const loader = new GLTFLoader();

// The world-space box around a 3D Tiles bounding volume (`box`: centre and three half axes;
// `sphere`: centre and radius) in the frame `matrix` maps it to.
function volumeBox(bv, matrix, where) {
  if (bv.box) {
    const b = bv.box, c = new THREE.Vector3(b[0], b[1], b[2]);
    const axes = [0, 1, 2].map((i) => new THREE.Vector3(b[3 + 3 * i], b[4 + 3 * i], b[5 + 3 * i]));
    const corners = [];
    for (let i = 0; i < 8; i++) {
      const p = c.clone();
      axes.forEach((a, k) => p.addScaledVector(a, (i >> k) & 1 ? 1 : -1));
      corners.push(p.applyMatrix4(matrix));
    }
    return new THREE.Box3().setFromPoints(corners);
  }
  if (bv.sphere) {
    const [x, y, z, r] = bv.sphere, c = new THREE.Vector3(x, y, z).applyMatrix4(matrix);
    return new THREE.Box3().setFromCenterAndSize(c, new THREE.Vector3().setScalar(2 * r * matrix.getMaxScaleOnAxis()));
  }
  throw new Error(`${where}: only box and sphere bounding volumes are supported (a region needs geodesy)`);
}

// The placement of a tileset in the viewer's frame: site.json's `matrix` (column-major), or
// for a tileset without a CRS (extras.ws.frame "local": CRS units relative to extras.ws.origin)
// the shift from its origin to the site's.
function placement(entry, doc, origin, where) {
  if (Array.isArray(entry.matrix) && entry.matrix.length === 16) return new THREE.Matrix4().fromArray(entry.matrix);
  const ws = doc.extras && doc.extras.ws;
  if (ws && ws.frame === 'local' && Array.isArray(ws.origin)) {
    const [x, y, z] = ws.origin;
    return new THREE.Matrix4().makeTranslation(x - origin.x, y - origin.y, z - origin.z);
  }
  throw new Error(`${where}: no placement (site.json tileset entry without 'matrix')`);
}

export class MeshTileset {
  // entry: the site.json tileset entry; doc: its tileset.json; url: absolute URL of tileset.json;
  // origin: THREE.Vector3 of site.json's origin.
  constructor(entry, doc, url, origin) {
    if (!doc.root) throw new Error(`${url}: tileset.json has no root tile`);
    this.entry = entry;
    this.url = url;
    this.place = placement(entry, doc, origin, url);
    this.group = new THREE.Group();
    this.group.name = entry.name;
    this.group.matrixAutoUpdate = false;
    this.group.matrix.copy(this.place);
    this.tiles = [];
    this.root = this.prepare(doc.root, new THREE.Matrix4(), 'REPLACE', true);
  }

  // One tile: its transform relative to the tileset (the root's own transform is replaced by
  // the placement), its box and geometric error in viewer units, and its children.
  prepare(json, parent, parentRefine, isRoot) {
    const matrix = parent.clone();
    if (json.transform && !isRoot) matrix.multiply(new THREE.Matrix4().fromArray(json.transform));
    const world = this.place.clone().multiply(matrix);
    const content = json.content && (json.content.uri || json.content.url);
    const tile = {
      matrix, uri: content || null, object: null, loading: false,
      box: volumeBox(json.boundingVolume || {}, world, this.url),
      error: Number(json.geometricError || 0) * world.getMaxScaleOnAxis(),
      refine: String(json.refine || parentRefine).toUpperCase(),
    };
    this.tiles.push(tile);
    tile.children = (json.children || []).map((c) => this.prepare(c, matrix, tile.refine, false));
    return tile;
  }

  // The tiles to draw for this view; tiles to fetch are appended to `wanted`.
  visit(tile, frustum, eye, proj, wanted) {
    if (!frustum.intersectsBox(tile.box)) return [];
    const dist = Math.max(tile.box.distanceToPoint(eye), 1e-6);
    const refine = tile.children.length > 0 && (tile.error * proj) / dist > MAX_SSE;
    if (!refine) {
      if (!tile.uri) return [];
      wanted.push(tile);
      return [tile];
    }
    const sub = tile.children.flatMap((c) => this.visit(c, frustum, eye, proj, wanted));
    if (tile.refine === 'ADD') {
      if (!tile.uri) return sub;
      wanted.push(tile);
      return [tile, ...sub];
    }
    if (!tile.uri || sub.every((t) => t.object)) return sub;
    wanted.push(tile); // REPLACE: keep the parent until its children in view are loaded
    return [tile];
  }

  // Show the tiles this view needs (frustum, eye position, pixels per unit at distance 1) and
  // the list of tiles still to fetch.
  select(frustum, eye, proj) {
    const wanted = [];
    const draw = this.group.visible ? new Set(this.visit(this.root, frustum, eye, proj, wanted)) : new Set();
    for (const t of this.tiles) if (t.object) t.object.visible = draw.has(t);
    return wanted.filter((t) => !t.object && !t.loading);
  }

  // Fetch and parse one tile's glb; it is added hidden (the next selection shows it).
  async load(tile) {
    tile.loading = true;
    try {
      const gltf = await loader.loadAsync(new URL(tile.uri, this.url).href);
      const holder = new THREE.Group();
      holder.matrixAutoUpdate = false;
      holder.matrix.copy(tile.matrix).multiply(Y_UP_TO_Z_UP);
      holder.add(gltf.scene);
      holder.visible = false;
      tile.object = holder;
      this.group.add(holder);
    } finally {
      tile.loading = false;
    }
  }

  // The drawn meshes (for picking).
  meshes() {
    const out = [];
    for (const t of this.tiles) {
      if (t.object && t.object.visible) t.object.traverse((o) => { if (o.isMesh) out.push(o); });
    }
    return out;
  }
}

// Fetch the tileset.json of a site.json tileset entry (url relative to the page).
export async function openTileset(entry, origin) {
  const url = new URL(entry.url, window.location.href).href;
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${entry.url}: HTTP ${r.status}`);
  return new MeshTileset(entry, await r.json(), url, origin);
}
