#pragma once
// The viewer's WebSockets: one SocketSession per browser, and the SocketHub that holds the open
// ones. A session sends its browser what the ViewerState has that the browser has not had yet
// (its Cursor), one message at a time, so a slow browser gets larger batches and never holds up
// the planner; it carries out the browser's messages through the ViewerControl, and answers a
// malformed or refused one with an error message and a log line.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <set>
#include <string>

#include "tandem/web/server_io.hpp"
#include "tandem/web/viewer_server.hpp"

namespace tandem::viewer {

/// Browsers at once (each costs the server a copy of the trees' new nodes per frame).
constexpr std::size_t kMaxSockets = 32;

class SocketSession;

/// The open sockets and what they serve.
///
/// Threading: everything on the server's thread, except clients() and connections(), which any
/// thread may read.
class SocketHub {
 public:
  SocketHub(ViewerState& state, ViewerControl& control) : state_(state), control_(control) {}

  ViewerState& state() { return state_; }
  ViewerControl& control() { return control_; }

  /// Sockets open now.
  std::size_t open() const { return sockets_.size(); }
  void add(const std::shared_ptr<SocketSession>& socket);
  void remove(const std::shared_ptr<SocketSession>& socket);
  /// Sends every socket what it has not had yet (the server's tick).
  void pump_all();

  std::size_t clients() const { return clients_.load(); }
  std::size_t connections() const { return connections_.load(); }

 private:
  ViewerState& state_;
  ViewerControl& control_;
  std::set<std::shared_ptr<SocketSession>> sockets_;
  std::atomic<std::size_t> clients_{0}, connections_{0};
};

/// One browser's WebSocket. Keeps itself alive through its pending reads and writes (and the hub,
/// while open).
///
/// Threading: the server's thread only (its handlers run there, as do the hub's calls).
class SocketSession : public std::enable_shared_from_this<SocketSession> {
 public:
  SocketSession(SocketHub& hub, tcp::socket&& socket) : hub_(hub), ws_(std::move(socket)) {}

  /// Completes the handshake of an upgrade request; the session then joins the hub.
  void start(http::request<http::string_body> req);

  /// Sends what this browser has not had yet, one message at a time.
  void pump();

  /// An error message to the browser, next in line.
  void send_error(const std::string& message);

 private:
  void read();
  void on_message();
  void refuse(const std::string& why);
  void close();

  SocketHub& hub_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  std::deque<Frame> queue_;
  ViewerState::Cursor cursor_;
  std::uint64_t seen_version_ = 0;
  bool writing_ = false, closed_ = false;
  std::string peer_;
};

}  // namespace tandem::viewer
