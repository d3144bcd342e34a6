// The panel's status: the problem's name, the connection, the session's status table (from the
// server's `status` messages, and the viewer's own frame rate) and the message line.
import { $ } from './dom.js';

const fmt = (x, d = 0) => (x === undefined ? '—' : Number(x).toLocaleString('en', {
  maximumFractionDigits: d, minimumFractionDigits: d }));

export class StatusPanel {
  /** @param viewer () => {fps, drawnEdges, edges}: how the page draws (for the table's last row) */
  constructor(viewer) {
    this.viewer = viewer;
    this.status = null; // the last status message
    this.errors = []; // what the server refused, in order
  }

  setProblem(name) { $('problem').textContent = name; }

  setConnection(text, cls) {
    const el = $('connection');
    el.textContent = text;
    el.className = cls;
  }

  showMessage(text, cls = '') {
    const el = $('message');
    el.textContent = text;
    el.className = `note ${cls}`;
  }

  /** An `error` message: the server refused what the page sent. */
  refused(message) {
    this.errors.push(message);
    this.showMessage(`refused: ${message}`, 'bad');
  }

  /** The status in a few lines (drawn over a recording, recorder.js). */
  overlayLines() {
    const m = this.status;
    const lines = [`tandem ${$('problem').textContent}`];
    if (!m) return lines;
    const src = m.nodes_by_source ?? [0, 0, 0, 0];
    return [...lines, `${m.status} · ${m.mode} · ${fmt(m.elapsed_s, 1)} s`,
      `${fmt(m.nodes)} nodes (random ${fmt(src[1])}, operator ${fmt(src[2])}, contact ${fmt(src[3])})`,
      typeof m.alpha === 'number' ? `α ${fmt(m.alpha, 2)}` : ''].filter(Boolean);
  }

  /** The viewer's own row, each second (the session's rows wait for its next status). */
  refresh() { if (this.status) this.show(this.status); }

  /** A `status` message. */
  show(m) {
    this.status = m;
    const src = m.nodes_by_source ?? [0, 0, 0, 0];
    const { fps, drawnEdges, edges } = this.viewer();
    const rows = [
      ['status', `${m.status}${m.paused ? ' (paused)' : ''}`],
      ['mode', `${m.mode} (${m.planner})`],
      ['elapsed', `${fmt(m.elapsed_s, 1)} s`],
      ['iterations/s', fmt(m.iterations_per_s)],
      ['iterations', fmt(m.iterations)],
      ['nodes', fmt(m.nodes)],
      ['edges', fmt(m.edges)],
      ['random / operator / contact', `${fmt(src[1])} / ${fmt(src[2])} / ${fmt(src[3])}`],
      ['authority α', typeof m.alpha === 'number'
        ? `${fmt(m.alpha, 2)} ${m.settings?.auto_alpha ? '(automatic)' : '(pinned)'}` : '—'],
      ['collision checks', fmt(m.collision_checks)],
      ['operator loop', m.operator_rate_hz === undefined ? '—' : `${fmt(m.operator_rate_hz)} Hz`],
      ['input', m.input],
      ['input → node', m.input_latency_id ? `${fmt(m.input_latency_ms, 1)} ms` : '—'],
      // The frames drawn over the last second: none when nothing changed.
      ['viewer', `${fps < 0.5 ? 'idle' : `${fmt(fps)} fps`}${drawnEdges < edges ? `, ${fmt(drawnEdges)} edges while turning` : ''}`],
    ];
    $('status').innerHTML = rows.map(([k, v]) => `<tr><td>${k}</td><td>${v}</td></tr>`).join('');
  }
}
