// Pictures and videos of the view: a still (PNG) and a recording (MediaRecorder, WebM) of a live
// session or of the path's playback. Both are made from a copy of the view: its canvases (one, or
// the layered drawing's two, see layers.js) drawn onto one canvas after each drawn frame, with the
// status as an overlay in its top left corner if asked for.
import { $ } from './dom.js';

/** The video's frame rate, and the codecs tried in order. */
const VIDEO_FPS = 30;
const TYPES = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'];

/** A file name for the problem, the time and the extension. */
function fileName(problem, extension) {
  const stamp = new Date().toISOString().replace(/[:.]/g, '-').slice(0, 19);
  return `${problem || 'tandem'}-${stamp}.${extension}`;
}

export class Recorder {
  /**
   * @param view the SceneView (its layers' canvases)
   * @param lines () => [string]: the status overlay's lines
   * @param notify (text, cls) => void: a message for the panel
   */
  constructor(view, { lines, notify }) {
    this.view = view;
    this.lines = lines;
    this.notify = notify;
    this.problem = '';
    this.canvas = document.createElement('canvas');
    this.overlay = true; // the status drawn over the picture
    this.recorder = null;
    this.chunks = [];
    this.last = null; // { size, type, url, seconds } of the last recording
    this.startedAt = 0;
  }

  get recording() { return this.recorder !== null; }

  /** After each drawn frame: the copy of the view is brought up to date while recording. */
  frameDrawn() {
    if (this.recording) this.compose();
  }

  /** Draws the view's canvases, and the status if asked, onto the copy. */
  compose() {
    const layers = this.view.layers.canvases;
    const { width, height } = layers[0];
    if (this.canvas.width !== width || this.canvas.height !== height) Object.assign(this.canvas, { width, height });
    const g = this.canvas.getContext('2d');
    for (const c of layers) g.drawImage(c, 0, 0, width, height);
    if (!this.overlay) return;
    const lines = this.lines();
    const scale = width / this.view.layers.domElement.clientWidth || 1;
    g.font = `${Math.round(13 * scale)}px system-ui, sans-serif`;
    const lineHeight = 17 * scale, pad = 8 * scale;
    const w = Math.max(...lines.map((l) => g.measureText(l).width), 0) + 2 * pad;
    g.fillStyle = 'rgba(20, 22, 27, 0.75)';
    g.fillRect(0, 0, w, lines.length * lineHeight + 2 * pad);
    g.fillStyle = '#e4e6ea';
    lines.forEach((l, k) => g.fillText(l, pad, pad + (k + 0.8) * lineHeight));
  }

  /** A still of the view now, saved as PNG; resolves to its size in bytes. */
  async screenshot() {
    this.view.render(performance.now());
    this.compose();
    const blob = await new Promise((resolve) => this.canvas.toBlob(resolve, 'image/png'));
    this.download(blob, fileName(this.problem, 'png'));
    return blob.size;
  }

  /** Starts recording (the next drawn frames). */
  start() {
    if (this.recording) return;
    const type = TYPES.find((t) => MediaRecorder.isTypeSupported(t));
    if (!type) { this.notify('this browser cannot record WebM video', 'bad'); return; }
    this.compose();
    const stream = this.canvas.captureStream(VIDEO_FPS);
    this.recorder = new MediaRecorder(stream, { mimeType: type, videoBitsPerSecond: 8e6 });
    this.chunks = [];
    this.recorder.ondataavailable = (e) => { if (e.data.size) this.chunks.push(e.data); };
    this.recorder.onstop = () => this.finish(type, stream);
    this.startedAt = performance.now();
    this.recorder.start(250);
    $('record').textContent = 'stop recording';
    $('record').classList.add('active');
  }

  stop() { this.recorder?.stop(); }

  finish(type, stream) {
    for (const track of stream.getTracks()) track.stop();
    const blob = new Blob(this.chunks, { type: type.split(';')[0] });
    if (this.last) URL.revokeObjectURL(this.last.url);
    this.last = { size: blob.size, type: blob.type, url: URL.createObjectURL(blob), seconds: (performance.now() - this.startedAt) / 1000 };
    this.recorder = null;
    $('record').textContent = 'record video';
    $('record').classList.remove('active');
    const link = $('save-video');
    link.href = this.last.url;
    link.download = fileName(this.problem, 'webm');
    link.hidden = false;
    this.notify(`recorded ${this.last.seconds.toFixed(1)} s of video (${(blob.size / 1e6).toFixed(1)} MB)`, 'ok');
  }

  download(blob, name) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  }
}
