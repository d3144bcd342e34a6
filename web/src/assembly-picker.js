// Choosing the part to take out of an assembly (`tandem interactive FILE.step` without --part):
// the page shows the assembly's tree (its parts' paths, from the scene's obstacle names), a click
// on a part in the scene or in the tree selects it, and "take it out" asks the server to start the
// session with it (a take_out message). The server then serves that session on the same address;
// the page reloads into it when its hello names another problem (main.js).
import { $ } from './dom.js';

/** The tree of '/'-separated paths: {name, path, children: [...]} per node, in the given order. */
export function pathTree(paths) {
  const root = { name: '', path: '', children: [] };
  for (const p of paths) {
    let node = root;
    p.split('/').forEach((name, i, all) => {
      let child = node.children.find((c) => c.name === name);
      if (!child) {
        child = { name, path: all.slice(0, i + 1).join('/'), children: [] };
        node.children.push(child);
      }
      node = child;
    });
  }
  return root;
}

export class AssemblyPicker {
  constructor(view, { send, touch, notify }) {
    this.view = view;
    this.send = send;
    this.touch = touch;
    this.notify = notify;
    this.selected = null;
    this.active = false;
  }

  /** Pick mode: the tree of the scene's parts, clicks in the scene select, the rest hidden. */
  start(scene) {
    this.active = true;
    document.body.classList.add('picking');
    $('pick-box').hidden = false;
    this.view.gizmo.detach();
    this.view.part.visible = false;
    this.parts = scene.obstacles.map((o) => o.name);
    $('pick-tree').replaceChildren(this.list(pathTree(this.parts)));
    $('take-out').onclick = () => this.takeOut();
    this.wireClicks(this.view.layers.domElement);
  }

  list(node) {
    const ul = document.createElement('ul');
    for (const child of node.children) {
      const li = document.createElement('li');
      if (child.children.length) {
        li.textContent = child.name;
        li.append(this.list(child));
      } else {
        const b = document.createElement('button');
        b.textContent = child.name;
        b.dataset.part = child.path;
        b.onclick = () => this.select(child.path);
        li.append(b);
      }
      ul.append(li);
    }
    return ul;
  }

  /** A click (a press and release without a drag) selects the part under the pointer. */
  wireClicks(canvas) {
    let down = null;
    canvas.addEventListener('pointerdown', (e) => { down = { x: e.clientX, y: e.clientY }; });
    canvas.addEventListener('pointerup', (e) => {
      if (!this.active || !down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4) return;
      const name = this.view.obstacleAt(e.clientX, e.clientY);
      if (name) this.select(name);
    });
  }

  select(name) {
    this.selected = name;
    this.view.highlight(name);
    for (const b of $('pick-tree').querySelectorAll('button')) b.classList.toggle('active', b.dataset.part === name);
    $('pick-choice').textContent = `chosen: ${name}`;
    $('take-out').disabled = false;
    this.touch();
  }

  takeOut() {
    if (!this.selected) return;
    this.send({ type: 'take_out', part: this.selected });
    $('take-out').disabled = true;
    this.notify(`taking ${this.selected} out: the session starts…`, 'ok');
  }
}
