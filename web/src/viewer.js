// The `ws publish` web viewer: COPC point clouds streamed by level of detail with three.js.
//
// site.json (written by workstation/publish/site.py) lists the clouds (COPC files), raster
// previews (PNG + bounds) and SfM camera frusta. Every COPC node is one LAZ chunk fetched with an
// HTTP Range request and decoded by laz-perf (WASM). Each time the view changes, the octree is
// walked from the root: a node is drawn when its cube meets the view frustum, and its children are
// visited while the node's point spacing (COPC info spacing / 2^level) covers more pixels on
// screen than the drawn point size (the screen-space error test of Schütz, "Potree: rendering
// large point clouds in web browsers", 2016). A point budget caps the drawn points; nearer,
// coarser nodes come first. Coordinates are shifted by site.json's origin so float32 keeps
// millimetres; the URL hash `#view=px,py,pz,tx,ty,tz` (CRS units) sets the camera and
// `&fov=DEG` its vertical field of view (default 55°). Meshes (site.json `tilesets` of kind
// mesh: 3D Tiles written by `ws publish --3d-tiles`) are drawn by tiles.js, lit by a sky light
// and a light from the camera.
//
// The page's state is published on <html data-ws-state="loading|ready|error"> together with
// data-ws-requests (Range requests sent), data-ws-nodes (nodes drawn) and data-ws-errors, and
// on window.wsViewer, so a headless browser can tell when the first view is complete.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { Copc, Info, Las } from 'copc';
import { createLazPerf } from 'laz-perf';
import { openTileset } from './tiles.js';

const MODES = { rgb: 0, classification: 1, elevation: 2, intensity: 3 };
const MAX_CONCURRENT = 4; // node requests in flight
const html = document.documentElement;
const $ = (id) => document.getElementById(id);
const state = {
  site: null, origin: new THREE.Vector3(), clouds: [], tilesets: [], requests: 0, errors: 0, nodesDrawn: 0,
  pending: 0, queue: [], pointSize: 2, budget: 3_000_000, needsUpdate: true, picks: [], measure: null,
  marks: {}, // ms since navigation: 'start' (script runs), 'wasm' (laz-perf ready), 'opened' (COPC headers read), 'first' (first node drawn), 'ready'
};
const mark = (name) => { if (!(name in state.marks)) state.marks[name] = Math.round(performance.now()); };
window.wsViewer = state;

// ---------------------------------------------------------------- status and errors
function publishState(s) {
  html.dataset.wsState = s;
  html.dataset.wsRequests = String(state.requests);
  html.dataset.wsNodes = String(state.nodesDrawn);
  html.dataset.wsErrors = String(state.errors);
  const pts = state.clouds.reduce((n, c) => n + c.drawnPoints, 0);
  $('status').textContent = `${s} · ${state.nodesDrawn} nodes · ${pts.toLocaleString()} points`;
}
function fail(err) {
  state.errors += 1;
  console.error('ws-viewer:', err);
  $('status').textContent = `error: ${err && err.message ? err.message : err}`;
  publishState('error');
}
window.addEventListener('error', (e) => fail(e.error || e.message));
window.addEventListener('unhandledrejection', (e) => fail(e.reason));

