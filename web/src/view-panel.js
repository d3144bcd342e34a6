// The panel's view controls and their keys: x-ray (X) and the automatic x-ray of what hides the
// part, section planes (C: one through the part, or none; another; flip), framing (F the part,
// G the path, H everything) and following, the trees while the path plays (shown, dimmed or
// hidden), and the still (PNG) and the video (WebM) of the view, with the status overlay or not.
import { $ } from './dom.js';

export class ViewPanel {
  /**
   * @param parts `looks` (ObstacleLooks), `sections` (SectionPlanes), `framing` (CameraFraming),
   *   `recorder` (Recorder), `playback` (Playback), `notify` ((text, cls) => void)
   */
  constructor({ looks, sections, framing, recorder, playback, notify }) {
    Object.assign(this, { looks, sections, framing, recorder, playback, notify });
    this.wireButtons();
    this.wireKeys();
  }

  wireButtons() {
    const { looks, sections, framing, recorder } = this;
    $('xray').onclick = () => looks.setXray(!looks.xray);
    $('auto-xray').onchange = (e) => looks.setAutoXray(e.target.checked);
    $('section').onclick = () => this.toggleSection();
    $('section-add').onclick = () => { sections.add(); this.syncSections(); };
    $('section-flip').onclick = () => sections.flipLast();
    $('frame-part').onclick = () => framing.frame('part');
    $('frame-path').onclick = () => framing.frame('path');
    $('frame-all').onclick = () => framing.frame('all');
    $('follow').onchange = (e) => { framing.follow = e.target.checked; };
    $('trees-playing').onchange = (e) => this.playback.setTreesWhilePlaying(e.target.value);
    $('screenshot').onclick = () => recorder.screenshot();
    $('record').onclick = () => (recorder.recording ? recorder.stop() : recorder.start());
    $('record-path').onclick = () => this.recordPlayback();
    $('record-overlay').onchange = (e) => { recorder.overlay = e.target.checked; };
  }

  wireKeys() {
    const keys = {
      KeyX: () => $('xray').click(),
      KeyC: () => this.toggleSection(),
      KeyF: () => this.framing.frame('part'),
      KeyG: () => this.framing.frame('path'),
      KeyH: () => this.framing.frame('all'),
    };
    window.addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      keys[e.code]?.();
    });
  }

  /** A section plane through the part, or none. */
  toggleSection() {
    if (this.sections.active) this.sections.clear(); else this.sections.add();
    this.syncSections();
  }

  syncSections() {
    const n = this.sections.planes.length;
    $('section').classList.toggle('active', n > 0);
    $('section').textContent = n > 1 ? `sections (${n})` : 'section';
    $('section-add').disabled = n === 0 || n >= 3;
    $('section-flip').disabled = n === 0;
  }

  /** The path played once from its start, recorded. */
  recordPlayback() {
    const { playback, recorder } = this;
    if (!playback.solution.length || recorder.recording) return;
    playback.playFromStart(() => recorder.stop());
    recorder.start();
  }
}
