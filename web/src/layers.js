// How a frame is drawn. With a GPU, the whole scene every frame on one canvas (`direct`). Without
// one (a software renderer such as SwiftShader, where each line segment costs a fixed setup time,
// about 0.35 µs, so 100k edges take 40–100 ms, and each full-screen pass about 11 ms at 960×800),
// `layered`, on two canvases, one over the other:
//  - the static canvas (opaque obstacles and their section caps, grid, axes, the trees) keeps its
//    image between frames (preserveDrawingBuffer); while the camera is still, only the edges and
//    nodes that came since the last frame are drawn into it, depth-tested against what is there,
//    and when nothing came it is not touched, so a frame costs the same with 100k edges as with 100;
//  - the dynamic canvas over it (transparent; the part, the ghosts, the solution line and its
//    ends, the contact plane, the arrows, the gizmo, the section planes' outlines, anything
//    transparent) is drawn every frame, after the opaque obstacles have been drawn
//    into its depth buffer only, so that obstacles hide the part where they are in front of it
//    (the trees' thin lines do not: the part and the start and goal ghosts are drawn over them);
//  - while the camera moves, there is nothing to keep: everything is drawn on the static canvas,
//    the dynamic one is empty, and if the trees have more than lodEdges edges (LOD_EDGES unless
//    said otherwise; 0: never thin) they are drawn
//    from an evenly thinned subset (every k-th edge, no nodes), as CAD and point-cloud viewers do;
//    everything is drawn in full once the camera has been still for SETTLE_MS. The status says
//    how many edges are drawn.
import * as THREE from 'three';

export const LOD_EDGES = 20000;
const SETTLE_MS = 200;

export class FrameRenderer {
  /**
   * @param container the element the canvases go into
   * @param scene the scene: its groups `staticRoot` (with `obstacles` in it) and `dynamicRoot` are
   *   made here; lights and anything else at the scene's root are drawn on both canvases
   * @param camera the camera
   * @param options `layered` (two canvases, as above), `lodEdges` (thin the trees beyond so many
   *   edges while the camera moves, 0 never; layered only), `antialias`, `pixelRatio`,
   *   `background` (a colour)
   */
  constructor(container, scene, camera, { layered, lodEdges = LOD_EDGES, antialias, pixelRatio, background }) {
    this.scene = scene;
    this.camera = camera;
    this.layered = layered;
    this.lodEdges = lodEdges;
    // The static canvas (or the only one), whose element takes the pointer events.
    // A stencil for the section planes' caps (section-planes.js); clipping per material.
    this.renderer = new THREE.WebGLRenderer({ antialias, preserveDrawingBuffer: layered, stencil: true });
    this.renderer.localClippingEnabled = true;
    this.renderer.setPixelRatio(pixelRatio);
    this.renderer.setClearColor(background, 1);
    container.appendChild(this.renderer.domElement);
    this.staticRoot = new THREE.Group();
    this.obstacles = new THREE.Group();
    this.staticRoot.add(this.obstacles);
    this.dynamicRoot = new THREE.Group();
    scene.add(this.staticRoot, this.dynamicRoot);
    this.valid = false; // the static canvas shows the static layer in full from the current camera
    this.cameraMovedAt = -Infinity;
    this.thinned = false; // the last frame drew thinned trees
    this.overlayEmpty = true;
    this.drawnEdges = 0;
    if (!layered) return;
    this.renderer.autoClear = false;
    this.overlay = new THREE.WebGLRenderer({ antialias, alpha: true });
    this.overlay.setPixelRatio(pixelRatio);
    this.overlay.setClearColor(0x000000, 0);
    this.overlay.autoClear = false;
    this.overlay.localClippingEnabled = true;
    Object.assign(this.overlay.domElement.style, { position: 'absolute', left: '0', top: '0', pointerEvents: 'none' });
    container.appendChild(this.overlay.domElement);
    this.depthOnly = new THREE.MeshBasicMaterial({ colorWrite: false, side: THREE.DoubleSide });
  }