// ---------------------------------------------------------------- three.js scene
// Colour modes: RGB (a cloud without colour shows elevation), ASPRS class, elevation, intensity.
const renderer = new THREE.WebGLRenderer({ canvas: $('view'), antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
const camera = new THREE.PerspectiveCamera(55, 1, 0.1, 1e6);
camera.up.set(0, 0, 1);
const sky = new THREE.HemisphereLight(0xffffff, 0x555555, 2.0); // lights meshes only (points are unlit)
sky.position.set(0, 0, 1); // the sky is up: +z here, not three.js's default +y
scene.add(sky);
const headlight = new THREE.DirectionalLight(0xffffff, 1.0);
headlight.position.set(0, 1, 0); // from above the viewer's head (camera frame: y up, looking down -z)...
headlight.target.position.set(0, 0, -1); // ...to a point ahead: faces towards the viewer are lit
camera.add(headlight, headlight.target);
scene.add(camera);
const controls = new OrbitControls(camera, renderer.domElement);
controls.addEventListener('change', () => { state.needsUpdate = true; });

const shared = {
  uMode: { value: 0 }, uSize: { value: 2 }, uProj: { value: 1 }, uZRange: { value: new THREE.Vector2(0, 1) },
  uIRange: { value: new THREE.Vector2(0, 65535) }, uClassTex: { value: null },
};
const classData = new Uint8Array(256 * 4);
shared.uClassTex.value = new THREE.DataTexture(classData, 256, 1, THREE.RGBAFormat);

const VERTEX = `
uniform int uMode; uniform float uSize, uProj, uSpacing, uHasRgb; uniform vec2 uZRange, uIRange;
uniform sampler2D uClassTex;
attribute vec3 rgb; attribute float cls; attribute float intensity;
varying vec3 vColor;
vec3 ramp(float t) { // a perceptually ordered blue-green-yellow ramp (viridis stops)
  t = clamp(t, 0.0, 1.0);
  vec3 c0 = vec3(0.267, 0.005, 0.329), c1 = vec3(0.229, 0.322, 0.546), c2 = vec3(0.128, 0.567, 0.551);
  vec3 c3 = vec3(0.369, 0.789, 0.383), c4 = vec3(0.993, 0.906, 0.144);
  if (t < 0.25) return mix(c0, c1, t * 4.0);
  if (t < 0.5) return mix(c1, c2, t * 4.0 - 1.0);
  if (t < 0.75) return mix(c2, c3, t * 4.0 - 2.0);
  return mix(c3, c4, t * 4.0 - 3.0);
}
void main() {
  vec4 k = texture2D(uClassTex, vec2((cls + 0.5) / 256.0, 0.5));
  vec4 mv = modelViewMatrix * vec4(position, 1.0);
  if (k.a < 0.5) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); gl_PointSize = 0.0; return; }
  gl_Position = projectionMatrix * mv;
  gl_PointSize = clamp(uSpacing * uProj / max(-mv.z, 1e-6), uSize, 4.0 * uSize);
  if (uMode == 0 && uHasRgb > 0.5) vColor = rgb;
  else if (uMode == 1) vColor = k.rgb;
  else if (uMode <= 2) vColor = ramp((position.z - uZRange.x) / (uZRange.y - uZRange.x));
  else vColor = vec3(clamp((intensity - uIRange.x) / (uIRange.y - uIRange.x), 0.0, 1.0));
}`;
const FRAGMENT = `varying vec3 vColor; void main() { gl_FragColor = vec4(vColor, 1.0); }`;

function resize() {
  const w = window.innerWidth, h = window.innerHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
  state.needsUpdate = true;
}
window.addEventListener('resize', resize);

// ---------------------------------------------------------------- COPC access
function rangeGetter(url) {
  let whole = null; // a server that ignores Range sends the whole file once
  return async (begin, end) => {
    if (whole) return whole.slice(begin, end);
    state.requests += 1;
    const r = await fetch(url, { headers: { Range: `bytes=${begin}-${end - 1}` } });
    if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
    const buf = new Uint8Array(await r.arrayBuffer());
    if (r.status === 206) return buf;
    console.warn(`ws-viewer: ${url} was served without Range support; using the whole file`);
    whole = buf;
    return whole.slice(begin, end);
  };
}

function nodeBox(cloud, key) {
  const [d, x, y, z] = key.split('-').map(Number);
  const c = cloud.info.cube, size = (c[3] - c[0]) / 2 ** d, o = state.origin;
  const min = new THREE.Vector3(c[0] + x * size - o.x, c[1] + y * size - o.y, c[2] + z * size - o.z);
  return new THREE.Box3(min, min.clone().addScalar(size));
}

// The LAS header, the COPC info VLR and the root hierarchy page (as Copc.create, without the
// extra-bytes VLR, which this viewer does not draw and whose 64-bit no-data values copc.js
// cannot hold in a JavaScript number).
async function readCopc(getter) {
  const head = getter(0, 65536).catch(() => null); // header + VLRs in one request
  const get = async (b, e) => { const h = await head; return h && e <= h.length ? h.slice(b, e) : getter(b, e); };
  const header = Las.Header.parse(await get(0, 375));
  const vlrs = await Las.Vlr.walk(get, header);
  const infoVlr = Las.Vlr.find(vlrs, 'copc', 1);
  if (!infoVlr) throw new Error('not a COPC file (no copc info VLR)');
  return { header, vlrs, info: Info.parse(await Las.Vlr.fetch(get, infoVlr)) };
}

async function openCloud(entry, lazPerf) {
  const getter = rangeGetter(entry.url);
  const copc = await readCopc(getter);
  const root = await Copc.loadHierarchyPage(getter, copc.info.rootHierarchyPage);
  const cloud = { entry, getter, copc, info: copc.info, lazPerf, nodes: { ...root.nodes }, pages: { ...root.pages },
                  loaded: new Map(), loading: new Set(), drawnPoints: 0, group: new THREE.Group() };
  scene.add(cloud.group);
  return cloud;
}

// A child page listed in the hierarchy is fetched the first time the walk reaches its key.
async function loadPage(cloud, key) {
  const page = cloud.pages[key];
  delete cloud.pages[key];
  state.pending += 1;
  try {
    const sub = await Copc.loadHierarchyPage(cloud.getter, page);
    Object.assign(cloud.nodes, sub.nodes);
    Object.assign(cloud.pages, sub.pages);
  } finally {
    state.pending -= 1;
    state.needsUpdate = true;
  }
}

// Decode one node (a LAZ chunk of point format 6, 7 or 8, as COPC requires) straight from the
// WASM heap into the typed arrays three.js draws: X/Y/Z int32 at bytes 0/4/8, intensity u16 at
// 12, classification u8 at 16, red/green/blue u16 at 30/32/34 (LAS 1.4 R15, Tables 11 and 12).
async function loadNode(cloud, key) {
  const node = cloud.nodes[key], h = cloud.copc.header, L = cloud.lazPerf;
  const fmt = h.pointDataRecordFormat, len = h.pointDataRecordLength, n = node.pointCount;
  if (fmt < 6 || fmt > 8) throw new Error(`COPC needs point format 6, 7 or 8, not ${fmt}`);
  const bytes = await cloud.getter(node.pointDataOffset, node.pointDataOffset + node.pointDataLength);
  const pos = new Float32Array(3 * n), rgb = new Uint8Array(3 * n), cls = new Uint8Array(n), inten = new Float32Array(n);
  const [sx, sy, sz] = h.scale, o = state.origin;
  const [ox, oy, oz] = [h.offset[0] - o.x, h.offset[1] - o.y, h.offset[2] - o.z];
  const hasRgb = fmt >= 7, shift = cloud.entry.rgb_bits === 16 ? 8 : 0;
  const blob = L._malloc(bytes.byteLength), pt = L._malloc(len), decoder = new L.ChunkDecoder();
  try {
    L.HEAPU8.set(bytes, blob);
    decoder.open(fmt, len, blob);
    let dv = new DataView(L.HEAPU8.buffer, pt, len);
    for (let i = 0; i < n; i++) {
      decoder.getPoint(pt);
      if (dv.buffer !== L.HEAPU8.buffer) dv = new DataView(L.HEAPU8.buffer, pt, len); // the heap grew
      pos[3 * i] = dv.getInt32(0, true) * sx + ox;
      pos[3 * i + 1] = dv.getInt32(4, true) * sy + oy;
      pos[3 * i + 2] = dv.getInt32(8, true) * sz + oz;
      inten[i] = dv.getUint16(12, true);
      cls[i] = dv.getUint8(16);
      if (hasRgb) {
        rgb[3 * i] = dv.getUint16(30, true) >> shift;
        rgb[3 * i + 1] = dv.getUint16(32, true) >> shift;
        rgb[3 * i + 2] = dv.getUint16(34, true) >> shift;
      }
    }
  } finally {
    L._free(blob); L._free(pt); decoder.delete();
  }
  const geom = new THREE.BufferGeometry();
  geom.setAttribute('position', new THREE.BufferAttribute(pos, 3));
  geom.setAttribute('rgb', new THREE.BufferAttribute(rgb, 3, true));
  geom.setAttribute('cls', new THREE.BufferAttribute(cls, 1));
  geom.setAttribute('intensity', new THREE.BufferAttribute(inten, 1));
  const depth = Number(key.split('-')[0]);
  const material = new THREE.ShaderMaterial({
    vertexShader: VERTEX, fragmentShader: FRAGMENT,
    uniforms: { ...shared, uSpacing: { value: cloud.info.spacing / 2 ** depth }, uHasRgb: { value: hasRgb && cloud.entry.rgb_bits ? 1 : 0 } },
  });
  const points = new THREE.Points(geom, material);
  points.frustumCulled = false;
  points.userData = { key, cloud };
  return points;
}

// ---------------------------------------------------------------- level-of-detail walk
function projectedSpacing(cloud, key, box, eye) {
  const depth = Number(key.split('-')[0]);
  const dist = Math.max(box.distanceToPoint(eye), camera.near);
  return (cloud.info.spacing / 2 ** depth) * shared.uProj.value / dist;
}

function childKeys(key) {
  const [d, x, y, z] = key.split('-').map(Number), out = [];
  for (let i = 0; i < 8; i++) out.push(`${d + 1}-${2 * x + (i & 1)}-${2 * y + ((i >> 1) & 1)}-${2 * z + ((i >> 2) & 1)}`);
  return out;
}

// The nodes to draw: in the frustum, refined while their spacing covers more than a point's size
// on screen, nearest-and-coarsest first (priority = projected spacing) within the point budget.
function selectNodes() {
  const frustum = new THREE.Frustum().setFromProjectionMatrix(
    new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse));
  const eye = camera.position, chosen = [];
  const heap = [];
  for (const cloud of state.clouds.filter((c) => c.group.visible)) {
    const box = nodeBox(cloud, '0-0-0-0');
    if (frustum.intersectsBox(box)) heap.push({ cloud, key: '0-0-0-0', box, p: Infinity });
  }
  let points = 0;
  while (heap.length) {
    heap.sort((a, b) => a.p - b.p);
    const item = heap.pop();
    const { cloud, key } = item;
    if (cloud.pages[key]) { loadPage(cloud, key).catch(fail); continue; }
    const node = cloud.nodes[key];
    if (!node) continue;
    if (points + node.pointCount > state.budget) break;
    points += node.pointCount;
    if (node.pointCount > 0) chosen.push(item);
    if (projectedSpacing(cloud, key, item.box, eye) <= shared.uSize.value) continue; // device pixels
    for (const ck of childKeys(key)) {
      if (!cloud.nodes[ck] && !cloud.pages[ck]) continue;
      const box = nodeBox(cloud, ck);
      if (frustum.intersectsBox(box)) heap.push({ cloud, key: ck, box, p: projectedSpacing(cloud, ck, box, eye) });
    }
  }
  return chosen;
}

function update() {
  camera.updateMatrixWorld();
  const chosen = selectNodes();
  const want = new Set(chosen.map((c) => `${c.cloud.entry.url}|${c.key}`));
  state.want = want;
  state.queue = chosen.filter((c) => !c.cloud.loaded.has(c.key) && !c.cloud.loading.has(c.key));
  for (const cloud of state.clouds) {
    for (const [key, pts] of cloud.loaded) {
      const keep = want.has(`${cloud.entry.url}|${key}`);
      if (!keep && pts.parent) { cloud.group.remove(pts); pts.geometry.dispose(); pts.material.dispose(); cloud.loaded.delete(key); }
    }
  }
  const frustum = new THREE.Frustum().setFromProjectionMatrix(
    new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse));
  for (const ts of state.tilesets) for (const tile of ts.select(frustum, camera.position, shared.uProj.value)) loadTile(ts, tile);
  pump();
  recount();
}

