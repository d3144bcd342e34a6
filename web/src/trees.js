// The planner's trees in three.js: per tree, one LineSegments and one Points over preallocated
// buffers that grow by doubling; new nodes are appended (the server sends deltas only) and only the
// new part is uploaded. The draw ranges say what a frame draws (see layers.js): everything, only
// what came since the last frame, or a thinned subset (every k-th edge, through an index over the
// same buffers) while the camera moves.
import * as THREE from 'three';

export const SOURCE_COLOURS = [
  new THREE.Color(0xffffff), // root
  new THREE.Color(0x60a5fa), // random
  new THREE.Color(0xfb923c), // operator
  new THREE.Color(0x4ade80), // contact
];
const NO_PARENT = 0xffffffff;
const AUTO_NODES = 25000;

/** Decodes a binary node message (see src/tandem/web/protocol.hpp). */
export function decodeNodes(buffer) {
  const view = new DataView(buffer);
  if (view.getUint8(0) !== 1) throw new Error('not a node message');
  const tree = view.getUint8(1);
  const generation = view.getUint32(4, true);
  const first = view.getUint32(8, true);
  const count = view.getUint32(12, true);
  const positions = new Float32Array(buffer, 16, 3 * count);
  const parents = new Uint32Array(buffer, 16 + 12 * count, count);
  const sources = new Uint8Array(buffer, 16 + 16 * count, count);
  const pad = (4 - (count % 4)) % 4;
  const labels = new Float32Array(buffer, 16 + 17 * count + pad, count);
  return { tree, generation, first, count, positions, parents, sources, labels };
}

function labelColour(label, out) {
  // Distance to goal over the space's extent: near the goal green, far red.
  const t = Math.max(0, Math.min(1, label < 0 ? 1 : label));
  return out.setHSL(0.33 * (1 - t), 0.85, 0.55);
}

class TreeView {
  constructor(group, index) {
    this.index = index;
    this.count = 0;
    this.capacity = 0;
    this.nodePositions = new Float32Array(0);
    this.sources = new Uint8Array(0);
    this.labels = new Float32Array(0);
    this.parents = new Uint32Array(0);
    this.edges = 0;
    this.drawnEdges = 0; // what the kept image has (layers.js)
    this.drawnNodes = 0;
    this.showPoints = true;
    this.stride = 0; // of the thinned index, which holds the edges 0, stride, … below
    this.thinnedEdges = 0; // stride * thinnedEdges
    this.lineGeometry = new THREE.BufferGeometry();
    this.pointGeometry = new THREE.BufferGeometry();
    this.lines = new THREE.LineSegments(
      this.lineGeometry,
      new THREE.LineBasicMaterial({ vertexColors: true }));
    this.points = new THREE.Points(
      this.pointGeometry,
      new THREE.PointsMaterial({ vertexColors: true, size: 2, sizeAttenuation: false }));
    this.thinGeometry = new THREE.BufferGeometry();
    this.thinGeometry.setIndex(new THREE.BufferAttribute(new Uint32Array(2048), 1));
    this.thinLines = new THREE.LineSegments(this.thinGeometry, this.lines.material);
    this.thinLines.visible = false;
    for (const o of [this.lines, this.points, this.thinLines]) o.frustumCulled = false;
    group.add(this.lines, this.points, this.thinLines);
    this.grow(1024);
  }

  grow(capacity) {
    const copy = (Type, old, n) => { const a = new Type(n); a.set(old); return a; };
    this.nodePositions = copy(Float32Array, this.nodePositions, 3 * capacity);
    this.sources = copy(Uint8Array, this.sources, capacity);
    this.labels = copy(Float32Array, this.labels, capacity);
    this.parents = copy(Uint32Array, this.parents, capacity);
    const oldLine = this.lineGeometry.getAttribute('position');
    const linePos = new Float32Array(6 * capacity), lineCol = new Float32Array(6 * capacity);
    if (oldLine) {
      linePos.set(oldLine.array);
      lineCol.set(this.lineGeometry.getAttribute('color').array);
    }
    const pointCol = new Float32Array(3 * capacity);
    const oldPointCol = this.pointGeometry.getAttribute('color');
    if (oldPointCol) pointCol.set(oldPointCol.array);
    const dyn = (array) => new THREE.BufferAttribute(array, 3).setUsage(THREE.DynamicDrawUsage);
    this.lineGeometry.setAttribute('position', dyn(linePos));
    this.lineGeometry.setAttribute('color', dyn(lineCol));
    this.thinGeometry.setAttribute('position', this.lineGeometry.getAttribute('position'));
    this.thinGeometry.setAttribute('color', this.lineGeometry.getAttribute('color'));
    // The points share the node positions array.
    this.pointGeometry.setAttribute('position', dyn(this.nodePositions));
    this.pointGeometry.setAttribute('color', dyn(pointCol));
    this.capacity = capacity;
  }

