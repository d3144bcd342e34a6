// The page's link to the tandem process: its token (the URL's ?token=, on every request), the
// scene over HTTP, and the WebSocket (reconnected a second after it closes), whose messages go to
// handlers: binary node batches to one, JSON messages by their `type` to others.

export class Connection {
  constructor(token) {
    this.token = token;
    this.socket = null;
    this.handlers = null;
  }

  /** A path of the server with the token. */
  withToken(path) { return `${path}?token=${encodeURIComponent(this.token)}`; }

  /** The scene (/api/scene). */
  async scene() {
    const res = await fetch(this.withToken('/api/scene'));
    if (!res.ok) throw new Error(`the scene: ${res.status} ${await res.text()}`);
    return res.json();
  }

  get connected() { return this.socket?.readyState === WebSocket.OPEN; }

  send(message) {
    if (this.connected) this.socket.send(JSON.stringify(message));
  }

  /**
   * Opens the socket, and opens it again whenever it closes.
   * @param handlers `nodes(buffer)`: a binary node batch, false if it does not follow what came
   *   (the socket is then closed: the page starts afresh); `state(text, cls)`: the connection's
   *   state; `messages`: {type: handler(message)} for the JSON messages
   */
  open(handlers) {
    this.handlers = handlers;
    this.connect();
  }

  connect() {
    const { state } = this.handlers;
    const socket = new WebSocket(`ws://${location.host}/ws?token=${encodeURIComponent(this.token)}`);
    this.socket = socket;
    socket.binaryType = 'arraybuffer';
    socket.onopen = () => state('connected', 'ok');
    socket.onclose = () => { state('disconnected — retrying', 'bad'); setTimeout(() => this.connect(), 1000); };
    socket.onmessage = (e) => this.dispatch(e.data);
  }

  dispatch(data) {
    if (data instanceof ArrayBuffer) {
      if (this.handlers.nodes(data) === false) this.socket.close(); // out of order: start afresh
      return;
    }
    const m = JSON.parse(data);
    const { messages } = this.handlers;
    if (Object.hasOwn(messages, m.type)) messages[m.type](m);
  }
}