// Fetch one mesh tile; the selection runs again once it is there (a REPLACE parent swaps out).
function loadTile(ts, tile) {
  state.pending += 1;
  ts.load(tile).catch(fail).finally(() => { state.pending -= 1; state.needsUpdate = true; });
}

function pump() {
  while (state.pending < MAX_CONCURRENT && state.queue.length) {
    const { cloud, key } = state.queue.shift();
    cloud.loading.add(key);
    state.pending += 1;
    loadNode(cloud, key).then((pts) => {
      if (!state.want.has(`${cloud.entry.url}|${key}`)) { pts.geometry.dispose(); pts.material.dispose(); return; }
      cloud.loaded.set(key, pts);
      cloud.group.add(pts);
    }).catch(fail).finally(() => {
      cloud.loading.delete(key);
      state.pending -= 1;
      recount();
      pump();
      state.dirty = true;
    });
  }
}

function recount() {
  state.nodesDrawn = 0;
  for (const c of state.clouds) {
    c.drawnPoints = 0;
    for (const pts of c.loaded.values()) { state.nodesDrawn += 1; c.drawnPoints += pts.geometry.attributes.position.count; }
  }
}

function frame() {
  requestAnimationFrame(frame);
  const proj = renderer.domElement.height / (2 * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2));
  shared.uProj.value = proj;
  shared.uSize.value = state.pointSize * renderer.getPixelRatio();
  if (state.needsUpdate) { state.needsUpdate = false; update(); state.dirty = true; }
  const busy = state.pending || state.queue.length, now = performance.now();
  // while nodes stream in, draw at most 4 times a second (software WebGL pays for every frame)
  if (!state.dirty || (busy && now - (state.lastDraw || 0) < 250)) return;
  state.dirty = false;
  state.lastDraw = now;
  renderer.render(scene, camera);
  drawMapMarker();
  if (state.nodesDrawn) mark('first');
  if (!busy) mark('ready');
  if (state.errors === 0) publishState(busy ? 'loading' : 'ready');
}