  add(batch, colourBy) {
    if (batch.first !== this.count) return false; // out of order: the caller resynchronises
    const needed = this.count + batch.count;
    if (needed > this.capacity) {
      let c = this.capacity;
      while (c < needed) c *= 2;
      this.grow(c);
    }
    const linePos = this.lineGeometry.getAttribute('position');
    const lineCol = this.lineGeometry.getAttribute('color');
    const pointCol = this.pointGeometry.getAttribute('color');
    const colour = new THREE.Color();
    const firstEdge = this.edges;
    for (let k = 0; k < batch.count; ++k) {
      const i = this.count + k;
      this.nodePositions.set(batch.positions.subarray(3 * k, 3 * k + 3), 3 * i);
      this.sources[i] = batch.sources[k];
      this.labels[i] = batch.labels[k];
      this.parents[i] = batch.parents[k];
      this.nodeColour(i, colourBy, colour);
      pointCol.array.set([colour.r, colour.g, colour.b], 3 * i);
      const p = batch.parents[k];
      if (p !== NO_PARENT && p < i) {
        const e = this.edges++;
        linePos.array.set(this.nodePositions.subarray(3 * p, 3 * p + 3), 6 * e);
        linePos.array.set(this.nodePositions.subarray(3 * i, 3 * i + 3), 6 * e + 3);
        lineCol.array.set([colour.r, colour.g, colour.b, colour.r, colour.g, colour.b], 6 * e);
      }
    }
    this.count = needed;
    // Upload only the new part. The ranges add up until the next frame uploads (and clears)
    // them: several batches may come between two frames.
    const upload = (attr, from, to) => {
      attr.addUpdateRange(from, to - from);
      attr.needsUpdate = true;
    };
    upload(linePos, 6 * firstEdge, 6 * this.edges);
    upload(lineCol, 6 * firstEdge, 6 * this.edges);
    const pointPos = this.pointGeometry.getAttribute('position');
    upload(pointPos, 3 * batch.first, 3 * needed);
    upload(pointCol, 3 * batch.first, 3 * needed);
    return true;
  }

  /** What the next draw draws: 'all', 'new' (since markDrawn) or 'thinned' (every stride-th
   * edge, no nodes). FrameRenderer sets it before every draw. */
  setRange(mode, stride) {
    if (mode === 'thinned') this.thin(stride);
    const from = mode === 'new' ? this.drawnEdges : 0, nodesFrom = mode === 'new' ? this.drawnNodes : 0;
    this.lineGeometry.setDrawRange(2 * from, 2 * (this.edges - from));
    this.pointGeometry.setDrawRange(nodesFrom, this.count - nodesFrom);
    this.lines.visible = mode !== 'thinned';
    this.points.visible = this.showPoints && mode !== 'thinned';
    this.thinLines.visible = mode === 'thinned';
  }

  markDrawn() {
    this.drawnEdges = this.edges;
    this.drawnNodes = this.count;
  }

  /** Brings the thinned index up to date: the edges 0, stride, 2 stride, … */
  thin(stride) {
    if (stride !== this.stride) {
      this.stride = stride;
      this.thinnedEdges = 0;
    }
    const wanted = Math.ceil(this.edges / stride);
    let index = this.thinGeometry.getIndex();
    if (2 * wanted > index.array.length) {
      let n = index.array.length;
      while (n < 2 * wanted) n *= 2;
      const a = new Uint32Array(n);
      a.set(index.array);
      index = new THREE.BufferAttribute(a, 1).setUsage(THREE.DynamicDrawUsage);
      this.thinGeometry.setIndex(index);
    }
    const first = this.thinnedEdges;
    for (let e = stride * this.thinnedEdges; e < this.edges; e += stride) {
      index.array[2 * this.thinnedEdges] = 2 * e;
      index.array[2 * this.thinnedEdges + 1] = 2 * e + 1;
      this.thinnedEdges++;
    }
    if (this.thinnedEdges > first) {
      index.clearUpdateRanges();
      index.addUpdateRange(2 * first, 2 * (this.thinnedEdges - first));
      index.needsUpdate = true;
    }
    this.thinGeometry.setDrawRange(0, 2 * this.thinnedEdges);
  }

  nodeColour(i, colourBy, out) {
    if (colourBy === 'label' && this.labels[i] >= 0) return labelColour(this.labels[i], out);
    return out.copy(SOURCE_COLOURS[this.sources[i]] ?? SOURCE_COLOURS[1]);
  }

