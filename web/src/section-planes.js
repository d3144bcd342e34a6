// Section planes: one or more planes that cut the obstacles (never the part, the trees or the path),
// each dragged along its normal in the scene by its own handle, with the cuts capped so that walls
// read as solid. The cap of an obstacle on a plane is drawn where the obstacle's back faces show
// through the cut more often than its front faces (a stencil count, as in three.js's
// webgl_clipping_stencil example): there, the plane is inside the obstacle. Caps are drawn for
// opaque obstacles, in the static layer (layers.js).
import * as THREE from 'three';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';

/** The axis-aligned normal nearest to a direction. */
function nearestAxis(dir) {
  const a = [Math.abs(dir.x), Math.abs(dir.y), Math.abs(dir.z)];
  const k = a.indexOf(Math.max(...a));
  const n = new THREE.Vector3();
  n.setComponent(k, Math.sign(dir.getComponent(k)) || 1);
  return n;
}

/** A material that counts, in the stencil, the faces of one side drawn (no colour, no depth). */
function stencilMaterial(side, op, clippingPlanes) {
  return new THREE.MeshBasicMaterial({
    side, clippingPlanes, colorWrite: false, depthWrite: false, depthTest: false,
    stencilWrite: true, stencilFunc: THREE.AlwaysStencilFunc,
    stencilFail: op, stencilZFail: op, stencilZPass: op,
  });
}

export class SectionPlanes {
  /**
   * @param view the SceneView (its obstacles, camera, orbit controls, layers, part)
   * @param changed () => void: the picture changed
   */
  constructor(view, changed) {
    this.view = view;
    this.changed = changed;
    this.planes = []; // { plane: THREE.Plane, handle: Mesh }
    this.capped = true; // the cuts capped (off: hollow, for comparing)
    this.group = new THREE.Group(); // the stencil meshes and caps (static layer)
    this.group.name = 'sections';
    view.layers.staticRoot.add(this.group);
    this.handles = new THREE.Group(); // the planes' handles (dynamic layer)
    view.layers.dynamicRoot.add(this.handles);
    this.drag = new TransformControls(view.camera, view.layers.domElement);
    this.drag.setMode('translate');
    this.drag.setSpace('local');
    this.drag.showX = this.drag.showY = false;
    this.drag.setSize(0.7);
    view.layers.dynamicRoot.add(this.drag.getHelper());
    this.drag.addEventListener('dragging-changed', (e) => { view.orbit.enabled = !e.value; });
    this.drag.addEventListener('objectChange', () => this.moved());
  }

  get active() { return this.planes.length > 0; }

  /** Whether a point is cut away (on the negative side of a plane). */
  cutsAway(point) { return this.planes.some(({ plane }) => plane.distanceToPoint(point) < 0); }

