// The three.js scene: the camera and its orbit controls, the obstacles, the part at q_device, the
// start and goal ghosts, both trees, the contact plane and its normal, the guidance force, the
// solution (a thick line in screen pixels, over the trees, with its start and goal marked) and its
// playback ghost, the drag gizmo; drawn by a FrameRenderer (layers.js). How the obstacles look is
// chosen in obstacle-looks.js, and they are cut by section-planes.js.
// Conventions: right-handed, z up, metres (scene units); orbit camera, grid, axes.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import { Line2 } from 'three/examples/jsm/lines/Line2.js';
import { LineGeometry } from 'three/examples/jsm/lines/LineGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { Trees } from './trees.js';
import { FrameRenderer } from './layers.js';

THREE.Object3D.DEFAULT_UP.set(0, 0, 1);

/** Whether WebGL runs on a software renderer (SwiftShader, as in headless Chromium, llvmpipe). */
export function softwareGL() {
  const gl = document.createElement('canvas').getContext('webgl2');
  const info = gl?.getExtension('WEBGL_debug_renderer_info');
  const software = !gl || /SwiftShader|llvmpipe|software/i.test(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : '');
  gl?.getExtension('WEBGL_lose_context')?.loseContext(); // the probe's context is not kept
  return software;
}

/** A mesh of a body of /api/scene ({positions, indices, color: [r, g, b, a]}). */
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
  m.userData.baseOpacity = alpha;
  return new THREE.Mesh(g, m);
}

/** The solution line's width, in CSS pixels, and the start and goal markers' colours. */
const PATH_WIDTH = 5;
const START_COLOUR = 0x60a5fa, GOAL_COLOUR = 0x4ade80;
/** The render order of what x-ray draws in front of the see-through obstacles. */
const IN_FRONT = 10;

/** The eight corners of a Box3. */
export function boxCorners(box) {
  return [0, 1, 2, 3, 4, 5, 6, 7].map((k) => new THREE.Vector3(
    k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z));
}

/** Places an object at a configuration [x y z qx qy qz qw]. */
function setPose(object, q) {
  object.position.set(q[0], q[1], q[2]);
  object.quaternion.set(q[3], q[4], q[5], q[6]);
}

const arrow = (dir, colour) => {
  const a = new THREE.ArrowHelper(dir, new THREE.Vector3(), 1, colour);
  a.visible = false;
  return a;
};

export class SceneView {
  /**
   * @param container the element the canvases go into
   * @param options `layered` (see layers.js), `lodEdges`, `software` (no multisampling, pixel ratio 1)
   */
  constructor(container, { layered, lodEdges, software }) {
    this.container = container;
    this.layered = layered;
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    // Multisampling costs a software renderer most of its frame: only with a real GPU.
    this.layers = new FrameRenderer(container, this.scene, this.camera, {
      layered, lodEdges, antialias: !software,
      pixelRatio: software ? 1 : Math.min(window.devicePixelRatio, 2), background: 0x1d2026 });
    this.orbit = new OrbitControls(this.camera, this.layers.domElement);
    this.orbit.enableDamping = false;
    this.orbit.autoRotateSpeed = 4;
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x445566, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(3, -5, 8);
    this.scene.add(sun);
    this.trees = new Trees(this.layers.staticRoot);
    this.extent = 10;
    this.ghosts = []; // the start and goal ghosts (dynamic layer)
    this.obstacleMeshes = [];
    this.inFront = false; // x-ray: the part, the path and the markers over everything
    this.makeDynamic();
    /** Called when the picture changed (the camera, the gizmo, the window's size). */
    this.onChange = () => {};
    this.orbit.addEventListener('change', () => { this.layers.cameraMoved(performance.now()); this.onChange(); });
    this.gizmo.addEventListener('change', () => this.onChange());
    window.addEventListener('resize', () => { this.resize(); this.onChange(); });
    this.resize();
  }

  /** The part, the path's ghost, the contact plane, the arrows and the gizmo (the dynamic layer). */
  makeDynamic() {
    const root = this.layers.dynamicRoot;
    this.part = new THREE.Group();
    this.pathGhost = new THREE.Group();
    this.pathGhost.visible = false;
    this.pathLine = null;
    this.planeMesh = new THREE.Mesh(
      new THREE.PlaneGeometry(1, 1),
      new THREE.MeshBasicMaterial({ color: 0x4ade80, transparent: true, opacity: 0.25,
        side: THREE.DoubleSide, depthWrite: false }));
    this.planeMesh.visible = false;
    this.normalArrow = arrow(new THREE.Vector3(0, 0, 1), 0x4ade80);
    this.forceArrow = arrow(new THREE.Vector3(1, 0, 0), 0xf472b6);
    this.gizmo = new TransformControls(this.camera, this.layers.domElement);
    this.gizmo.setSize(0.8);
    this.markers = new THREE.Group();
    this.markers.visible = false;
    root.add(this.part, this.pathGhost, this.planeMesh, this.normalArrow, this.forceArrow, this.markers,
      this.gizmo.getHelper());
  }

