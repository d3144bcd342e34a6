// The browser's operator inputs besides the drag gizmo: the keyboard, the Gamepad API and a
// SpaceMouse through WebHID. Each gives a velocity (6 numbers, each in [-1, 1]: x y z translation,
// rx ry rz rotation, world frame, z up) that the viewer integrates into the part's pose.

const KEYS = {
  KeyD: [0, 1], KeyA: [0, -1], KeyW: [1, 1], KeyS: [1, -1], KeyE: [2, 1], KeyQ: [2, -1],
  KeyL: [5, -1], KeyJ: [5, 1], KeyI: [3, -1], KeyK: [3, 1], KeyO: [4, 1], KeyU: [4, -1],
};

export class Keyboard {
  constructor(target) {
    this.down = new Set();
    target.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (KEYS[e.code]) { this.down.add(e.code); e.preventDefault(); }
    });
    target.addEventListener('keyup', (e) => this.down.delete(e.code));
    window.addEventListener('blur', () => this.down.clear());
  }
  velocity() {
    const v = [0, 0, 0, 0, 0, 0];
    for (const code of this.down) { const [axis, sign] = KEYS[code]; v[axis] += sign; }
    return v;
  }
}

const DEADZONE = 0.15;
const dz = (x) => (Math.abs(x) < DEADZONE ? 0 : x);

export class Gamepads {
  velocity() {
    const v = [0, 0, 0, 0, 0, 0];
    const pads = navigator.getGamepads ? navigator.getGamepads() : [];
    for (const pad of pads) {
      if (!pad || pad.axes.length < 4) continue;
      // Left stick: x, y; right stick: yaw and z; triggers/shoulders: roll.
      v[0] += dz(pad.axes[0]);
      v[1] -= dz(pad.axes[1]);
      v[5] -= dz(pad.axes[2]);
      v[2] -= dz(pad.axes[3]);
      if (pad.buttons[4]?.pressed) v[3] -= 1;
      if (pad.buttons[5]?.pressed) v[3] += 1;
    }
    return v;
  }
}

/**
 * A 3Dconnexion SpaceMouse through WebHID (vendor ids 0x046d, 0x256f): report 1 carries the
 * translation (int16 LE x, y, z; some models append the rotation), report 2 the rotation, report 3
 * the buttons; values about +-350. The device's y points away from the user and its z down; the
 * scene's z is up.
 */
export class SpaceMouseHID {
  constructor(onStatus) {
    this.motion = [0, 0, 0, 0, 0, 0];
    this.onStatus = onStatus;
    this.device = null;
  }
  static available() { return 'hid' in navigator; }
  async connect() {
    if (!SpaceMouseHID.available()) throw new Error('this browser has no WebHID (use Chromium)');
    const [device] = await navigator.hid.requestDevice({
      filters: [{ vendorId: 0x046d }, { vendorId: 0x256f }],
    });
    if (!device) throw new Error('no SpaceMouse chosen');
    if (!device.opened) await device.open();
    this.device = device;
    device.addEventListener('inputreport', (e) => this.report(e.reportId, e.data));
    this.onStatus(`SpaceMouse: ${device.productName}`);
  }
  report(id, data) {
    const axis = (k) => Math.max(-1, Math.min(1, data.getInt16(2 * k, true) / 350));
    if (id === 1 && data.byteLength >= 6) {
      this.motion[0] = axis(0); this.motion[1] = -axis(1); this.motion[2] = -axis(2);
      if (data.byteLength >= 12) {
        this.motion[3] = axis(3); this.motion[4] = -axis(4); this.motion[5] = -axis(5);
      }
    } else if (id === 2 && data.byteLength >= 6) {
      this.motion[3] = axis(0); this.motion[4] = -axis(1); this.motion[5] = -axis(2);
    }
  }
  velocity() { return this.device ? this.motion.slice() : [0, 0, 0, 0, 0, 0]; }
}
