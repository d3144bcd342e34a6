// tandem's live viewer: the scene, the part at q_device, both trees growing, the contact plane,
// the guidance force, the solution with playback; the browser's operator inputs and the tuning;
// the objects list, x-ray, section planes, framing, stills and videos of the view.
// This module wires the pieces; the URL's options:
//   ?token=…          the session's token (printed with the URL)
//   ?layers=on|off    draw in layers (default: on with a software renderer, see layers.js)
//   ?lod=N            thin the trees beyond N edges while the camera moves (0: never)
//   ?maxfps=N         at most N frames a second (default 30; 0: no cap)
import { $ } from './dom.js';
import { decodeNodes } from './trees.js';
import { SceneView, softwareGL } from './scene-view.js';
import { Connection } from './connection.js';
import { StatusPanel } from './status-panel.js';
import { TuningPanel } from './tuning-panel.js';
import { Playback } from './playback.js';
import { SolutionProducts } from './solution-products.js';
import { AssemblyPicker } from './assembly-picker.js';
import { OperatorInput } from './operator-input.js';
import { FrameLoop } from './frame-loop.js';
import { VrOperator } from './xr.js';
import { ObstacleLooks } from './obstacle-looks.js';
import { ObjectsPanel } from './objects-panel.js';
import { SectionPlanes } from './section-planes.js';
import { CameraFraming } from './camera-framing.js';
import { Recorder } from './recorder.js';
import { ViewPanel } from './view-panel.js';
import { exposePageApi } from './page-api.js';

function start(query) {
  const software = softwareGL();
  const view = new SceneView($('view'), {
    software, layered: { on: true, off: false }[query.get('layers')] ?? software,
    lodEdges: query.has('lod') ? Number(query.get('lod')) : undefined });
  const connection = new Connection(query.get('token') ?? '');
  const loop = new FrameLoop(view, Number(query.get('maxfps') ?? 30));
  const touch = () => loop.touch();
  const panel = new StatusPanel(() => ({ fps: loop.fps, drawnEdges: view.layers.drawn, edges: view.trees.edgeCount() }));
  const notify = (text, cls) => panel.showMessage(text, cls);
  const tuning = new TuningPanel(connection);
  const products = new SolutionProducts(view, { touch, notify });
  const playback = new Playback(view, { touch, notify, products });
  const input = new OperatorInput(view, { send: (m) => connection.send(m), touch, notify });
  view.onChange = touch;
  $('colour-by').onchange = (e) => { view.trees.setColourBy(e.target.value); touch(); };
  $('show-nodes').onchange = (e) => { view.trees.setShowNodes(e.target.value); touch(); };

  const picker = new AssemblyPicker(view, { send: (m) => connection.send(m), touch, notify });
  const looks = new ObstacleLooks(view, touch);
  const objects = new ObjectsPanel(view, looks, () => picker.active);
  const sections = new SectionPlanes(view, touch);
  const framing = new CameraFraming(view, { looks, sections, playback, changed: touch });
  const recorder = new Recorder(view, { lines: () => panel.overlayLines(), notify });
  new ViewPanel({ looks, sections, framing, recorder, playback, notify });
  loop.onUpdate((now) => { framing.update(now); sections.update(); });
  loop.onDrawn(() => recorder.frameDrawn());
  loop.onFps(() => panel.refresh());
  let hello = null, scene = null;
  const restart = (generation) => { view.trees.clear(generation); playback.clear(); };
  const messages = {
    hello: (m) => {
      // Another problem on this address (the session of the part chosen here): start afresh.
      if (scene && m.problem !== scene.name) { location.reload(); return; }
      hello = m;
      restart(m.generation);
      tuning.build(m.parameters);
      if (m.mode === 'pick' && !picker.active) picker.start(scene);
    },
    reset: (m) => restart(m.generation),
    status: (m) => { input.onStatus(m); panel.show(m); tuning.onStatus(m); },
    operator: (m) => loop.setOperator(m),
    solution: (m) => playback.show(m.path),
    error: (m) => panel.refused(m.message),
  };
  const nodes = (buffer) => {
    const ok = view.trees.add(decodeNodes(buffer));
    touch();
    return ok;
  };
  const xr = new VrOperator(view, input, { notify });
  exposePageApi({ connection, view, loop, panel, input, playback, products, picker, xr, looks, sections,
    framing, recorder, hello: () => hello });
  connection.scene()
    .then((s) => {
      scene = s;
      panel.setProblem(s.name);
      view.load(s);
      looks.load(s.name);
      objects.build();
      recorder.problem = s.name;
      connection.open({ nodes, messages, state: (text, cls) => panel.setConnection(text, cls) });
      loop.start(input, playback, xr);
    })
    .catch((err) => { panel.setConnection(String(err.message ?? err), 'bad'); });
}

start(new URLSearchParams(location.search));