  /** The section planes (THREE.Plane) that cut the obstacles, in their depth pass too. */
  setClipping(planes) {
    if (this.depthOnly) {
      this.depthOnly.clippingPlanes = planes.length ? planes : null;
      this.depthOnly.needsUpdate = true;
    }
    this.valid = false;
  }

  /** The canvases a picture of the view is made of, bottom first. */
  get canvases() { return this.overlay ? [this.renderer.domElement, this.overlay.domElement] : [this.renderer.domElement]; }

  /** The canvas that takes the pointer events (for the camera and the gizmo). */
  get domElement() { return this.renderer.domElement; }

  /** The static layer changed as a whole (the scene, the obstacles' looks, colours, a reset). */
  invalidate() { this.valid = false; }

  /** The camera moved. */
  cameraMoved(now) {
    this.cameraMovedAt = now;
    this.valid = false;
  }

  setSize(w, h) {
    this.renderer.setSize(w, h);
    this.overlay?.setSize(w, h);
    this.valid = false;
  }

  /** Whether a frame must be drawn even if nothing else changed: full detail once the camera has
   * settled after a thinned frame. */
  needsFrame(now) { return this.thinned && now - this.cameraMovedAt >= SETTLE_MS; }

  /** How many edges the last frame drew. */
  get drawn() { return this.drawnEdges; }

  /** Draws a frame of the scene, whose trees (`Trees`, their group in staticRoot) are `trees`. */
  render(trees, now) {
    const { renderer, scene, camera } = this;
    if (renderer.xr.isPresenting) {
      // In VR: everything, every frame, into the headset's views.
      this.dynamicRoot.visible = this.staticRoot.visible = true;
      trees.setRange('all');
      const autoClear = renderer.autoClear;
      renderer.autoClear = true;
      renderer.render(scene, camera);
      renderer.autoClear = autoClear;
      this.drawnEdges = trees.edgeCount();
      this.valid = false;
      return;
    }
    if (!this.layered) {
      trees.setRange('all');
      renderer.render(scene, camera);
      this.drawnEdges = trees.edgeCount();
      return;
    }
    const moving = now - this.cameraMovedAt < SETTLE_MS;
    const thin = this.lodEdges > 0 && moving && trees.edgeCount() > this.lodEdges;
    if (moving) {
      // Nothing to keep: everything on the static canvas, the dynamic one empty.
      renderer.clear();
      trees.setRange(thin ? 'thinned' : 'all', this.lodEdges);
      renderer.render(scene, camera);
      this.drawnEdges = thin ? trees.thinnedCount() : trees.edgeCount();
      this.valid = false;
      this.thinned = thin;
      if (!this.overlayEmpty) this.overlay.clear();
      this.overlayEmpty = true;
      return;
    }
    this.dynamicRoot.visible = false;
    if (!this.valid || trees.changed) {
      // The static layer in full from this camera.
      renderer.clear();
      trees.setRange('all');
      renderer.render(scene, camera);
      this.valid = true;
      this.drawnEdges = trees.edgeCount();
    } else if (trees.hasNew()) {
      // Only what the trees gained since the last frame, over the kept image and depth.
      this.only(trees.group, () => {
        trees.setRange('new');
        renderer.render(scene, camera);
      });
      this.drawnEdges = trees.edgeCount();
    }
    trees.markDrawn();
    this.thinned = false;
    this.dynamicRoot.visible = true;
    // The dynamic canvas: the obstacles into its depth only, then the dynamic layer.
    this.overlay.clear();
    this.overlayEmpty = false;
    this.only(this.obstacles, () => {
      scene.overrideMaterial = this.depthOnly;
      this.overlay.render(scene, camera);
      scene.overrideMaterial = null;
    });
    this.staticRoot.visible = false;
    this.overlay.render(scene, camera);
    this.staticRoot.visible = true;
  }

  /** Runs draw with only `object` of the static layer visible (and no dynamic layer). */
  only(object, draw) {
    const hidden = this.staticRoot.children.filter((o) => o !== object && o.visible);
    for (const o of hidden) o.visible = false;
    const dynamic = this.dynamicRoot.visible;
    this.dynamicRoot.visible = false;
    draw();
    this.dynamicRoot.visible = dynamic;
    for (const o of hidden) o.visible = true;
  }
}