// ---------------------------------------------------------------- colours and classes
function setClassVisible(code, on) {
  classData[4 * code + 3] = on ? 255 : 0;
  shared.uClassTex.value.needsUpdate = true;
  state.dirty = true;
}

function buildControls(site) {
  const mode = $('color');
  const hasRgb = site.clouds.some((c) => c.rgb_bits);
  mode.value = hasRgb ? 'rgb' : (site.classes.length > 1 ? 'classification' : 'elevation');
  if (!hasRgb) mode.querySelector('option[value=rgb]').disabled = true;
  mode.addEventListener('change', () => { shared.uMode.value = MODES[mode.value]; state.dirty = true; });
  shared.uMode.value = MODES[mode.value];
  for (let code = 0; code < 256; code++) setClassVisible(code, true);
  const list = $('classes');
  for (const k of site.classes) {
    classData.set(k.color, 4 * k.code);
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox'; box.checked = true; box.dataset.code = k.code;
    box.addEventListener('change', () => setClassVisible(k.code, box.checked));
    const swatch = `<span class="swatch" style="background:rgb(${k.color.join(',')})"></span>`;
    label.append(box);
    label.insertAdjacentHTML('beforeend', `${swatch}${k.code} ${k.name} <small>${k.count.toLocaleString()}</small>`);
    list.append(label);
  }
  shared.uClassTex.value.needsUpdate = true;
  shared.uZRange.value.set(site.bounds[2] - state.origin.z, site.bounds[5] - state.origin.z);
  shared.uIRange.value.set(...site.intensity_range);
  $('size').addEventListener('input', (e) => { state.pointSize = Number(e.target.value); state.needsUpdate = true; });
  $('measure-distance').addEventListener('click', () => startMeasure('distance'));
  $('measure-height').addEventListener('click', () => startMeasure('height'));
}

