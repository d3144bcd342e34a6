// window.tandem, for the tests and for scripts (web/test, web/bench): read-only views of what the
// page shows, and two switches for measuring.

/**
 * @param parts the page's pieces: `connection`, `view` (SceneView), `loop` (FrameLoop), `panel`
 *   (StatusPanel), `input` (OperatorInput), `playback`, `products` (SolutionProducts), `picker`
 *   (AssemblyPicker), `xr` (VrOperator), `looks` (ObstacleLooks), `sections` (SectionPlanes),
 *   `framing` (CameraFraming), `recorder` (Recorder), `hello` (() => the last hello message)
 */
export function exposePageApi({ connection, view, loop, panel, input, playback, products, picker, xr, looks,
  sections, framing, recorder, hello }) {
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
    solutionLineColours: () => view.pathLine?.userData.colours ?? null,
    /** The solution line: its width in pixels and whether x-ray draws it in front; null: none. */
    solutionLine: () => (view.pathLine ? { width: view.pathLine.material.linewidth, inFront: view.inFront } : null),
    /** How each obstacle is drawn: {name: {shown, opacity}}; x-ray; the obstacles hiding the part. */
    obstacles: () => Object.fromEntries(view.obstacleMeshes.map((m) => [m.name, looks.effective(m.name)])),
    get xray() { return looks.xray; },
    get hiding() { return [...looks.hiding]; },
    get selectedObstacle() { return view.obstacleMeshes.find((m) => m.material.emissive.getHex() !== 0)?.name ?? null; },
    /** The section planes: [{normal, constant}]. */
    sections: () => sections.planes.map(({ plane }) => ({ normal: plane.normal.toArray(), constant: plane.constant })),
    /** Caps the section planes' cuts, or not (to see what the caps draw). */
    setCapped: (on) => { sections.capped = on; view.layers.invalidate(); loop.touch(); },
    /** The part's box on the page (CSS pixels) and the view's box. */
    partBox: () => view.screenBoxOf(view.part),
    viewBox: () => {
      const r = view.layers.domElement.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    },
    /** Moves the part as a drag would (the pose goes to the server at once). */
    movePart: (q) => { view.setPartPose(q); input.moved(performance.now(), true); },
    get treesLook() { return view.trees.look; },
    get following() { return framing.follow; },
    /** The last recording: {size, type, url, seconds}, or null; whether one is under way. */
    get recording() { return recorder.last; },
    get recordingNow() { return recorder.recording; },
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