  recolour(colourBy) {
    const lineCol = this.lineGeometry.getAttribute('color');
    const pointCol = this.pointGeometry.getAttribute('color');
    const colour = new THREE.Color();
    let e = 0;
    for (let i = 0; i < this.count; ++i) {
      this.nodeColour(i, colourBy, colour);
      pointCol.array.set([colour.r, colour.g, colour.b], 3 * i);
      if (this.parents[i] !== NO_PARENT && this.parents[i] < i)
        lineCol.array.set([colour.r, colour.g, colour.b, colour.r, colour.g, colour.b], 6 * e++);
    }
    lineCol.clearUpdateRanges();
    pointCol.clearUpdateRanges();
    lineCol.needsUpdate = true;
    pointCol.needsUpdate = true;
  }

  dispose(group) {
    group.remove(this.lines, this.points, this.thinLines);
    this.lineGeometry.dispose();
    this.pointGeometry.dispose();
    this.thinGeometry.dispose();
  }
}

/** All trees of the session; `counts` for the status and the tests. */
export class Trees {
  constructor(parent) {
    this.group = new THREE.Group();
    parent.add(this.group);
    this.views = [];
    this.changed = true; // drawn otherwise than the kept image shows (layers.js)
    this.colourBy = 'source';
    this.showNodes = 'auto';
    this.generation = 0;
    this.look = 'shown'; // 'shown', 'dim' or 'hide' (while the path plays, playback.js)
  }
  /** The trees 'shown', 'dim' (faint) or 'hide'. */
  setLook(look) {
    if (look === this.look) return;
    this.look = look;
    this.group.visible = look !== 'hide';
    for (const v of this.views) this.applyLook(v);
    this.changed = true;
  }
  applyLook(v) {
    for (const m of [v.lines.material, v.points.material]) {
      m.transparent = this.look === 'dim';
      m.opacity = this.look === 'dim' ? 0.12 : 1;
      m.depthWrite = this.look !== 'dim';
      m.needsUpdate = true;
    }
  }
  /** 'auto' (nodes drawn up to AUTO_NODES per tree: a software renderer spends most of a frame
   * on point sprites), 'on' or 'off'. Edges are always drawn. */
  setShowNodes(mode) {
    this.showNodes = mode;
    for (const v of this.views) this.updateNodes(v);
  }
  updateNodes(v) {
    const show = this.showNodes === 'on' || (this.showNodes === 'auto' && v.count <= AUTO_NODES);
    if (show !== v.showPoints) this.changed = true;
    v.showPoints = show;
  }
  clear(generation) {
    for (const v of this.views) v.dispose(this.group);
    this.views = [];
    this.generation = generation;
    this.changed = true;
  }
  add(batch) {
    if (batch.generation !== this.generation) return true; // an old generation's leftovers
    while (this.views.length <= batch.tree) {
      this.views.push(new TreeView(this.group, this.views.length));
      this.applyLook(this.views[this.views.length - 1]);
    }
    const v = this.views[batch.tree];
    const ok = v.add(batch, this.colourBy);
    this.updateNodes(v);
    return ok;
  }
  setColourBy(mode) {
    this.colourBy = mode;
    for (const v of this.views) v.recolour(mode);
    this.changed = true;
  }
  /** Draw ranges for a frame: 'all', 'new' or 'thinned' (to about `budget` edges in all). */
  setRange(mode, budget = Infinity) {
    const stride = mode === 'thinned' ? 2 ** Math.ceil(Math.log2(Math.max(1, this.edgeCount() / budget))) : 1;
    for (const v of this.views) v.setRange(mode, stride);
  }
  markDrawn() {
    for (const v of this.views) v.markDrawn();
    this.changed = false;
  }
  hasNew() { return this.views.some((v) => v.edges > v.drawnEdges || v.count > v.drawnNodes); }
  edgeCount() { return this.views.reduce((n, v) => n + v.edges, 0); }
  thinnedCount() { return this.views.reduce((n, v) => n + v.thinnedEdges, 0); }
  counts() {
    const bySource = [0, 0, 0, 0];
    let nodes = 0, edges = 0;
    for (const v of this.views) {
      nodes += v.count;
      edges += v.edges;
      for (let i = 0; i < v.count; ++i) bySource[v.sources[i]]++;
    }
    return { nodes, edges, bySource };
  }
  /** The positions of the operator nodes of every tree, in order. */
  operatorNodes() {
    const out = [];
    for (const v of this.views) {
      for (let i = 0; i < v.count; ++i) {
        if (v.sources[i] === 2) out.push([v.nodePositions[3 * i], v.nodePositions[3 * i + 1],
          v.nodePositions[3 * i + 2]]);
      }
    }
    return out;
  }
}