  /** A plane through a point (default: the part), its normal the axis nearest to the way the
   * camera looks: it cuts away what is between the camera and that point. */
  add(point = this.view.part.position.clone()) {
    const { camera, orbit } = this.view;
    const ahead = orbit.target.clone().sub(camera.position);
    const used = this.planes.map((p) => p.plane.normal);
    let normal = nearestAxis(ahead);
    // A second plane on another axis (the nearest one not used yet).
    for (const axis of [normal, new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 1, 0), new THREE.Vector3(0, 0, 1)]) {
      if (!used.some((n) => Math.abs(n.dot(axis)) > 0.99)) { normal = axis.clone(); break; }
    }
    if (normal.dot(ahead) < 0) normal.negate();
    const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, point);
    this.planes.push({ plane, handle: this.makeHandle(plane, point) });
    this.rebuild();
    return plane;
  }

  /** No plane. */
  clear() {
    this.handles.clear();
    this.planes = [];
    this.rebuild();
  }

  /** Turns the last plane round: the other side is cut away. */
  flipLast() {
    const last = this.planes[this.planes.length - 1];
    if (!last) return;
    last.plane.negate();
    last.handle.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), last.plane.normal);
    this.rebuild();
  }

  /** A square outline on the plane, its local z the normal, that the drag handle moves. */
  makeHandle(plane, point) {
    const size = this.view.extent * 0.15;
    // The plane's outline only: a fill would tint what the section is there to show.
    const handle = new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.PlaneGeometry(size, size)),
      new THREE.LineBasicMaterial({ color: 0xfbbf24 }));
    handle.position.copy(plane.projectPoint(point, new THREE.Vector3()));
    handle.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), plane.normal);
    this.handles.add(handle);
    return handle;
  }

  /** A handle was dragged: its plane follows it. */
  moved() {
    for (const { plane, handle } of this.planes) plane.setFromNormalAndCoplanarPoint(plane.normal, handle.position);
    this.placeCaps();
    this.view.layers.invalidate();
    this.changed();
  }

  /** The obstacles' clipping, the stencil meshes and the caps, after a plane came, went or turned. */
  rebuild() {
    const planes = this.planes.map((p) => p.plane);
    for (const m of this.view.obstacleMeshes) {
      m.material.clippingPlanes = planes.length ? planes : null;
      m.material.needsUpdate = true;
    }
    this.view.layers.setClipping(planes);
    this.disposeCaps();
    this.view.obstacleMeshes.forEach((mesh, i) => planes.forEach((plane, j) => this.cap(mesh, i, plane, j, planes)));
    this.placeCaps();
    const last = this.planes[this.planes.length - 1];
    if (last) this.drag.attach(last.handle); else this.drag.detach();
    this.view.layers.invalidate();
    this.changed();
  }

  /** The stencil meshes of one obstacle on one plane, and the cap drawn where they leave a count
   * (the stencil is cleared after each cap). The obstacles' geometry is in the world frame. */
  cap(mesh, i, plane, j, planes) {
    const order = 1 + 3 * (i * planes.length + j);
    const back = new THREE.Mesh(mesh.geometry, stencilMaterial(THREE.BackSide, THREE.IncrementWrapStencilOp, [plane]));
    const front = new THREE.Mesh(mesh.geometry, stencilMaterial(THREE.FrontSide, THREE.DecrementWrapStencilOp, [plane]));
    const size = this.view.extent * 4;
    const capMaterial = new THREE.MeshLambertMaterial({
      color: mesh.material.color.clone().multiplyScalar(0.7), side: THREE.DoubleSide,
      clippingPlanes: planes.filter((p) => p !== plane),
      stencilWrite: true, stencilRef: 0, stencilFunc: THREE.NotEqualStencilFunc,
      stencilFail: THREE.ReplaceStencilOp, stencilZFail: THREE.ReplaceStencilOp, stencilZPass: THREE.ReplaceStencilOp,
    });
    const capMesh = new THREE.Mesh(new THREE.PlaneGeometry(size, size), capMaterial);
    capMesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), plane.normal);
    capMesh.onAfterRender = (renderer) => renderer.clearStencil();
    capMesh.userData.plane = plane;
    back.renderOrder = order;
    front.renderOrder = order + 1;
    capMesh.renderOrder = order + 2;
    for (const m of [back, front, capMesh]) {
      m.userData.of = mesh;
      m.frustumCulled = false;
      this.group.add(m);
    }
  }

  /** Each cap on its plane. */
  placeCaps() {
    for (const m of this.group.children) if (m.userData.plane) m.userData.plane.coplanarPoint(m.position);
  }

  /** Before a frame: caps only for the obstacles drawn opaque (their looks change at any time). */
  update() {
    if (!this.active) return;
    for (const m of this.group.children) {
      const of = m.userData.of;
      m.visible = this.capped && of.visible && !of.material.transparent;
    }
  }

  disposeCaps() {
    for (const m of this.group.children) {
      m.material.dispose();
      if (m.geometry.type === 'PlaneGeometry') m.geometry.dispose();
    }
    this.group.clear();
  }
}
