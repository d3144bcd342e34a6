// The objects list: every obstacle by name, with show / hide, transparent and its opacity, and
// "isolate" (it alone); a click on an obstacle in the scene (a press and release without a drag)
// selects it in the list and marks it in the scene. The looks themselves are obstacle-looks.js's.
import { $ } from './dom.js';

const escape = (s) => String(s).replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);

export class ObjectsPanel {
  /**
   * @param view the SceneView (its obstacles, for the clicks)
   * @param looks the ObstacleLooks
   * @param busy () => bool: a click in the scene is someone else's (choosing a part to take out)
   */
  constructor(view, looks, busy) {
    this.view = view;
    this.looks = looks;
    this.selected = null;
    looks.onChange(() => this.sync());
    $('objects').addEventListener('input', (e) => this.edited(e.target));
    $('objects').addEventListener('click', (e) => this.clicked(e.target));
    this.wireClicks(busy);
  }

  /** The list, once the scene is loaded. */
  build() {
    const rows = this.view.obstacleMeshes.map((m) => `
      <tr data-name="${escape(m.name)}">
        <td><label class="object-name"><input type="checkbox" data-do="shown"> ${escape(m.name)}</label></td>
        <td><label title="transparent"><input type="checkbox" data-do="transparent"> see-through</label>
          <input type="range" min="5" max="100" data-do="opacity" title="opacity"></td>
        <td><button data-do="isolate" title="this obstacle alone">isolate</button></td>
      </tr>`);
    $('objects').innerHTML = rows.join('');
    this.sync();
  }

  row(name) { return [...$('objects').querySelectorAll('tr')].find((r) => r.dataset.name === name); }

  /** The controls show the looks. */
  sync() {
    for (const tr of $('objects').querySelectorAll('tr')) {
      const look = this.looks.look(tr.dataset.name);
      if (!look) continue;
      tr.querySelector('[data-do=shown]').checked = look.shown;
      tr.querySelector('[data-do=transparent]').checked = look.transparent;
      tr.querySelector('[data-do=opacity]').value = String(Math.round(look.opacity * 100));
      tr.querySelector('[data-do=isolate]').classList.toggle('active', this.looks.isolated === tr.dataset.name);
      tr.classList.toggle('selected', this.selected === tr.dataset.name);
    }
    $('xray').classList.toggle('active', this.looks.xray);
    $('auto-xray').checked = this.looks.autoXray;
  }

  edited(el) {
    const name = el.closest('tr')?.dataset.name;
    if (!name) return;
    if (el.dataset.do === 'shown') this.looks.set(name, { shown: el.checked });
    if (el.dataset.do === 'transparent') this.looks.set(name, { transparent: el.checked });
    if (el.dataset.do === 'opacity') this.looks.set(name, { transparent: true, opacity: Number(el.value) / 100 });
  }

  clicked(el) {
    const name = el.closest('tr')?.dataset.name;
    if (el.dataset.do === 'isolate') this.looks.isolate(this.looks.isolated === name ? null : name);
    else if (name && el.tagName !== 'INPUT') this.select(name);
  }

  /** Selects an obstacle (null: none): its row is marked, and it glows in the scene. */
  select(name) {
    this.selected = name;
    this.view.highlight(name);
    this.sync();
    if (name) this.row(name)?.scrollIntoView({ block: 'nearest' });
  }

  wireClicks(busy) {
    const canvas = this.view.layers.domElement;
    let down = null;
    canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY }; });
    canvas.addEventListener('pointerup', (e) => {
      const click = down && Math.hypot(e.clientX - down.x, e.clientY - down.y) < 4;
      down = null;
      if (!click || busy() || this.view.gizmo.dragging) return;
      this.select(this.view.obstacleAt(e.clientX, e.clientY));
    });
  }
}
