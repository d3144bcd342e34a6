// window.tandem, for the tests and for scripts (web/test, web/bench): read-only views of what the
// page shows, and two switches for measuring.

/**
 * @param parts the page's pieces: `connection`, `view` (SceneView), `loop` (FrameLoop), `panel`
 *   (StatusPanel), `input` (OperatorInput), `playback`, `products` (SolutionProducts), `picker`
 *   (AssemblyPicker), `xr` (VrOperator), `hello` (() => the last hello message)
 */
export function exposePageApi({ connection, view, loop, panel, input, playback, products, picker, xr, hello }) {
  window.tandem = {
    get connected() { return connection.connected; },
    get hello() { return hello(); },
    get status() { return panel.status; },
    get operator() { return loop.operator; },
    get fps() { return loop.fps; },
    /** How the page draws ('layered' or 'direct', see layers.js) and how many edges its last frame drew. */
    get rendering() { return { mode: view.layered ? 'layered' : 'direct', drawnEdges: view.layers.drawn }; },
    /** Turns the camera about the scene without end (a frame to draw every time: for measuring). */
    spin(on) { view.orbit.autoRotate = on; },
    /** Draws a frame every time, the camera still (for measuring). */
    redraw(on) { loop.redrawAlways = on; },
    get frames() { return loop.frames; },
    get solution() { return playback.solution; },
    /** The solution's clearance as the server sent it (null until then), and the line's colours
     * ([r, g, b] per vertex; null while it is drawn plain). */
    get clearance() { return products.clearance; },
    solutionLineColours: () => {
      const c = view.pathLine?.geometry.getAttribute('color');
      return c ? Array.from({ length: c.count }, (_, i) => [c.getX(i), c.getY(i), c.getZ(i)]) : null;
    },
    /** Choosing a part of an assembly: whether the page is, and the part selected. */
    get picking() { return picker.active; },
    get pickedPart() { return picker.selected; },
    /** The motion envelope shown: its triangle count, or 0. */
    envelopeTriangles: () => (view.envelope?.visible ? view.envelope.geometry.attributes.position.count / 3 : 0),
    get errors() { return panel.errors.slice(); },
    get latencies() { return input.latencies; },
    counts: () => view.trees.counts(),
    operatorNodes: () => view.trees.operatorNodes(),
    partPose: () => view.partPose(),
    /** Where a world point is on the page, in CSS pixels. */
    screenOf: (x, y, z) => view.screenOf(x, y, z),
    partScreen: () => { const p = view.part.position; return view.screenOf(p.x, p.y, p.z); },
    /** The bounding boxes on the page, in CSS pixels, of the meshes that the layered drawing draws
     * over the trees (layers.js): the part, the start and goal ghosts, transparent obstacles. */
    overlaidBoxes: () => view.overlaidObjects().map((o) => view.screenBoxOf(o)),
    screenBoxOf: (object) => view.screenBoxOf(object),
    /** The VR operator: in VR, holding the part, pulses and rumbles sent, a scene point in VR. */
    xr: {
      get presenting() { return xr.presenting; },
      get holding() { return xr.holding !== null; },
      get pulses() { return xr.pulses; },
      get rumbles() { return xr.rumbles; },
      pointOf: (x, y, z) => xr.xrPointOf(x, y, z),
    },
  };
}