  /** Builds the scene of /api/scene: obstacles, part, ghosts, grid and axes; frames the camera. */
  load(s) {
    const { dynamicRoot } = this.layers;
    for (const body of s.obstacles) {
      const m = meshOf(body);
      m.name = body.name;
      this.obstacleMeshes.push(m);
      this.placeObstacle(m, m.material.transparent);
    }
    this.part.add(meshOf(s.object));
    this.pathGhost.add(meshOf(s.object, 0.45));
    const ghost = (q, colour) => {
      const m = meshOf({ ...s.object, color: colour }, 0.3);
      setPose(m, q);
      dynamicRoot.add(m);
      this.ghosts.push(m);
    };
    ghost(s.start, [0.3, 0.6, 1, 1]);
    ghost(s.goal, [0.3, 1, 0.5, 1]);
    setPose(this.part, s.start);
    this.extent = s.extent;
    this.bounds = s.bounds;
    this.frame(s.bounds);
    this.gizmo.attach(this.part);
  }

  /** The grid and the axes under the bounds; the camera on them. */
  frame(bounds) {
    const { camera, orbit, extent } = this;
    const min = new THREE.Vector3(...bounds.min), max = new THREE.Vector3(...bounds.max);
    const centre = min.clone().add(max).multiplyScalar(0.5);
    const size = Math.max(max.x - min.x, max.y - min.y, 1e-3);
    const grid = new THREE.GridHelper(size * 1.2, 12, 0x555b66, 0x3a3f48);
    grid.rotation.x = Math.PI / 2; // the grid in the xy plane: z up
    grid.position.set(centre.x, centre.y, min.z);
    this.layers.staticRoot.add(grid);
    const axes = new THREE.AxesHelper(size * 0.1);
    axes.position.set(min.x, min.y, min.z);
    this.layers.staticRoot.add(axes);
    orbit.target.copy(centre);
    camera.position.copy(centre).add(new THREE.Vector3(0.6, -1.1, 0.8).multiplyScalar(extent * 0.8));
    camera.near = extent / 1000;
    camera.far = extent * 20;
    camera.updateProjectionMatrix();
    orbit.update();
  }

  /** Transparent obstacles go with the dynamic layer, drawn after everything opaque (as three.js
   * orders them); opaque ones with the static layer's obstacles. */
  placeObstacle(mesh, transparent) {
    const parent = transparent ? this.layers.dynamicRoot : this.layers.obstacles;
    if (mesh.parent !== parent) parent.add(mesh);
    this.layers.invalidate();
  }

  /** X-ray: the part, the path and its markers drawn over everything (after the see-through
   * obstacles, without the depth test); off: as everything else. */
  setInFront(on) {
    this.inFront = on;
    const objects = [this.part, this.pathGhost, this.markers, this.pathLine].filter(Boolean);
    for (const o of objects) {
      o.renderOrder = on ? IN_FRONT : 0;
      o.traverse((m) => {
        if (!m.material) return;
        const base = m.material.userData.baseOpacity ?? 1;
        m.material.transparent = on || base < 1;
        m.material.depthTest = !on;
        m.material.needsUpdate = true;
      });
    }
    this.layers.invalidate();
  }

