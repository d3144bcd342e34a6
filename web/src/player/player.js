// tandem's animation player: the page `tandem export --html` writes. It plays the glb inlined in
// the page (#tandem-glb, base64) with three.js's GLTFLoader: orbit camera, play/pause, a scrubber
// over the animation "path", the envelope shown or hidden. No network: everything is in the page.
//
// Page API for tests and scripts: window.tandemPlayer = { ready (a Promise), load(arrayBuffer),
// seek(seconds), duration, objectPose() -> {position, quaternion} of the animated node in tandem's
// frame (z up), nodeNames() }.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

const view = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x1d2127);
scene.add(new THREE.HemisphereLight(0xffffff, 0x445566, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(1, 3, 2);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(45, 1, 0.001, 1000);
const orbit = new OrbitControls(camera, renderer.domElement);
orbit.enableDamping = true;
const clock = new THREE.Clock();
const state = { root: null, mixer: null, action: null, object: null, duration: 0, playing: true };

function inlinedGlb() {
  const text = document.getElementById('tandem-glb').textContent.trim();
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i += 1) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

/** The camera on the scene's bounding box, from the front-right and above. */
function frame(root) {
  const box = new THREE.Box3().setFromObject(root);
  const centre = box.getCenter(new THREE.Vector3());
  const extent = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-3);
  camera.position.copy(centre).add(new THREE.Vector3(0.7, 0.6, 1.0).multiplyScalar(extent * 0.8));
  camera.near = extent / 1000;
  camera.far = extent * 50;
  camera.updateProjectionMatrix();
  orbit.target.copy(centre);
  orbit.update();
}

function showTime() {
  const t = state.action ? state.action.time : 0;
  document.getElementById('time').textContent = `${t.toFixed(2)} / ${state.duration.toFixed(2)} s`;
  if (state.duration > 0 && state.playing)
    document.getElementById('scrub').value = String(Math.round((1000 * t) / state.duration));
}

function seek(seconds) {
  if (!state.mixer) return;
  state.action.enabled = true;
  state.action.paused = false;
  state.mixer.setTime(Math.min(Math.max(seconds, 0), state.duration));
  state.action.paused = !state.playing;
  showTime();
}

function setPlaying(playing) {
  state.playing = playing;
  if (state.action) state.action.paused = !playing;
  document.getElementById('play').textContent = playing ? 'Pause' : 'Play';
}

function setupEnvelope(root) {
  const envelope = root.getObjectByName('envelope');
  const toggle = document.getElementById('envelope-toggle');
  toggle.hidden = !envelope;
  if (!envelope) return;
  envelope.traverse((o) => { if (o.material) o.material.depthWrite = false; });
  envelope.renderOrder = 1;
  document.getElementById('envelope').onchange = (e) => { envelope.visible = e.target.checked; };
}

/** Shows the glb's scene and plays its animation "path" in a loop, clamped at its end. */
async function load(buffer) {
  const gltf = await new GLTFLoader().parseAsync(buffer, '');
  if (state.root) scene.remove(state.root);
  state.root = gltf.scene;
  scene.add(gltf.scene);
  const clip = gltf.animations.find((a) => a.name === 'path') ?? gltf.animations[0];
  state.mixer = new THREE.AnimationMixer(gltf.scene);
  state.action = clip ? state.mixer.clipAction(clip) : null;
  state.duration = clip ? clip.duration : 0;
  state.object = clip ? gltf.scene.getObjectByName(clip.tracks[0].name.split('.')[0]) : null;
  if (state.action) {
    state.action.setLoop(THREE.LoopOnce);
    state.action.clampWhenFinished = true;  // at its end the part stays at the path's last pose
    state.action.play();
  }
  setupEnvelope(gltf.scene);
  frame(gltf.scene);
  seek(0);
  return { duration: state.duration, nodes: nodeNames() };
}

function nodeNames() {
  const names = [];
  state.root?.traverse((o) => { if (o.name) names.push(o.name); });
  return names;
}

function objectPose() {
  const o = state.object;
  if (!o) return null;
  return { position: o.position.toArray(), quaternion: o.quaternion.toArray() };
}

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}

function tick() {
  const dt = clock.getDelta();
  if (state.mixer && state.playing) {
    state.mixer.update(dt);
    if (state.action.time >= state.duration) seek(0);  // play again from the start
    showTime();
  }
  orbit.update();
  renderer.render(scene, camera);
}

document.getElementById('play').onclick = () => setPlaying(!state.playing);
document.getElementById('scrub').oninput = (e) => {
  setPlaying(false);
  seek((Number(e.target.value) / 1000) * state.duration);
};
window.addEventListener('resize', resize);
resize();
renderer.setAnimationLoop(tick);

window.tandemPlayer = {
  ready: load(inlinedGlb()),
  load,
  seek: (t) => { setPlaying(false); seek(t); return objectPose(); },
  get duration() { return state.duration; },
  objectPose,
  nodeNames,
};