// One checkbox per cloud when there are several; a hidden cloud's nodes are dropped.
function buildCloudList(clouds) {
  if (clouds.length < 2) { $('clouds-box').hidden = true; return; }
  for (const cloud of clouds) {
    const label = document.createElement('label'), box = document.createElement('input');
    box.type = 'checkbox'; box.checked = true; box.dataset.cloud = cloud.entry.name;
    box.addEventListener('change', () => { cloud.group.visible = box.checked; state.needsUpdate = true; });
    label.append(box, ` ${cloud.entry.name} `);
    label.insertAdjacentHTML('beforeend', `<small>${cloud.entry.points.toLocaleString()}</small>`);
    $('clouds').append(label);
  }
}

// One checkbox per mesh (3D Tiles); the box is hidden when the site has none.
function buildMeshList(tilesets) {
  if (!tilesets.length) { $('meshes-box').hidden = true; return; }
  for (const ts of tilesets) {
    const label = document.createElement('label'), box = document.createElement('input');
    box.type = 'checkbox'; box.checked = true; box.dataset.mesh = ts.entry.name;
    box.addEventListener('change', () => { ts.group.visible = box.checked; state.needsUpdate = true; });
    label.append(box, ` ${ts.entry.name} `);
    const faces = ts.entry.faces ? `<small>${ts.entry.faces.toLocaleString()} faces</small>` : '';
    label.insertAdjacentHTML('beforeend', faces);
    $('meshes').append(label);
  }
}

