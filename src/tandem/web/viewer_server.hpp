#pragma once
// The viewer's server, inside the tandem process: HTTP for the page and the scene, a WebSocket
// for the live stream and the browser's inputs (Boost.Beast, on one thread of its own).
//
// Security: it listens on 127.0.0.1 unless told otherwise. Every request needs the session's
// random token (in the printed URL, as Jupyter does; the page then keeps it in a strict
// same-site cookie); the Host header must name this server (against DNS rebinding) and a
// WebSocket's Origin, if any, must be this server's page. A refused request gets 403 and a log
// line; a malformed or hostile message gets an error message and a log line, never a crash. A
// browser that disconnects or reads slowly never holds up the planner (see ViewerState).
//
// Threading: construct and destroy on one thread; url(), port(), clients() from any thread. The
// control's handle() and connected() are called on the server's thread.

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "tandem/web/viewer_state.hpp"

namespace tandem {

/// What the browser may change. Called on the server's thread.
class ViewerControl {
 public:
  virtual ~ViewerControl() = default;
  /// Carries out a message; returns why it was refused, if it was.
  virtual std::optional<std::string> handle(const ClientMessage& message) = 0;
  /// What a "params" message is applied to.
  virtual InteractionSettings settings() const = 0;
  /// The session's journal, for "save the session" (none for a replay).
  virtual std::optional<std::filesystem::path> journal() const = 0;
  /// A browser's WebSocket has opened (on the server's thread).
  virtual void connected() {}
};

struct ServerOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8170;      ///< 0: any free port
  std::filesystem::path web_root;  ///< the built front end (index.html and assets/)
  std::string token;               ///< empty: a random one
};

/// The folder the front end is built into (web/dist in the source tree, or $TANDEM_WEB_ROOT).
std::filesystem::path default_web_root();

/// Throws InputError naming the folder when the front end is not built there, or naming --host
/// when it is not an IP address: what can be checked before a session starts.
void check_server_options(const ServerOptions& options);

/// A token of 32 hex digits from the system's random source.
std::string random_token();

class ViewerServer {
 public:
  /// Listens at once. Throws InputError when the front end is not built or the port is taken.
  ViewerServer(ViewerState& state, ViewerControl& control, const ServerOptions& options);
  ~ViewerServer();
  ViewerServer(const ViewerServer&) = delete;
  ViewerServer& operator=(const ViewerServer&) = delete;

  /// http://127.0.0.1:PORT/?token=…
  std::string url() const;
  unsigned short port() const;
  /// Browsers connected now, and since the start.
  std::size_t clients() const;
  std::size_t connections() const;

  class Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tandem
