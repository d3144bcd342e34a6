// The solution: its line in the scene, and its playback (a ghost of the part going along it, eight
// seconds from start to goal) with the play button and the scrubber; the trees are shown, dimmed
// or hidden while it plays. Played once from the start (for a recording), it stops at the goal.
import { $ } from './dom.js';

export class Playback {
  /**
   * @param view the SceneView
   * @param touch () => void: the picture changed
   * @param notify (text, cls) => void: a message for the panel
   * @param products the SolutionProducts (clearance colours, envelope)
   */
  constructor(view, { touch, notify, products }) {
    this.view = view;
    this.products = products;
    this.touch = touch;
    this.notify = notify;
    this.solution = [];
    this.playing = false;
    this.t = 0; // in [0, 1]
    this.treesWhilePlaying = 'dim';
    this.onEnd = null; // played once: told at the goal
    $('play').onclick = () => this.setPlaying(!this.playing);
    $('scrub').oninput = (e) => {
      this.touch();
      this.setPlaying(false);
      this.t = e.target.value / 1000;
      this.showAt(this.t);
    };
  }

  /** No solution (a new session, a reset). */
  clear() {
    this.touch();
    this.solution = [];
    this.view.setSolutionLine(null);
    this.products.clear();
    this.setPlaying(false);
    $('path-box').hidden = true;
  }

  /** A `solution` message's path (configurations). */
  show(path) {
    this.clear();
    if (!path.length) return;
    this.solution = path;
    this.view.setSolutionLine(path);
    this.products.show(path);
    $('path-box').hidden = false;
    this.notify(`solved: a path of ${path.length} states`, 'ok');
  }

  /** The ghost at t in [0, 1] along the path. */
  showAt(t) {
    const s = this.solution;
    if (s.length < 1) return;
    const x = t * (s.length - 1);
    const i = Math.min(Math.floor(x), s.length - 2), f = x - i;
    this.view.showPathGhost(s[Math.max(i, 0)], s[Math.min(i + 1, s.length - 1)], f);
  }

  setPlaying(on) {
    this.playing = on;
    if (!on) this.onEnd = null;
    $('play').textContent = on ? 'pause path' : 'play path';
    this.view.trees.setLook(on ? this.treesWhilePlaying : 'shown');
    this.view.layers.invalidate();
    this.touch();
  }

  /** How the trees look while the path plays: 'shown', 'dim' or 'hide'. */
  setTreesWhilePlaying(look) {
    this.treesWhilePlaying = look;
    if (this.playing) this.setPlaying(true);
  }

  /** Plays the path once from its start; `onEnd` is told at the goal, where it stops. */
  playFromStart(onEnd) {
    this.t = 0;
    this.setPlaying(true);
    this.onEnd = onEnd;
  }

  /** A frame's step of the playback, dt seconds on. */
  advance(dt) {
    if (!this.playing || this.solution.length <= 1) return;
    if (this.onEnd && this.t + dt / 8 >= 1) {
      const end = this.onEnd;
      this.t = 1;
      this.showAt(1);
      this.setPlaying(false);
      end();
      return;
    }
    this.t = (this.t + dt / 8) % 1;
    $('scrub').value = String(Math.round(this.t * 1000));
    this.showAt(this.t);
  }
}
