// The VR operator (WebXR, three.js): an "enter VR" button, shown where the browser offers
// immersive VR. In the headset the scene is at real scale, its z up turned to WebXR's y up, its
// bounds' near edge 0.3 m in front of the user and the bounds' floor on the floor. A controller's
// grip (squeeze) grabs the part wherever the hand is and moves it with the hand, as a 6D device;
// opening the grip releases it where it is, and squeezing again grabs it anew from where the hand
// is then (a clutch). The planner's contact mode and the I-RRT's guidance force F_a are felt as
// pulses of the holding controller's haptic actuator (hapticActuators), and, outside VR, as a
// gamepad's rumble (vibrationActuator) while the browser is the input in control.
import * as THREE from 'three';
import { $ } from './dom.js';

/** One pulse's length and the shortest time between two, in milliseconds. */
const PULSE_MS = 50;
/** How far in front of the user the bounds' near edge is placed, in metres. */
const IN_FRONT = 0.3;
/** A contact pulse's strength; the guidance force's grows to 1 at a tenth of the scene's extent. */
const CONTACT_STRENGTH = 0.4;

/** The strength (0 to 1) the operator's cues are felt with: contact mode, the guidance force. */
export function cueStrength(op, extent) {
  if (!op) return 0;
  const f = op.force ? Math.hypot(op.force[0], op.force[1], op.force[2]) / (0.1 * extent) : 0;
  return Math.min(1, Math.max(op.contact ? CONTACT_STRENGTH : 0, f));
}

export class VrOperator {
  /**
   * @param view the SceneView (its renderer, scene, part, bounds and extent)
   * @param input the OperatorInput (sends the part's pose as the browser's)
   * @param notify (text, cls) => void: a message for the panel
   */
  constructor(view, input, { notify }) {
    this.view = view;
    this.input = input;
    this.notify = notify;
    this.renderer = view.layers.renderer;
    this.session = null;
    this.grips = [0, 1].map((i) => this.renderer.xr.getControllerGrip(i));
    this.holding = null; // { grip, source, offset }: the grip holding the part
    this.lastPulse = -Infinity;
    this.pulses = 0; // haptic pulses sent (for the tests)
    this.rumbles = 0; // gamepad rumbles played
    for (const grip of this.grips) {
      grip.addEventListener('connected', (e) => { grip.userData.source = e.data; });
      grip.addEventListener('disconnected', () => { if (this.holding?.grip === grip) this.release(); });
      grip.addEventListener('squeezestart', () => this.grab(grip));
      grip.addEventListener('squeezeend', () => { if (this.holding?.grip === grip) this.release(); });
    }
    this.wireButton();
  }

  get presenting() { return this.renderer.xr.isPresenting; }

  async wireButton() {
    const button = $('enter-vr');
    const supported = await navigator.xr?.isSessionSupported?.('immersive-vr').catch(() => false);
    button.hidden = !supported;
    button.onclick = () => (this.session ? this.session.end() : this.enter());
  }

  async enter() {
    try {
      const session = await navigator.xr.requestSession('immersive-vr', { optionalFeatures: ['local-floor'] });
      this.renderer.xr.enabled = true;
      this.renderer.xr.setReferenceSpaceType('local-floor');
      await this.renderer.xr.setSession(session);
      this.session = session;
      session.addEventListener('end', () => this.left());
      this.placeScene();
      this.view.gizmo.getHelper().visible = false; // the hand moves the part in VR
      $('enter-vr').textContent = 'leave VR';
      this.notify('in VR: squeeze a controller\'s grip to hold the part, open it to let go', 'ok');
    } catch (err) {
      this.notify(`VR: ${err.message ?? err}`, 'bad');
    }
  }

  left() {
    this.release();
    this.session = null;
    this.renderer.xr.enabled = false;
    this.view.scene.position.set(0, 0, 0);
    this.view.scene.rotation.set(0, 0, 0);
    this.view.scene.updateMatrixWorld(true);
    this.view.gizmo.getHelper().visible = true;
    this.view.layers.invalidate();
    $('enter-vr').textContent = 'enter VR';
  }

  /** The scene (z up) in WebXR's floor space (y up): near edge of the bounds in front, floor down. */
  placeScene() {
    const { scene, bounds } = this.view;
    const cx = 0.5 * (bounds.min[0] + bounds.max[0]);
    // A rotation of -90 degrees about x takes (x, y, z) to (x, z, -y): the scene's y goes away from
    // the user (-z), its z up (y).
    scene.rotation.set(-Math.PI / 2, 0, 0);
    scene.position.set(-cx, -bounds.min[2], bounds.min[1] - IN_FRONT);
    scene.updateMatrixWorld(true);
  }

  /** Where a scene point is in WebXR's floor space (for the tests, which place the controllers). */
  xrPointOf(x, y, z) {
    return new THREE.Vector3(x, y, z).applyMatrix4(this.view.scene.matrixWorld).toArray();
  }

  /** The grip's pose in the scene's frame. */
  gripInScene(grip) {
    const toScene = this.view.scene.matrixWorld.clone().invert();
    return toScene.multiply(grip.matrix);
  }

  grab(grip) {
    if (!this.presenting) return;
    const { part } = this.view;
    const partMatrix = new THREE.Matrix4().compose(part.position, part.quaternion, new THREE.Vector3(1, 1, 1));
    const offset = this.gripInScene(grip).invert().multiply(partMatrix);
    this.holding = { grip, source: grip.userData.source, offset };
    this.input.holding = true;
  }

  release() {
    if (!this.holding) return;
    this.holding = null;
    this.input.holding = false;
    this.input.moved(performance.now(), true);
  }

  /** Each frame: the held part follows the hand; the operator's cues are felt. */
  update(now, op) {
    if (this.holding) {
      const m = this.gripInScene(this.holding.grip).multiply(this.holding.offset);
      const scale = new THREE.Vector3();
      m.decompose(this.view.part.position, this.view.part.quaternion, scale);
      this.input.moved(now);
    }
    this.feel(now, op);
  }

  feel(now, op) {
    const strength = cueStrength(op, this.view.extent);
    if (strength <= 0 || now - this.lastPulse < PULSE_MS) return;
    if (this.presenting) {
      const actuator = this.holding?.source?.gamepad?.hapticActuators?.[0];
      if (!actuator?.pulse) return;
      this.lastPulse = now;
      actuator.pulse(strength, PULSE_MS);
      ++this.pulses;
      return;
    }
    if (!this.input.inControl) return;
    const pads = navigator.getGamepads ? [...navigator.getGamepads()] : [];
    for (const pad of pads) {
      if (!pad?.vibrationActuator?.playEffect) continue;
      this.lastPulse = now;
      pad.vibrationActuator.playEffect('dual-rumble',
        { duration: PULSE_MS, strongMagnitude: strength, weakMagnitude: 0.5 * strength }).catch(() => {});
      ++this.rumbles;
    }
  }
}