  /** Turns the camera, keeping its direction, so that a box (Box3) fills about `fill` of the
   * view, centred. */
  frameBox(box, fill = 0.6) {
    const { camera, orbit } = this;
    const centre = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, this.extent * 1e-3);
    const half = THREE.MathUtils.degToRad(camera.fov / 2);
    const fit = Math.min(Math.tan(half), Math.tan(half) * camera.aspect) * fill;
    const distance = radius / Math.sin(Math.atan(fit));
    const dir = camera.position.clone().sub(orbit.target).normalize();
    orbit.target.copy(centre);
    camera.position.copy(centre).addScaledVector(dir, distance);
    camera.near = Math.max(distance / 1000, this.extent / 10000);
    camera.updateProjectionMatrix();
    orbit.update();
  }

  /** Moves the camera and its target by the same offset (to follow what moves). */
  shiftCamera(offset) {
    this.camera.position.add(offset);
    this.orbit.target.add(offset);
    this.orbit.update();
  }

  resize() {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    this.layers.setSize(w, h);
    if (this.pathLine) this.pathLine.material.resolution.set(w, h);
    this.camera.aspect = w / Math.max(h, 1);
    this.camera.updateProjectionMatrix();
  }

  setPartPose(q) { setPose(this.part, q); }

  /** The part's configuration [x y z qx qy qz qw]. */
  partPose() {
    const p = this.part.position, r = this.part.quaternion;
    return [p.x, p.y, p.z, r.x, r.y, r.z, r.w];
  }

  /** The contact plane and its normal, the guidance force: from an `operator` message (or none). */
  showOperatorCues(op) {
    const { planeMesh, normalArrow, forceArrow, extent } = this;
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
  }

  /** The solution's line through its positions (a path of configurations), or none; no ghost.
   * `coloured`: {points, colours} (solution-products.js) to draw it coloured by clearance. The
   * line is PATH_WIDTH pixels wide whatever the distance, in the dynamic layer (over the trees), and
   * the start and goal are marked with spheres. */
  setSolutionLine(path, coloured = null) {
    if (this.pathLine) {
      this.pathLine.parent.remove(this.pathLine);
      this.pathLine.geometry.dispose();
      this.pathLine.material.dispose();
      this.pathLine = null;
    }
    this.markers.clear();
    this.markers.visible = false;
    if (path) {
      const points = coloured?.points ?? path.map((q) => new THREE.Vector3(q[0], q[1], q[2]));
      const g = new LineGeometry().setPositions(points.flatMap((p) => [p.x, p.y, p.z]));
      const colours = coloured?.colours.map((c) => [c.r, c.g, c.b]) ?? null;
      if (colours) g.setColors(colours.flat());
      const m = new LineMaterial({ color: colours ? 0xffffff : 0xfacc15, vertexColors: Boolean(colours),
        linewidth: PATH_WIDTH, worldUnits: false });
      m.resolution.set(this.container.clientWidth, this.container.clientHeight);
      this.pathLine = new Line2(g, m);
      this.pathLine.computeLineDistances();
      this.pathLine.name = coloured ? 'solution-clearance' : 'solution';
      this.pathLine.userData.colours = colours;
      this.pathLine.userData.points = points;
      this.layers.dynamicRoot.add(this.pathLine);
      this.markEnds(points[0], points[points.length - 1]);
    }
    this.setInFront(this.inFront);
    this.layers.invalidate();
    this.pathGhost.visible = false;
  }

  /** Spheres at the path's start and goal. */
  markEnds(start, goal) {
    const r = this.extent * 0.006;
    for (const [p, colour] of [[start, START_COLOUR], [goal, GOAL_COLOUR]]) {
      const s = new THREE.Mesh(new THREE.SphereGeometry(r, 16, 12), new THREE.MeshBasicMaterial({ color: colour }));
      s.position.copy(p);
      this.markers.add(s);
    }
    this.markers.visible = true;
  }

  /** The name of the obstacle under a point of the page (CSS pixels), or null. */
  obstacleAt(clientX, clientY) {
    const r = this.layers.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, 1 - ((clientY - r.top) / r.height) * 2);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    return ray.intersectObjects(this.obstacleMeshes.filter((m) => m.visible), false)[0]?.object.name ?? null;
  }

  /** Marks one obstacle (by name) with a glow; null: none. */
  highlight(name) {
    for (const m of this.obstacleMeshes) m.material.emissive.setHex(m.name === name ? 0x996600 : 0x000000);
    this.layers.invalidate();
  }

  /** The part's motion envelope (a BufferGeometry in the world frame), translucent; null: none. */
  setEnvelope(geometry) {
    const { staticRoot } = this.layers;
    if (this.envelope) staticRoot.remove(this.envelope);
    this.envelope = null;
    if (geometry) {
      this.envelope = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({
        color: 0xf28c19, transparent: true, opacity: 0.35, depthWrite: false, side: THREE.DoubleSide }));
      this.envelope.name = 'envelope';
      staticRoot.add(this.envelope);
    }
    this.layers.invalidate();
  }

  /** The path's ghost at the fraction f from configuration a to b. */
  showPathGhost(a, b, f) {
    const g = this.pathGhost;
    g.position.set(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
    g.quaternion.set(a[3], a[4], a[5], a[6]).slerp(new THREE.Quaternion(b[3], b[4], b[5], b[6]), f);
    g.visible = true;
  }

  render(now) { this.layers.render(this.trees, now); }

  /** Where a world point is on the page, in CSS pixels. */
  screenOf(x, y, z) {
    const v = new THREE.Vector3(x, y, z).project(this.camera);
    const r = this.layers.domElement.getBoundingClientRect();
    return { x: r.left + (v.x + 1) / 2 * r.width, y: r.top + (1 - v.y) / 2 * r.height };
  }

  /** The bounding box of an object on the page, in CSS pixels. */
  screenBoxOf(object) {
    const corners = boxCorners(new THREE.Box3().setFromObject(object)).map((p) => this.screenOf(p.x, p.y, p.z));
    const xs = corners.map((c) => c.x), ys = corners.map((c) => c.y);
    return { left: Math.min(...xs), top: Math.min(...ys), right: Math.max(...xs), bottom: Math.max(...ys) };
  }

  /** The meshes that the layered drawing draws over the trees (layers.js): the part, the start and
   * goal ghosts, transparent obstacles, the solution and its markers. */
  overlaidObjects() {
    const transparent = this.obstacleMeshes.filter((m) => m.visible && m.parent === this.layers.dynamicRoot);
    return [this.part, ...this.ghosts, ...transparent, ...(this.pathLine ? [this.pathLine, this.markers] : [])];
  }
}
