// tandem's live viewer: the scene, the part at q_device, both trees growing, the contact plane,
// the guidance force, the solution with playback; the browser's operator inputs and the tuning.
// Conventions: right-handed, z up, metres (scene units); orbit camera, grid, axes.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import { Trees, decodeNodes } from './trees.js';
import { FrameRenderer } from './layers.js';
import { Keyboard, Gamepads, SpaceMouseHID } from './inputs.js';

const $ = (id) => document.getElementById(id);
const token = new URLSearchParams(location.search).get('token') ?? '';
const withToken = (path) => `${path}?token=${encodeURIComponent(token)}`;
THREE.Object3D.DEFAULT_UP.set(0, 0, 1);

// --- three.js scene ------------------------------------------------------------------------------
const container = $('view');
// Multisampling costs a software renderer (SwiftShader, as in headless Chromium) most of its
// frame: only with a real GPU; and without one the page draws in layers (layers.js).
function softwareGL() {
  const gl = document.createElement('canvas').getContext('webgl2');
  const info = gl?.getExtension('WEBGL_debug_renderer_info');
  const software = !gl || /SwiftShader|llvmpipe|software/i.test(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : '');
  gl?.getExtension('WEBGL_lose_context')?.loseContext(); // the probe's context is not kept
  return software;
}
const software = softwareGL();
const query = new URLSearchParams(location.search);
// ?layers=on|off (default: on with a software renderer, see layers.js), ?lod=N (thin the trees
// beyond N edges while the camera moves; 0 never).
const layered = { on: true, off: false }[query.get('layers')] ?? software;
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(50, 1, 0.01, 1000);
camera.up.set(0, 0, 1);
const layers = new FrameRenderer(container, scene, camera, {
  layered, lodEdges: query.has('lod') ? Number(query.get('lod')) : undefined, antialias: !software,
  pixelRatio: software ? 1 : Math.min(window.devicePixelRatio, 2), background: 0x1d2026 });
const { staticRoot, dynamicRoot } = layers;
const orbit = new OrbitControls(camera, layers.domElement);
orbit.enableDamping = false;
scene.add(new THREE.HemisphereLight(0xffffff, 0x445566, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(3, -5, 8);
scene.add(sun);

const trees = new Trees(staticRoot);
const part = new THREE.Group();
dynamicRoot.add(part);
const pathGhost = new THREE.Group();
pathGhost.visible = false;
dynamicRoot.add(pathGhost);
let pathLine = null;
const overlaid = []; // meshes of the scene in the dynamic layer
let solution = [];
let extent = 10;

const planeMesh = new THREE.Mesh(
  new THREE.PlaneGeometry(1, 1),
  new THREE.MeshBasicMaterial({ color: 0x4ade80, transparent: true, opacity: 0.25,
    side: THREE.DoubleSide, depthWrite: false }));
planeMesh.visible = false;
dynamicRoot.add(planeMesh);
const normalArrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, 0x4ade80);
normalArrow.visible = false;
dynamicRoot.add(normalArrow);
const forceArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0xf472b6);
forceArrow.visible = false;
dynamicRoot.add(forceArrow);

const gizmo = new TransformControls(camera, layers.domElement);
gizmo.setSize(0.8);
dynamicRoot.add(gizmo.getHelper());

function meshOf(body, opacity = 1) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(body.positions, 3));
  g.setIndex(body.indices);
  g.computeVertexNormals();
  const [r, gr, b, a] = body.color;
  const alpha = a * opacity;
  // Lambert shading: cheap enough for a software renderer, and CAD parts need no more.
  const m = new THREE.MeshLambertMaterial({ color: new THREE.Color(r, gr, b),
    transparent: alpha < 1, opacity: alpha, side: THREE.DoubleSide });
  return new THREE.Mesh(g, m);
}

function setPose(object, q) {
  object.position.set(q[0], q[1], q[2]);
  object.quaternion.set(q[3], q[4], q[5], q[6]);
}

function poseOf(object) {
  const p = object.position, r = object.quaternion;
  return [p.x, p.y, p.z, r.x, r.y, r.z, r.w];
}

