// The camera's framing: "frame the part", "frame the path", "frame everything" (keys F, G, H);
// following the part while it moves, or the path's ghost while the path plays; and the part kept
// visible: the obstacles between the camera and the part are found (rays to the part's centre and
// its box's corners, every AUTO_XRAY_MS) and drawn see-through (obstacle-looks.js).
import * as THREE from 'three';
import { boxCorners } from './scene-view.js';

const AUTO_XRAY_MS = 100;

export class CameraFraming {
  /**
   * @param view the SceneView
   * @param looks the ObstacleLooks (for the automatic x-ray)
   * @param sections the SectionPlanes (what they cut away hides nothing)
   * @param playback the Playback (the ghost to follow while it plays)
   * @param changed () => void: the picture changed
   */
  constructor(view, { looks, sections, playback, changed }) {
    this.view = view;
    this.looks = looks;
    this.sections = sections;
    this.playback = playback;
    this.changed = changed;
    this.follow = false;
    this.followed = null; // the position followed at the last frame
    this.lastCheck = -Infinity;
  }

  /** Frames what `what` names: 'part', 'path' or 'all'. */
  frame(what) {
    const { view } = this;
    const box = new THREE.Box3();
    if (what === 'part') box.setFromObject(view.part);
    else if (what === 'path' && view.pathLine) {
      box.setFromPoints(view.pathLine.userData.points);
      box.expandByObject(view.part);
    } else {
      box.set(new THREE.Vector3(...view.bounds.min), new THREE.Vector3(...view.bounds.max));
      for (const m of view.obstacleMeshes) if (m.visible && m.name !== 'floor') box.expandByObject(m);
    }
    view.frameBox(box, what === 'part' ? 0.35 : 0.8);
    view.layers.cameraMoved(performance.now());
    this.followed = null;
    this.changed();
  }

  /** What is followed now: the ghost while the path plays, else the part. */
  target() { return this.playback.playing && this.view.pathGhost.visible ? this.view.pathGhost : this.view.part; }

  /** Each frame: the camera follows (if asked), and the obstacles hiding the part are found. */
  update(now) {
    const target = this.target().position;
    if (this.follow && this.followed) {
      const offset = target.clone().sub(this.followed);
      if (offset.lengthSq() > 0) {
        this.view.shiftCamera(offset);
        this.view.layers.cameraMoved(now);
        this.changed();
      }
    }
    this.followed = target.clone();
    if (now - this.lastCheck >= AUTO_XRAY_MS) {
      this.lastCheck = now;
      this.findHiding();
    }
  }

  /** The obstacles nearer to the camera than the part's centre or a corner of its box. */
  findHiding() {
    const { view, looks } = this;
    if (!looks.autoXray || looks.xray) { looks.setHiding([]); return; }
    const object = this.target();
    const box = new THREE.Box3().setFromObject(object);
    if (box.isEmpty()) return;
    const points = [box.getCenter(new THREE.Vector3()), ...boxCorners(box)];
    const eye = view.camera.position;
    const shown = view.obstacleMeshes.filter((m) => looks.effective(m.name).shown);
    const ray = new THREE.Raycaster();
    const hits = points.map((p) => {
      const dir = p.clone().sub(eye);
      ray.set(eye, dir.clone().normalize());
      ray.far = dir.length() * 0.999;
      return ray.intersectObjects(shown, false).filter((h) => !this.sections.cutsAway(h.point)).map((h) => h.object.name);
    });
    // Hidden only if every ray is blocked: a part merely behind an edge stays as it is.
    const blocked = hits.every((names) => names.length > 0);
    const hiding = new Set(hits.flat());
    looks.setHiding(blocked ? [...hiding] : []);
  }
}