// ---------------------------------------------------------------- measuring
const raycaster = new THREE.Raycaster();
const measureGroup = new THREE.Group();
scene.add(measureGroup);

function startMeasure(kind) {
  state.measure = kind;
  state.picks = [];
  measureGroup.clear();
  $('measure-out').textContent = `${kind}: click two points`;
  state.dirty = true;
}

function pick(ev) {
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((ev.clientX - rect.left) / rect.width) * 2 - 1, -((ev.clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  raycaster.params.Points.threshold = camera.position.distanceTo(controls.target) * 0.01;
  const objects = state.clouds.filter((c) => c.group.visible).flatMap((c) => [...c.loaded.values()]);
  const hits = raycaster.intersectObjects(objects, false).filter((h) => {
    const cls = h.object.geometry.attributes.cls.array[h.index];
    return classData[4 * cls + 3] > 0;
  }).map((h) => ({ distance: h.distance, // the point itself, not its foot on the ray
    point: new THREE.Vector3().fromBufferAttribute(h.object.geometry.attributes.position, h.index).applyMatrix4(h.object.matrixWorld) }));
  const meshes = state.tilesets.filter((t) => t.group.visible).flatMap((t) => t.meshes());
  hits.push(...raycaster.intersectObjects(meshes, false)); // surface points of the meshes
  hits.sort((a, b) => a.distance - b.distance);
  return hits.length ? hits[0].point.clone() : null; // the nearest along the ray: the front surface
}

function addMarker(p) {
  const g = new THREE.BufferGeometry().setFromPoints([p]);
  measureGroup.add(new THREE.Points(g, new THREE.PointsMaterial({ color: 0xff3b30, size: 8, sizeAttenuation: false })));
}

function addLine(pts, color) {
  const g = new THREE.BufferGeometry().setFromPoints(pts);
  measureGroup.add(new THREE.Line(g, new THREE.LineBasicMaterial({ color, depthTest: false })));
}

function finishMeasure([a, b]) {
  const d = b.clone().sub(a), unit = state.site.units || '';
  if (state.measure === 'distance') {
    addLine([a, b], 0xff3b30);
    const horiz = Math.hypot(d.x, d.y);
    state.lastMeasure = { kind: 'distance', value: d.length(), horizontal: horiz, dz: d.z };
    $('measure-out').textContent = `distance ${d.length().toFixed(3)} ${unit} (horizontal ${horiz.toFixed(3)}, Δz ${d.z.toFixed(3)})`;
  } else {
    const [lo, hi] = a.z <= b.z ? [a, b] : [b, a];
    const foot = new THREE.Vector3(hi.x, hi.y, lo.z);
    addLine([lo, foot], 0x8e8e93);
    addLine([foot, hi], 0xffcc00);
    state.lastMeasure = { kind: 'height', value: Math.abs(d.z) };
    $('measure-out').textContent = `height ${Math.abs(d.z).toFixed(3)} ${unit}`;
  }
  state.measure = null;
}

let downAt = null;
renderer.domElement.addEventListener('pointerdown', (e) => { downAt = [e.clientX, e.clientY]; });
renderer.domElement.addEventListener('pointerup', (e) => {
  if (!state.measure || !downAt || Math.hypot(e.clientX - downAt[0], e.clientY - downAt[1]) > 4) return;
  const p = pick(e);
  if (!p) { $('measure-out').textContent = 'no point under the cursor'; return; }
  state.picks.push(p);
  addMarker(p);
  if (state.picks.length === 2) finishMeasure(state.picks);
  state.dirty = true;
});

// ---------------------------------------------------------------- cameras and map
function addCameras(cameras) {
  if (!cameras.length) { $('cameras-row').hidden = true; return; }
  const o = state.origin, v = [];
  for (const cam of cameras) {
    const c = cam.center.map((x, i) => x - o.getComponent(i));
    const k = cam.corners.map((p) => p.map((x, i) => x - o.getComponent(i)));
    for (let i = 0; i < 4; i++) v.push(...c, ...k[i], ...k[i], ...k[(i + 1) % 4]);
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(v, 3));
  const frusta = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0xffcc00 }));
  scene.add(frusta);
  $('cameras').addEventListener('change', (e) => { frusta.visible = e.target.checked; state.dirty = true; });
}

