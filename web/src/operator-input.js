// The browser's operator inputs: the drag gizmo (move or rotate, keys T and R), the keyboard, a
// gamepad and a WebHID SpaceMouse (the devices in inputs.js), and the choice of the input in
// control. The part's pose goes to the server as a `pose` message, at most every 16 ms while it
// moves, with an id whose status comes back with the input-to-node latency.
import * as THREE from 'three';
import { Keyboard, Gamepads, SpaceMouseHID } from './inputs.js';
import { $ } from './dom.js';

/** How long the part stays where the browser put it before it follows the operator again. */
const HOLD_MS = 300;

/** Sends poses with ids and measures, per id, the time until the status reporting its node. */
class PoseSender {
  constructor(send) {
    this.send = send;
    this.id = 0;
    this.sentAt = new Map();
    this.lastSent = 0;
    this.latencies = [];
  }

  post(q, now) {
    const id = ++this.id;
    this.sentAt.set(id, now);
    if (this.sentAt.size > 500) this.sentAt.delete(this.sentAt.keys().next().value);
    this.send({ type: 'pose', q, id });
    this.lastSent = now;
  }

  /** Whether a pose may go now (not within 16 ms of the last). */
  due(now) { return now - this.lastSent > 16; }

  /** A `status` message: its input_latency_id, if one of ours, closes a measurement. */
  onStatus(m) {
    const id = m.input_latency_id;
    if (!id || !this.sentAt.has(id)) return;
    this.latencies.push({ id, server_ms: m.input_latency_ms, round_trip_ms: performance.now() - this.sentAt.get(id) });
    this.sentAt.delete(id);
  }
}

export class OperatorInput {
  /**
   * @param view the SceneView (its part, gizmo, orbit controls, extent)
   * @param send (message) => void: to the server
   * @param touch () => void: the picture changed
   * @param notify (text, cls) => void: a message for the panel
   */
  constructor(view, { send, touch, notify }) {
    this.view = view;
    this.send = send;
    this.touch = touch;
    this.poses = new PoseSender(send);
    this.hid = new SpaceMouseHID((text) => notify(text, 'ok'));
    this.devices = [new Keyboard(window), new Gamepads(), this.hid];
    this.dragging = false;
    this.holding = false; // a VR controller holds the part (xr.js)
    this.inputInControl = null; // the status's input
    this.drivingUntil = 0;
    this.wireGizmo();
    this.wireControls(notify);
  }

  get latencies() { return this.poses.latencies.slice(); }

  /** Whether the browser is the input in control (the server's last status says). */
  get inControl() { return this.inputInControl === 'browser'; }

  wireGizmo() {
    const { gizmo, orbit } = this.view;
    gizmo.addEventListener('dragging-changed', (e) => {
      this.dragging = e.value;
      orbit.enabled = !e.value;
      if (!e.value) this.poses.post(this.view.partPose(), performance.now());
    });
    gizmo.addEventListener('objectChange', () => this.moved(performance.now()));
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
  }

  wireControls(notify) {
    $('input').onchange = (e) => this.send({ type: 'input', input: e.target.value });
    $('webhid').onclick = async () => {
      try { await this.hid.connect(); } catch (err) { notify(String(err.message ?? err), 'bad'); }
    };
    if (!SpaceMouseHID.available()) $('webhid').disabled = true;
  }

  /** The browser moved the part: it holds it for a while, and sends its pose if due (or at once). */
  moved(now, immediately = false) {
    this.drivingUntil = now + HOLD_MS;
    this.touch();
    if (immediately || this.poses.due(now)) this.poses.post(this.view.partPose(), now);
  }

  /** Moves the part by the devices' velocities over dt seconds. */
  integrate(dt, now) {
    const v = [0, 0, 0, 0, 0, 0];
    for (const device of this.devices) {
      const w = device.velocity();
      for (let k = 0; k < 6; ++k) v[k] += w[k];
    }
    if (v.every((x) => x === 0)) return;
    const { part, extent } = this.view;
    const speed = 0.1 * extent, turn = 1.2;
    part.position.add(new THREE.Vector3(v[0], v[1], v[2]).multiplyScalar(speed * dt));
    const w = new THREE.Vector3(v[3], v[4], v[5]);
    const angle = w.length() * turn * dt;
    if (angle > 0) part.quaternion.premultiply(new THREE.Quaternion().setFromAxisAngle(w.normalize(), angle));
    this.moved(now);
  }

  /** The part at the operator's configuration (an `operator` message), unless the browser holds it. */
  follow(op, now) {
    if (op && !this.dragging && !this.holding && now > this.drivingUntil) this.view.setPartPose(op.q);
  }

  /** A `status` message: the input in control and those available; a replay takes no input. */
  onStatus(m) {
    this.poses.onStatus(m);
    this.inputInControl = m.input;
    const select = $('input');
    if (m.input && document.activeElement !== select) select.value = m.input;
    select.querySelector('[value=spacemouse]').disabled = !m.spacemouse_available;
    select.querySelector('[value=simulated]').disabled = !m.simulated_available;
    if (m.replay) select.disabled = true;
  }
}
