// The tuning panel: the controls of the session planner's live tunables, built from what the
// server announces (hello.parameters; none from an old server that announces nothing), kept at
// the values of the `status` messages' settings, sent as `params` messages when changed (after a
// check against the announced bounds); the pause, resume, step and reset commands; the save links.
import { $ } from './dom.js';
import { parameterControl } from './parameter-controls.js';

export class TuningPanel {
  /** @param connection the Connection (send, withToken) */
  constructor(connection) {
    this.connection = connection;
    this.controls = [];
    for (const c of ['pause', 'resume', 'step', 'reset']) $(c).onclick = () => connection.send({ type: 'command', command: c });
    $('save-path').href = connection.withToken('/api/path');
    $('save-session').href = connection.withToken('/api/session');
  }

  /** The controls for these parameters (hello.parameters), in their order, replacing the last. */
  build(parameters) {
    this.note('');
    this.controls = (Array.isArray(parameters) ? parameters : []).map((p) => parameterControl(p));
    for (const c of this.controls) c.input.addEventListener('change', () => this.changed(c));
    $('tuning-controls').replaceChildren(...this.controls.map((c) => c.label));
  }

  changed(control) {
    const { value, problem } = control.read();
    if (problem) {
      this.note(problem, 'bad');
      return;
    }
    this.note('');
    const { name } = control.parameter;
    const message = { type: 'params', [name]: value };
    // Automatic alpha: turning it off, or setting alpha by hand, pins alpha (where it is now).
    if (name === 'auto_alpha' && value === false && typeof this.alphaNow === 'number') {
      message.alpha = Math.round(this.alphaNow * 1000) / 1000;
    }
    if (name === 'alpha' && this.autoAlpha) message.auto_alpha = false;
    this.connection.send(message);
  }

  note(text, cls = '') {
    const el = $('tuning-note');
    el.textContent = text;
    el.className = `note ${cls}`;
  }

  /** A `status` message: its settings (by parameter name) shown but where the user is; a replay
   * takes no tuning. */
  onStatus(m) {
    const settings = m.settings ?? {};
    this.alphaNow = m.alpha;
    this.autoAlpha = settings.auto_alpha === true;
    for (const c of this.controls) {
      if (document.activeElement === c.input || !Object.hasOwn(settings, c.parameter.name)) continue;
      c.show(settings[c.parameter.name]);
    }
    if (m.replay) for (const el of $('tuning').querySelectorAll('input, button, select')) el.disabled = true;
  }
}