async function loadScene() {
  const res = await fetch(withToken('/api/scene'));
  if (!res.ok) throw new Error(`the scene: ${res.status} ${await res.text()}`);
  const s = await res.json();
  $('problem').textContent = s.name;
  // Transparent obstacles go with the dynamic layer: drawn after everything opaque, as three.js
  // orders them.
  for (const body of s.obstacles) {
    const m = meshOf(body);
    (m.material.transparent ? dynamicRoot : layers.obstacles).add(m);
    if (m.material.transparent) overlaid.push(m);
  }
  part.add(meshOf(s.object));
  pathGhost.add(meshOf(s.object, 0.45));
  const ghost = (q, colour) => {
    const m = meshOf({ ...s.object, color: colour }, 0.3);
    setPose(m, q);
    dynamicRoot.add(m);
    overlaid.push(m);
  };
  ghost(s.start, [0.3, 0.6, 1, 1]);
  ghost(s.goal, [0.3, 1, 0.5, 1]);
  setPose(part, s.start);
  const min = new THREE.Vector3(...s.bounds.min), max = new THREE.Vector3(...s.bounds.max);
  const centre = min.clone().add(max).multiplyScalar(0.5);
  extent = s.extent;
  const size = Math.max(max.x - min.x, max.y - min.y, 1e-3);
  const grid = new THREE.GridHelper(size * 1.2, 12, 0x555b66, 0x3a3f48);
  grid.rotation.x = Math.PI / 2; // the grid in the xy plane: z up
  grid.position.set(centre.x, centre.y, min.z);
  staticRoot.add(grid);
  const axes = new THREE.AxesHelper(size * 0.1);
  axes.position.set(min.x, min.y, min.z);
  staticRoot.add(axes);
  orbit.target.copy(centre);
  camera.position.copy(centre).add(new THREE.Vector3(0.6, -1.1, 0.8).multiplyScalar(extent * 0.8));
  camera.near = extent / 1000;
  camera.far = extent * 20;
  camera.updateProjectionMatrix();
  orbit.update();
  gizmo.attach(part);
  return s;
}

