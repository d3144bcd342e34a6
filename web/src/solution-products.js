// What the server derives from the solution (src/tandem/web/solution_products.hpp): the path
// coloured by its clearance (certified per motion, red where the part comes closest, green where it
// stays farthest), the part's motion envelope on demand, and the downloads (animation .glb, its
// offline page .html, the envelope .stl). A product still being computed answers 503: ask again.
import * as THREE from 'three';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { $ } from './dom.js';

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** The product at `url` once it is ready (polling while the server computes it), or null if the
 * solution changed meanwhile (`current()` false) or there is none. */
async function fetchWhenReady(url, current, as) {
  while (current()) {
    const res = await fetch(url, { credentials: 'same-origin' });
    if (res.ok) return as === 'json' ? res.json() : res.arrayBuffer();
    if (res.status !== 503) throw new Error(`${url}: ${(await res.text()).trim()}`);
    await sleep(500);
  }
  return null;
}

/** Red (0) through yellow to green (at `scale` and beyond). */
export function clearanceColour(d, scale) {
  const s = scale > 0 ? Math.min(Math.max(d / scale, 0), 1) : 1;
  return new THREE.Color().setHSL((s * 120) / 360, 0.85, 0.5);
}

/** The line's points and colours: each state (its distance), and inside each motion the point
 * where it comes closest (its certified minimum), so the colour runs along the motion. */
export function clearancePolyline(path, clearance) {
  const scale = Math.max(...clearance.states.map((s) => s.distance), 1e-12);
  const points = [], colours = [];
  const add = (p, d) => { points.push(new THREE.Vector3(...p)); colours.push(clearanceColour(d, scale)); };
  path.forEach((q, i) => {
    add(q.slice(0, 3), clearance.states[i].distance);
    const m = clearance.segments[i];
    if (!m) return;
    const b = path[i + 1];
    add([0, 1, 2].map((k) => q[k] + m.at * (b[k] - q[k])), m.lower);
  });
  return { points, colours, scale };
}

export class SolutionProducts {
  constructor(view, { touch, notify }) {
    this.view = view;
    this.touch = touch;
    this.notify = notify;
    this.generation = 0;
    this.clearance = null;
    this.envelope = null;
    $('show-envelope').onchange = (e) => this.showEnvelope(e.target.checked);
  }

  clear() {
    this.generation += 1;
    this.clearance = null;
    this.view.setEnvelope(null);
    this.envelope = null;
    $('show-envelope').checked = false;
    $('clearance-note').textContent = '';
  }

  /** A new solution: its clearance colours the line. */
  async show(path) {
    this.clear();
    const generation = this.generation, current = () => generation === this.generation;
    try {
      const c = await fetchWhenReady('/api/clearance', current, 'json');
      if (!c || !current()) return;
      this.clearance = c;
      const line = clearancePolyline(path, c);
      this.view.setSolutionLine(path, line);
      const worst = c.segments.reduce((w, s) => (s.lower < w.lower ? s : w), c.segments[0] ?? c.states[0]);
      $('clearance-note').textContent = `clearance: at least ${(1000 * c.min_clearance).toPrecision(3)} mm`
        + (worst?.obstacle ? `, near ${worst.obstacle}` : '')
        + ` (red 0 → green ${(1000 * line.scale).toPrecision(3)} mm)`;
      this.touch();
    } catch (err) { this.notify(String(err.message ?? err), 'bad'); }
  }

  async showEnvelope(on) {
    if (!on) { this.view.setEnvelope(null); this.touch(); return; }
    const generation = this.generation, current = () => generation === this.generation;
    if (!this.envelope) {
      this.notify('computing the motion envelope…');
      try {
        const bytes = await fetchWhenReady('/api/envelope.stl', current, 'buffer');
        if (!bytes || !current()) return;
        this.envelope = new STLLoader().parse(bytes);
        this.notify(`motion envelope: ${this.envelope.attributes.position.count / 3} triangles`, 'ok');
      } catch (err) { this.notify(String(err.message ?? err), 'bad'); return; }
    }
    if ($('show-envelope').checked) this.view.setEnvelope(this.envelope);
    this.touch();
  }
}
