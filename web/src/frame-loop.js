// The frame loop: each animation frame moves the part by the operator's devices or to the
// operator's configuration, and draws a frame only when something changed, at most maxfps times a
// second (0: no cap), so that a software renderer leaves the planner its core. It keeps the
// latest `operator` message (the contact plane, the guidance force) and counts frames. The frames
// come from the renderer's animation loop: the window's, or the headset's while in VR, where every
// frame is drawn.

export class FrameLoop {
  /**
   * @param view the SceneView
   * @param maxfps the cap on frames a second (0: none)
   */
  constructor(view, maxfps) {
    this.view = view;
    this.maxfps = maxfps;
    this.input = null;
    this.playback = null;
    this.xr = null;
    this.dirty = true;
    this.operator = null; // the last `operator` message
    this.operatorShown = ''; // what it shows (q, contact, plane, force)
    this.redrawAlways = false; // a frame every time, for measuring
    this.fps = 0;
    this.frames = 0;
    this.fpsFrames = 0;
    this.fpsSince = performance.now();
    this.lastFrame = performance.now();
    this.lastRender = 0;
    this.updates = []; // (now) => void, each animation frame, before drawing
    this.drawn = []; // () => void, after each frame drawn
    this.fpsListeners = []; // (fps) => void, each second
    this.frame = this.frame.bind(this);
  }

  /** Runs `fn(now)` each animation frame, before the frame is drawn (if it is). */
  onUpdate(fn) { this.updates.push(fn); }

  /** Runs `fn()` after each frame drawn. */
  onDrawn(fn) { this.drawn.push(fn); }

  /** Runs `fn(fps)` each second, with the frames drawn over that second. */
  onFps(fn) { this.fpsListeners.push(fn); }

  /** Something changed: the next frame is drawn. */
  touch() { this.dirty = true; }

  /** An `operator` message: a frame is drawn if what it shows changed (not its time alone). */
  setOperator(m) {
    const shown = JSON.stringify([m.q, m.contact, m.plane, m.force]);
    if (shown !== this.operatorShown) this.dirty = true;
    this.operatorShown = shown;
    this.operator = m;
  }

  /** Runs the loop, with the OperatorInput, the Playback and the VrOperator. */
  start(input, playback, xr) {
    this.input = input;
    this.playback = playback;
    this.xr = xr;
    this.view.layers.renderer.setAnimationLoop(this.frame);
  }

  frame(now) {
    const dt = Math.min((now - this.lastFrame) / 1000, 0.1);
    this.lastFrame = now;
    this.update(dt, now);
    if (!this.due(now)) return;
    this.lastRender = now;
    this.dirty = false;
    this.view.showOperatorCues(this.operator);
    this.playback.advance(dt);
    this.view.render(now);
    for (const fn of this.drawn) fn();
    ++this.frames;
    ++this.fpsFrames;
  }

  /** What moves without a frame drawn: the part, the turning camera, the frame rate. */
  update(dt, now) {
    const { view, input } = this;
    input.integrate(dt, now);
    if (view.orbit.autoRotate) view.orbit.update(dt);
    input.follow(this.operator, now);
    this.xr.update(now, this.operator);
    for (const fn of this.updates) fn(now);
    if (now - this.fpsSince >= 1000) {
      this.fps = (1000 * this.fpsFrames) / (now - this.fpsSince);
      this.fpsFrames = 0;
      this.fpsSince = now;
      for (const fn of this.fpsListeners) fn(this.fps);
    }
  }

  /** Whether a frame is drawn now: something to draw, and not within the cap's interval. */
  due(now) {
    if (this.xr.presenting) return true;
    const wanted = this.dirty || this.input.dragging || this.playback.playing || this.redrawAlways
      || this.view.layers.needsFrame(now);
    return wanted && !(this.maxfps > 0 && now - this.lastRender < 1000 / this.maxfps - 2);
  }
}
