// How each obstacle is drawn: shown or hidden, opaque or transparent (with its opacity), and the
// views that override that: x-ray (every shown obstacle see-through, the part, the path and the
// trees in front of them), isolation (one obstacle alone) and the automatic x-ray of the obstacles
// that hide the part (camera-framing.js). An obstacle drawn see-through goes to the dynamic layer,
// an opaque one to the static layer's obstacles (layers.js); the section planes cut them all
// (section-planes.js). The choices (not the automatic x-ray) are kept per problem in the browser's
// localStorage, so that they survive a reconnect and a reload.

/** The opacity of an obstacle in x-ray, and of one that hides the part. */
export const XRAY_OPACITY = 0.15;

const storageKey = (problem) => `tandem-view:${problem}`;

export class ObstacleLooks {
  /**
   * @param view the SceneView (its obstacle meshes, its layers, its part and path)
   * @param changed () => void: the picture changed
   */
  constructor(view, changed) {
    this.view = view;
    this.changed = changed;
    this.problem = null;
    this.looks = new Map(); // name -> { shown, transparent, opacity }
    this.isolated = null; // a name, or null
    this.xray = false;
    this.hiding = new Set(); // names of the obstacles that hide the part (automatic x-ray)
    this.autoXray = true;
    this.listeners = [];
  }

  /** The scene's obstacles are loaded: their looks as last chosen for this problem. */
  load(problem) {
    this.problem = problem;
    for (const m of this.view.obstacleMeshes) {
      const base = m.material.userData.baseOpacity;
      this.looks.set(m.name, { shown: true, transparent: base < 1, opacity: base < 1 ? base : 0.3 });
    }
    this.restore();
    this.apply();
  }

  /** Called with no argument after every change (the objects panel redraws itself). */
  onChange(listener) { this.listeners.push(listener); }

  look(name) { return this.looks.get(name); }

  set(name, change) {
    Object.assign(this.looks.get(name), change);
    this.apply();
  }

  /** One obstacle alone (null: all again). */
  isolate(name) {
    this.isolated = name;
    this.apply();
  }

  setXray(on) {
    this.xray = on;
    this.apply();
  }

  setAutoXray(on) {
    this.autoXray = on;
    if (!on) this.hiding.clear();
    this.apply();
  }

  /** The obstacles that hide the part now (camera-framing.js); redrawn only if that changed. */
  setHiding(names) {
    const next = this.autoXray ? new Set(names) : new Set();
    if (next.size === this.hiding.size && [...next].every((n) => this.hiding.has(n))) return;
    this.hiding = next;
    this.apply();
  }

  /** Whether an obstacle is drawn, and with which opacity (1: opaque). */
  effective(name) {
    const l = this.looks.get(name);
    const shown = l.shown && (this.isolated === null || this.isolated === name);
    if (!shown) return { shown: false, opacity: 0 };
    if (this.xray || this.hiding.has(name)) return { shown: true, opacity: Math.min(XRAY_OPACITY, l.transparent ? l.opacity : 1) };
    return { shown: true, opacity: l.transparent ? l.opacity : 1 };
  }

  /** Puts every obstacle in its layer with its material; the part and path in front in x-ray. */
  apply() {
    const { view } = this;
    for (const m of view.obstacleMeshes) {
      const { shown, opacity } = this.effective(m.name);
      m.visible = shown;
      m.material.opacity = opacity;
      m.material.transparent = opacity < 1;
      m.material.depthWrite = opacity >= 1;
      m.material.needsUpdate = true;
      view.placeObstacle(m, opacity < 1);
    }
    view.setInFront(this.xray);
    this.save();
    this.changed();
    for (const listener of this.listeners) listener();
  }

  save() {
    if (!this.problem) return;
    const state = { objects: Object.fromEntries(this.looks), isolated: this.isolated, xray: this.xray, autoXray: this.autoXray };
    try { localStorage.setItem(storageKey(this.problem), JSON.stringify(state)); } catch { /* private mode */ }
  }

  restore() {
    let state = null;
    try { state = JSON.parse(localStorage.getItem(storageKey(this.problem)) ?? 'null'); } catch { state = null; }
    if (!state || typeof state !== 'object') return;
    for (const [name, l] of Object.entries(state.objects ?? {})) {
      const look = this.looks.get(name);
      if (!look || !l || typeof l !== 'object') continue;
      look.shown = l.shown !== false;
      look.transparent = l.transparent === true;
      if (Number.isFinite(l.opacity)) look.opacity = Math.min(1, Math.max(0.05, l.opacity));
    }
    this.isolated = this.looks.has(state.isolated) ? state.isolated : null;
    this.xray = state.xray === true;
    this.autoXray = state.autoXray !== false;
  }
}