function setupMap(rasters) {
  if (!rasters.length) { $('map').hidden = true; return; }
  const select = $('map-layer'), img = $('map-img');
  rasters.forEach((r, i) => select.add(new Option(`${r.kind}: ${r.name}`, String(i))));
  const show = () => { img.src = rasters[Number(select.value)].url; state.map = rasters[Number(select.value)]; state.dirty = true; };
  select.addEventListener('change', show);
  show();
  img.addEventListener('click', (e) => { // fly the orbit centre to the clicked map position
    const b = state.map.bounds, r = img.getBoundingClientRect();
    const x = b[0] + ((e.clientX - r.left) / r.width) * (b[2] - b[0]) - state.origin.x;
    const y = b[3] - ((e.clientY - r.top) / r.height) * (b[3] - b[1]) - state.origin.y;
    const shift = new THREE.Vector3(x - controls.target.x, y - controls.target.y, 0);
    controls.target.add(shift); camera.position.add(shift); controls.update();
  });
}

function drawMapMarker() {
  if (!state.map) return;
  const b = state.map.bounds, m = $('map-marker'), t = controls.target.clone().add(state.origin);
  m.style.left = `${(100 * (t.x - b[0])) / (b[2] - b[0])}%`;
  m.style.top = `${(100 * (b[3] - t.y)) / (b[3] - b[1])}%`;
}

// ---------------------------------------------------------------- start
function initialView(site) {
  const b = site.bounds, o = state.origin;
  const m = /view=([-\d.e,]+)/.exec(window.location.hash);
  if (m) {
    const v = m[1].split(',').map(Number);
    camera.position.set(v[0] - o.x, v[1] - o.y, v[2] - o.z);
    controls.target.set(v[3] - o.x, v[4] - o.y, v[5] - o.z);
  } else {
    const c = new THREE.Vector3((b[0] + b[3]) / 2, (b[1] + b[4]) / 2, (b[2] + b[5]) / 2).sub(o);
    const r = Math.max(b[3] - b[0], b[4] - b[1], b[5] - b[2]);
    controls.target.copy(c);
    camera.position.copy(c).add(new THREE.Vector3(0, -0.9 * r, 0.9 * r));
  }
  const fov = /fov=([\d.]+)/.exec(window.location.hash);
  if (fov && Number(fov[1]) > 0 && Number(fov[1]) < 180) camera.fov = Number(fov[1]);
  const extent = Math.hypot(b[3] - b[0], b[4] - b[1], b[5] - b[2]);
  camera.near = extent / 1e4; camera.far = extent * 20;
  camera.updateProjectionMatrix();
  controls.update();
}

async function main() {
  mark('start');
  publishState('loading');
  const params = new URLSearchParams(window.location.search);
  if (params.get('budget')) state.budget = Number(params.get('budget'));
  const site = await (await fetch('site.json')).json();
  state.site = site;
  document.title = `${site.title} · ws viewer`;
  $('title').textContent = site.title;
  state.origin.fromArray(site.origin);
  resize();
  buildControls(site);
  addCameras(site.cameras);
  setupMap(site.rasters);
  initialView(site);
  const lazPerf = await createLazPerf({ locateFile: (f) => new URL(f, import.meta.url).href });
  mark('wasm');
  state.clouds = await Promise.all(site.clouds.map((c) => openCloud(c, lazPerf)));
  buildCloudList(state.clouds);
  const meshes = (site.tilesets || []).filter((t) => t.kind === 'mesh');
  state.tilesets = await Promise.all(meshes.map((t) => openTileset(t, state.origin)));
  for (const ts of state.tilesets) scene.add(ts.group);
  buildMeshList(state.tilesets);
  mark('opened');
  state.needsUpdate = true;
  requestAnimationFrame(frame);
}

main().catch(fail);
