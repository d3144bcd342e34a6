#include "tandem/web/socket_session.hpp"

#include <nlohmann/json.hpp>
#include <vector>

namespace tandem::viewer {

void SocketHub::add(const std::shared_ptr<SocketSession>& socket) {
  sockets_.insert(socket);
  clients_.store(sockets_.size());
  connections_.fetch_add(1);
  control_.connected();
}

void SocketHub::remove(const std::shared_ptr<SocketSession>& socket) {
  sockets_.erase(socket);
  clients_.store(sockets_.size());
}

void SocketHub::pump_all() {
  // A copy: a failed write may close a socket, which leaves the set.
  const std::vector<std::shared_ptr<SocketSession>> sockets(sockets_.begin(), sockets_.end());
  for (const auto& s : sockets)
    s->pump();
}

void SocketSession::start(http::request<http::string_body> req) {
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& res) { res.set(http::field::server, "tandem"); }));
  ws_.read_message_max(kMaxMessageBytes);
  beast::error_code no_peer;
  const auto endpoint = beast::get_lowest_layer(ws_).socket().remote_endpoint(no_peer);
  peer_ = no_peer ? std::string("?") : endpoint.address().to_string();
  ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) {
    if (ec)
      return;
    self->hub_.add(self);
    self->read();
    self->pump();
  });
}

void SocketSession::pump() {
  if (writing_ || closed_)
    return;
  if (queue_.empty()) {
    const std::uint64_t v = hub_.state().version();
    if (v == seen_version_ && cursor_.greeted)
      return;
    seen_version_ = v;
    for (Frame& f : hub_.state().pending(cursor_))
      queue_.push_back(std::move(f));
    if (queue_.empty())
      return;
  }
  writing_ = true;
  ws_.binary(queue_.front().binary);
  ws_.async_write(net::buffer(queue_.front().data),
                  [self = shared_from_this()](beast::error_code ec, std::size_t) {
                    self->writing_ = false;
                    if (ec) {
                      self->close();
                      return;
                    }
                    self->queue_.pop_front();
                    self->pump();
                  });
}

void SocketSession::send_error(const std::string& message) {
  nlohmann::json j{{"type", "error"}, {"message", message}};
  // Next in line; the frame being written, if any, is at the front and stays there.
  queue_.insert(queue_.begin() + (writing_ ? 1 : 0), Frame{false, j.dump()});
  pump();
}

void SocketSession::read() {
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if (ec) {
      if (ec == websocket::error::message_too_big)
        log_line("closed a WebSocket from " + self->peer_ + ": message too long");
      self->close();
      return;
    }
    self->on_message();
    self->read();
  });
}

void SocketSession::on_message() {
  const std::string text = beast::buffers_to_string(buffer_.data());
  buffer_.consume(buffer_.size());
  if (!ws_.got_text()) {
    refuse("binary messages are not accepted");
    return;
  }
  try {
    const ClientMessage m = parse_client_message(text, hub_.control().settings());
    if (auto why = hub_.control().handle(m))
      refuse(*why);
  } catch (const ProtocolError& e) {
    refuse(e.what());
  }
}

void SocketSession::refuse(const std::string& why) {
  log_line("refused a message from " + peer_ + ": " + why);
  send_error(why);
}

void SocketSession::close() {
  if (closed_)
    return;
  closed_ = true;
  hub_.remove(shared_from_this());
}

}  // namespace tandem::viewer