function resize() {
  const w = container.clientWidth, h = container.clientHeight;
  layers.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

// --- the socket ----------------------------------------------------------------------------------
let socket = null;
let status = null, op = null, hello = null;
let poseId = 0;
const sentAt = new Map();
const latencies = [];
const errors = [];

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws?token=${encodeURIComponent(token)}`);
  socket.binaryType = 'arraybuffer';
  socket.onopen = () => setConnection('connected', 'ok');
  socket.onclose = () => { setConnection('disconnected — retrying', 'bad'); setTimeout(connect, 1000); };
  socket.onmessage = (e) => {
    if (e.data instanceof ArrayBuffer) {
      const batch = decodeNodes(e.data);
      if (!trees.add(batch)) { socket.close(); } // out of order: reconnect, start afresh
      dirty = true;
      return;
    }
    const m = JSON.parse(e.data);
    if (m.type === 'hello') { hello = m; trees.clear(m.generation); clearSolution(); }
    else if (m.type === 'reset') { trees.clear(m.generation); clearSolution(); }
    else if (m.type === 'status') onStatus(m);
    else if (m.type === 'operator') { op = m; dirty = true; }
    else if (m.type === 'solution') onSolution(m.path);
    else if (m.type === 'error') { errors.push(m.message); showMessage(`refused: ${m.message}`, 'bad'); }
  };
}

function setConnection(text, cls) {
  const el = $('connection');
  el.textContent = text;
  el.className = cls;
}
function showMessage(text, cls = '') {
  const el = $('message');
  el.textContent = text;
  el.className = `note ${cls}`;
}

const fmt = (x, d = 0) => (x === undefined ? '—' : Number(x).toLocaleString('en', {
  maximumFractionDigits: d, minimumFractionDigits: d }));

function onStatus(m) {
  status = m;
  if (m.input_latency_id && sentAt.has(m.input_latency_id)) {
    latencies.push({ id: m.input_latency_id, server_ms: m.input_latency_ms,
      round_trip_ms: performance.now() - sentAt.get(m.input_latency_id) });
    sentAt.delete(m.input_latency_id);
  }
  const src = m.nodes_by_source ?? [0, 0, 0, 0];
  const rows = [
    ['status', `${m.status}${m.paused ? ' (paused)' : ''}`],
    ['mode', `${m.mode} (${m.planner})`],
    ['elapsed', `${fmt(m.elapsed_s, 1)} s`],
    ['iterations/s', fmt(m.iterations_per_s)],
    ['iterations', fmt(m.iterations)],
    ['nodes', fmt(m.nodes)],
    ['edges', fmt(m.edges)],
    ['random / operator / contact', `${fmt(src[1])} / ${fmt(src[2])} / ${fmt(src[3])}`],
    ['collision checks', fmt(m.collision_checks)],
    ['operator loop', m.operator_rate_hz === undefined ? '—' : `${fmt(m.operator_rate_hz)} Hz`],
    ['input', m.input],
    ['input → node', m.input_latency_id ? `${fmt(m.input_latency_ms, 1)} ms` : '—'],
    ['viewer', `${fmt(fps)} fps${layers.drawn < trees.edgeCount() ? `, ${fmt(layers.drawn)} edges while turning` : ''}`],
  ];
  $('status').innerHTML = rows.map(([k, v]) => `<tr><td>${k}</td><td>${v}</td></tr>`).join('');
  if (m.settings) syncTuning(m.settings);
  if (m.input && document.activeElement !== $('input')) $('input').value = m.input;
  $('input').querySelector('[value=spacemouse]').disabled = !m.spacemouse_available;
  $('input').querySelector('[value=simulated]').disabled = !m.simulated_available;
  if (m.replay) for (const el of document.querySelectorAll('#tuning input, #tuning button, #tuning select, #input'))
    el.disabled = true;
}

function clearSolution() {
  dirty = true;
  solution = [];
  if (pathLine) { staticRoot.remove(pathLine); pathLine.geometry.dispose(); pathLine = null; }
  layers.invalidate();
  pathGhost.visible = false;
  playing = false;
  $('path-box').hidden = true;
}

function onSolution(path) {
  clearSolution();
  if (!path.length) return;
  solution = path;
  const g = new THREE.BufferGeometry().setFromPoints(path.map((q) => new THREE.Vector3(q[0], q[1], q[2])));
  pathLine = new THREE.Line(g, new THREE.LineBasicMaterial({ color: 0xfacc15 }));
  staticRoot.add(pathLine);
  layers.invalidate();
  $('path-box').hidden = false;
  showMessage(`solved: a path of ${path.length} states`, 'ok');
}

// --- path playback -------------------------------------------------------------------------------
let playing = false;
let playT = 0; // in [0, 1]
function showPathAt(t) {
  if (solution.length < 1) return;
  const x = t * (solution.length - 1);
  const i = Math.min(Math.floor(x), solution.length - 2), f = x - i;
  const a = solution[Math.max(i, 0)], b = solution[Math.min(i + 1, solution.length - 1)];
  pathGhost.position.set(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
  pathGhost.quaternion.set(a[3], a[4], a[5], a[6]).slerp(new THREE.Quaternion(b[3], b[4], b[5], b[6]), f);
  pathGhost.visible = true;
}
$('play').onclick = () => { playing = !playing; $('play').textContent = playing ? 'pause path' : 'play path'; };
$('scrub').oninput = (e) => { dirty = true; playing = false; playT = e.target.value / 1000; showPathAt(playT); };

// --- operator inputs -----------------------------------------------------------------------------
const keyboard = new Keyboard(window);
const gamepads = new Gamepads();
const hid = new SpaceMouseHID((text) => showMessage(text, 'ok'));
let dragging = false;
let drivingUntil = 0;
let lastSent = 0;

function sendPose(now) {
  const id = ++poseId;
  sentAt.set(id, now);
  if (sentAt.size > 500) sentAt.delete(sentAt.keys().next().value);
  send({ type: 'pose', q: poseOf(part), id });
  lastSent = now;
}

gizmo.addEventListener('dragging-changed', (e) => {
  dragging = e.value;
  orbit.enabled = !e.value;
  if (!e.value) sendPose(performance.now());
});
gizmo.addEventListener('objectChange', () => {
  const now = performance.now();
  drivingUntil = now + 300;
  dirty = true;
  if (now - lastSent > 16) sendPose(now);
});
const setGizmo = (mode) => {
  gizmo.setMode(mode);
  $('gizmo-translate').classList.toggle('active', mode === 'translate');
  $('gizmo-rotate').classList.toggle('active', mode === 'rotate');
};
$('gizmo-translate').onclick = () => setGizmo('translate');
$('gizmo-rotate').onclick = () => setGizmo('rotate');
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement) return;
  if (e.code === 'KeyT') setGizmo('translate');
  if (e.code === 'KeyR') setGizmo('rotate');
});
setGizmo('translate');
$('input').onchange = (e) => send({ type: 'input', input: e.target.value });
$('webhid').onclick = async () => {
  try { await hid.connect(); } catch (err) { showMessage(String(err.message ?? err), 'bad'); }
};
if (!SpaceMouseHID.available()) $('webhid').disabled = true;

function integrate(dt, now) {
  const v = [0, 0, 0, 0, 0, 0];
  for (const src of [keyboard, gamepads, hid]) {
    const w = src.velocity();
    for (let k = 0; k < 6; ++k) v[k] += w[k];
  }
  if (v.every((x) => x === 0)) return;
  const speed = 0.1 * extent, turn = 1.2;
  part.position.add(new THREE.Vector3(v[0], v[1], v[2]).multiplyScalar(speed * dt));
  const w = new THREE.Vector3(v[3], v[4], v[5]);
  const angle = w.length() * turn * dt;
  if (angle > 0) part.quaternion.premultiply(new THREE.Quaternion().setFromAxisAngle(w.normalize(), angle));
  drivingUntil = now + 300;
  dirty = true;
  if (now - lastSent > 16) sendPose(now);
}

// --- tuning --------------------------------------------------------------------------------------
const tuning = ['alpha', 'contact', 'contact_samples', 'contact_distance', 'sampling', 'sigma'];
function syncTuning(s) {
  for (const key of tuning) {
    const el = $(key);
    if (document.activeElement === el) continue;
    if (el.type === 'checkbox') el.checked = s[key];
    else el.value = s[key];
  }
  $('alpha-value').textContent = Number(s.alpha).toFixed(2);
}
for (const key of tuning) {
  $(key).addEventListener('change', (e) => {
    const el = e.target;
    let value = el.type === 'checkbox' ? el.checked : el.value;
    if (el.type === 'range' || el.type === 'number') value = Number(value);
    send({ type: 'params', [key]: value });
  });
}
$('alpha').addEventListener('input', (e) => { $('alpha-value').textContent = Number(e.target.value).toFixed(2); });
for (const c of ['pause', 'resume', 'step', 'reset']) $(c).onclick = () => send({ type: 'command', command: c });
$('save-path').href = withToken('/api/path');
$('save-session').href = withToken('/api/session');
$('colour-by').onchange = (e) => { trees.setColourBy(e.target.value); dirty = true; };
$('show-nodes').onchange = (e) => { trees.setShowNodes(e.target.value); dirty = true; };

// --- the frame loop ------------------------------------------------------------------------------
// A frame is drawn only when something changed, at most maxfps times a second (default 30; the
// URL's ?maxfps=0 lifts the cap): a software renderer then leaves the planner its core.
const maxfps = Number(query.get('maxfps') ?? 30);
orbit.autoRotateSpeed = 4;
let dirty = true;
const touch = () => { dirty = true; };
orbit.addEventListener('change', () => { layers.cameraMoved(performance.now()); dirty = true; });
gizmo.addEventListener('change', touch);
window.addEventListener('resize', touch);
let fps = 0, frames = 0, fpsFrames = 0, fpsSince = performance.now(), lastFrame = performance.now();
let lastRender = 0;
let redrawAlways = false;
function frame(now) {
  requestAnimationFrame(frame);
  const dt = Math.min((now - lastFrame) / 1000, 0.1);
  lastFrame = now;
  integrate(dt, now);
  if (orbit.autoRotate) orbit.update(dt);
  if (op && !dragging && now > drivingUntil) setPose(part, op.q);
  if (now - fpsSince >= 1000) { fps = (1000 * fpsFrames) / (now - fpsSince); fpsFrames = 0; fpsSince = now; }
  if (!dirty && !dragging && !playing && !redrawAlways && !layers.needsFrame(now)) return;
  if (maxfps > 0 && now - lastRender < 1000 / maxfps - 2) return;
  lastRender = now;
  dirty = false;
  if (op && op.contact && op.plane) {
    const n = new THREE.Vector3(...op.plane.normal).normalize();
    const p = new THREE.Vector3(...op.plane.point);
    planeMesh.position.copy(p);
    planeMesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
    planeMesh.scale.setScalar(extent * 0.08);
    normalArrow.position.copy(p);
    normalArrow.setDirection(n);
    normalArrow.setLength(extent * 0.05);
    planeMesh.visible = normalArrow.visible = true;
  } else {
    planeMesh.visible = normalArrow.visible = false;
  }
  if (op && op.force) {
    const f = new THREE.Vector3(op.force[0], op.force[1], op.force[2]);
    const len = f.length();
    forceArrow.visible = len > 1e-9;
    if (forceArrow.visible) {
      forceArrow.position.set(op.q[0], op.q[1], op.q[2]);
      forceArrow.setDirection(f.normalize());
      forceArrow.setLength(len);
    }
  } else {
    forceArrow.visible = false;
  }
  if (playing && solution.length > 1) {
    playT = (playT + dt / 8) % 1;
    $('scrub').value = String(Math.round(playT * 1000));
    showPathAt(playT);
  }
  layers.render(trees, now);
  ++frames; ++fpsFrames;
}

// --- for the tests and for scripts: read-only views of what the page shows ------------------------
window.tandem = {
  get connected() { return socket?.readyState === WebSocket.OPEN; },
  get hello() { return hello; },
  get status() { return status; },
  get operator() { return op; },
  get fps() { return fps; },
  /** How the page draws ('layered' or 'direct', see layers.js) and how many edges its last frame drew. */
  get rendering() { return { mode: layered ? 'layered' : 'direct', drawnEdges: layers.drawn }; },
  /** Turns the camera about the scene without end (a frame to draw every time: for measuring). */
  spin(on) { orbit.autoRotate = on; },
  /** Draws a frame every time, the camera still (for measuring). */
  redraw(on) { redrawAlways = on; },
  get frames() { return frames; },
  get solution() { return solution; },
  get errors() { return errors.slice(); },
  get latencies() { return latencies.slice(); },
  counts: () => trees.counts(),
  operatorNodes: () => trees.operatorNodes(),
  partPose: () => poseOf(part),
  /** Where a world point is on the page, in CSS pixels. */
  screenOf(x, y, z) {
    const v = new THREE.Vector3(x, y, z).project(camera);
    const r = layers.domElement.getBoundingClientRect();
    return { x: r.left + (v.x + 1) / 2 * r.width, y: r.top + (1 - v.y) / 2 * r.height };
  },
  partScreen() { return this.screenOf(part.position.x, part.position.y, part.position.z); },
  /** The bounding boxes on the page, in CSS pixels, of the meshes that the layered drawing draws
   * over the trees (layers.js): the part, the start and goal ghosts, transparent obstacles. */
  overlaidBoxes() { return [part, ...overlaid].map((o) => this.screenBoxOf(o)); },
  screenBoxOf(object) {
    const box = new THREE.Box3().setFromObject(object);
    const corners = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => this.screenOf(
      k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z));
    const xs = corners.map((c) => c.x), ys = corners.map((c) => c.y);
    return { left: Math.min(...xs), top: Math.min(...ys), right: Math.max(...xs), bottom: Math.max(...ys) };
  },
};

loadScene()
  .then(() => { connect(); requestAnimationFrame(frame); })
  .catch((err) => { setConnection(String(err.message ?? err), 'bad'); });
