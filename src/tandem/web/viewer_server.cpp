#include "tandem/web/viewer_server.hpp"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include "tandem/core/error.hpp"

namespace tandem {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

constexpr std::chrono::milliseconds kTick{15};
/// Browsers at once (each costs the server a copy of the trees' new nodes per frame).
constexpr std::size_t kMaxSockets = 32;

std::string_view sv(beast::string_view s) {
  return {s.data(), s.size()};
}

bool equal_constant_time(std::string_view a, std::string_view b) {
  if (a.size() != b.size())
    return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

/// The value of `key` in a query string or a Cookie header ("a=1&b=2", "a=1; b=2").
std::string field_value(std::string_view text, std::string_view key, char separator) {
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find(separator, pos);
    if (end == std::string_view::npos)
      end = text.size();
    std::string_view item = text.substr(pos, end - pos);
    while (!item.empty() && item.front() == ' ')
      item.remove_prefix(1);
    if (item.size() > key.size() && item.substr(0, key.size()) == key && item[key.size()] == '=')
      return std::string(item.substr(key.size() + 1));
    pos = end + 1;
  }
  return {};
}

std::string_view mime_type(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html")
    return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs")
    return "text/javascript; charset=utf-8";
  if (ext == ".css")
    return "text/css; charset=utf-8";
  if (ext == ".json")
    return "application/json";
  if (ext == ".svg")
    return "image/svg+xml";
  if (ext == ".png")
    return "image/png";
  if (ext == ".ico")
    return "image/x-icon";
  return "application/octet-stream";
}

std::optional<std::string> read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A short plain-text answer that closes the connection (refusals).
http::response<http::string_body> plain_reply(http::status status, unsigned version,
                                              std::string text) {
  http::response<http::string_body> res{status, version};
  res.set(http::field::server, "tandem");
  res.set(http::field::content_type, "text/plain; charset=utf-8");
  res.body() = std::move(text);
  res.keep_alive(false);
  res.prepare_payload();
  return res;
}

net::ip::address listen_address(const std::string& host) {
  boost::system::error_code ec;
  const auto address = net::ip::make_address(host, ec);
  if (ec)
    throw InputError("--host", "'" + host + "' is not an IP address");
  return address;
}

void log_line(const std::string& text) {
  std::cerr << "tandem viewer: " << text << '\n' << std::flush;
}

}  // namespace

std::filesystem::path default_web_root() {
  if (const char* env = std::getenv("TANDEM_WEB_ROOT"); env != nullptr && *env != '\0')
    return env;
  return TANDEM_WEB_ROOT;
}

std::string random_token() {
  std::random_device device;
  std::string token;
  static constexpr char kHex[] = "0123456789abcdef";
  for (int i = 0; i < 16; ++i) {
    const unsigned byte = device() & 0xffu;
    token += kHex[byte >> 4];
    token += kHex[byte & 15u];
  }
  return token;
}

class WsSession;

class ViewerServer::Impl {
 public:
  Impl(ViewerState& state, ViewerControl& control, const ServerOptions& options)
      : state_(state),
        control_(control),
        options_(options),
        token_(options.token.empty() ? random_token() : options.token),
        acceptor_(ioc_),
        tick_(ioc_) {
    boost::system::error_code ec;
    const tcp::endpoint endpoint(listen_address(options.host), options.port);
    acceptor_.open(endpoint.protocol(), ec);
    if (!ec)
      acceptor_.set_option(net::socket_base::reuse_address(true), ec);
    if (!ec)
      acceptor_.bind(endpoint, ec);
    if (!ec)
      acceptor_.listen(net::socket_base::max_listen_connections, ec);
    if (ec) {
      throw InputError("--port", "cannot listen on " + options.host + ":" +
                                     std::to_string(options.port) + ": " + ec.message());
    }
    port_ = acceptor_.local_endpoint().port();
    const std::string p = std::to_string(port_);
    allowed_hosts_ = {"127.0.0.1:" + p, "localhost:" + p, "[::1]:" + p};
    if (options.host != "127.0.0.1" && options.host != "::1")
      allowed_hosts_.insert(options.host + ":" + p);
    accept();
    schedule_tick();
    thread_ = std::thread([this] { ioc_.run(); });
  }

  ~Impl() {
    net::post(ioc_, [this] {
      boost::system::error_code ec;
      acceptor_.close(ec);
      tick_.cancel();
    });
    ioc_.stop();
    if (thread_.joinable())
      thread_.join();
  }

  std::string url() const {
    return "http://" + (options_.host == "::1" ? std::string("[::1]") : options_.host) + ":" +
           std::to_string(port_) + "/?token=" + token_;
  }

  // The HTTP side.
  template <class Body>
  http::response<http::string_body> respond(const http::request<Body>& req) const;
  /// Why a request is refused (403), if it is.
  template <class Body>
  std::optional<std::string> refusal(const http::request<Body>& req) const;

  void accept();
  void schedule_tick();

  ViewerState& state_;
  ViewerControl& control_;
  ServerOptions options_;
  std::string token_;
  std::set<std::string> allowed_hosts_;
  net::io_context ioc_{1};
  tcp::acceptor acceptor_;
  net::steady_timer tick_;
  unsigned short port_ = 0;
  std::set<std::shared_ptr<WsSession>> sockets_;  ///< server thread only
  std::atomic<std::size_t> clients_{0}, connections_{0};
  std::thread thread_;
};

class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(ViewerServer::Impl& server, tcp::socket&& socket)
      : server_(server), ws_(std::move(socket)) {}

  void start(http::request<http::string_body> req) {
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
      self->server_.sockets_.insert(self);
      self->server_.clients_.store(self->server_.sockets_.size());
      self->server_.connections_.fetch_add(1);
      self->read();
      self->pump();
    });
  }

  /// Sends what this browser has not had yet, one message at a time.
  void pump() {
    if (writing_ || closed_)
      return;
    if (queue_.empty()) {
      const std::uint64_t v = server_.state_.version();
      if (v == seen_version_ && cursor_.greeted)
        return;
      seen_version_ = v;
      for (Frame& f : server_.state_.pending(cursor_))
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

  void send_error(const std::string& message) {
    nlohmann::json j{{"type", "error"}, {"message", message}};
    // Next in line; the frame being written, if any, is at the front and stays there.
    queue_.insert(queue_.begin() + (writing_ ? 1 : 0), Frame{false, j.dump()});
    pump();
  }

 private:
  void read() {
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

  void on_message() {
    const std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (!ws_.got_text()) {
      refuse("binary messages are not accepted");
      return;
    }
    try {
      const ClientMessage m = parse_client_message(text, server_.control_.settings());
      if (auto why = server_.control_.handle(m))
        refuse(*why);
    } catch (const ProtocolError& e) {
      refuse(e.what());
    }
  }

  void refuse(const std::string& why) {
    log_line("refused a message from " + peer_ + ": " + why);
    send_error(why);
  }

  void close() {
    if (closed_)
      return;
    closed_ = true;
    server_.sockets_.erase(shared_from_this());
    server_.clients_.store(server_.sockets_.size());
  }

  ViewerServer::Impl& server_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  std::deque<Frame> queue_;
  ViewerState::Cursor cursor_;
  std::uint64_t seen_version_ = 0;
  bool writing_ = false, closed_ = false;
  std::string peer_;
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(ViewerServer::Impl& server, tcp::socket&& socket)
      : server_(server), stream_(std::move(socket)) {}

  void read() {
    parser_.emplace();
    parser_->header_limit(16 * 1024);
    parser_->body_limit(16 * 1024);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) {
                       if (ec) {
                         if (ec != http::error::end_of_stream && ec != beast::error::timeout &&
                             ec != net::error::operation_aborted) {
                           self->reply_bad_request(ec.message());
                         }
                         return;
                       }
                       self->on_request();
                     });
  }

 private:
  void on_request() {
    http::request<http::string_body> req = parser_->release();
    const std::string target(req.target());
    const bool upgrade = websocket::is_upgrade(req);
    if (auto why = server_.refusal(req)) {
      log_line("refused " + target.substr(0, target.find('?')) + " from " + peer() + ": " + *why);
      write(plain_reply(http::status::forbidden, req.version(), "403 forbidden: " + *why + "\n"));
      return;
    }
    if (upgrade && server_.sockets_.size() >= kMaxSockets) {
      log_line("refused a WebSocket from " + peer() + ": " + std::to_string(kMaxSockets) +
               " are open");
      write(
          plain_reply(http::status::service_unavailable, req.version(), "503 too many viewers\n"));
      return;
    }
    if (upgrade) {
      std::make_shared<WsSession>(server_, stream_.release_socket())->start(std::move(req));
      return;
    }
    write(server_.respond(req));
  }

  void reply_bad_request(const std::string& why) {
    log_line("refused a malformed request from " + peer() + ": " + why);
    write(plain_reply(http::status::bad_request, 11, "400 bad request: " + why + "\n"));
  }

  void write(http::response<http::string_body>&& res) {
    auto sp = std::make_shared<http::response<http::string_body>>(std::move(res));
    http::async_write(stream_, *sp,
                      [self = shared_from_this(), sp](beast::error_code ec, std::size_t) {
                        if (ec || !sp->keep_alive()) {
                          beast::error_code ignored;
                          self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                          return;
                        }
                        self->read();
                      });
  }

  std::string peer() {
    beast::error_code ec;
    const auto endpoint = stream_.socket().remote_endpoint(ec);
    return ec ? std::string("?") : endpoint.address().to_string();
  }

  ViewerServer::Impl& server_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

void ViewerServer::Impl::accept() {
  acceptor_.async_accept(net::make_strand(ioc_), [this](beast::error_code ec, tcp::socket socket) {
    if (ec)
      return;  // closed
    // Small messages (a pose, a status) go out at once, not after Nagle's wait.
    beast::error_code ignored;
    socket.set_option(tcp::no_delay(true), ignored);
    std::make_shared<HttpSession>(*this, std::move(socket))->read();
    accept();
  });
}

void ViewerServer::Impl::schedule_tick() {
  tick_.expires_after(kTick);
  tick_.async_wait([this](beast::error_code ec) {
    if (ec)
      return;
    const std::vector<std::shared_ptr<WsSession>> sockets(sockets_.begin(), sockets_.end());
    for (const auto& s : sockets)
      s->pump();
    schedule_tick();
  });
}

template <class Body>
std::optional<std::string> ViewerServer::Impl::refusal(const http::request<Body>& req) const {
  const std::string host(req[http::field::host]);
  if (!allowed_hosts_.contains(host))
    return "Host '" + host.substr(0, 80) + "' is not this server";
  // A browser always sends Origin with a WebSocket (and with cross-site requests).
  if (const auto origin = req.find(http::field::origin);
      origin != req.end() && origin->value() != "http://" + host) {
    return "Origin '" + std::string(origin->value()).substr(0, 80) + "' is not this server's page";
  }
  const std::string_view target = sv(req.target());
  const auto q = target.find('?');
  const std::string from_query =
      q == std::string_view::npos ? std::string() : field_value(target.substr(q + 1), "token", '&');
  const std::string from_cookie = field_value(sv(req[http::field::cookie]), "tandem_token", ';');
  if (!equal_constant_time(from_query, token_) && !equal_constant_time(from_cookie, token_))
    return "missing or wrong token (open the URL tandem printed)";
  return std::nullopt;
}

template <class Body>
http::response<http::string_body> ViewerServer::Impl::respond(
    const http::request<Body>& req) const {
  http::response<http::string_body> res{http::status::ok, req.version()};
  res.set(http::field::server, "tandem");
  res.set("X-Content-Type-Options", "nosniff");
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(req.keep_alive());
  auto finish = [&](http::status status, std::string_view type, std::string body) {
    res.result(status);
    res.set(http::field::content_type, beast::string_view(type.data(), type.size()));
    res.body() = std::move(body);
    if (req.method() == http::verb::head)
      res.body().clear();
    res.prepare_payload();
    return res;
  };
  if (req.method() != http::verb::get && req.method() != http::verb::head)
    return finish(http::status::method_not_allowed, "text/plain", "405 GET only\n");
  std::string path(req.target().substr(0, req.target().find('?')));
  if (path == "/api/scene")
    return finish(http::status::ok, "application/json", state_.scene_json());
  if (path == "/api/path") {
    auto text = state_.path_text();
    if (!text)
      return finish(http::status::not_found, "text/plain", "no solution yet\n");
    res.set(http::field::content_disposition, "attachment; filename=\"tandem-path.path\"");
    return finish(http::status::ok, "text/plain; charset=utf-8", std::move(*text));
  }
  if (path == "/api/session") {
    const auto journal = control_.journal();
    auto text = journal ? read_file(*journal) : std::nullopt;
    if (!text)
      return finish(http::status::not_found, "text/plain", "no session journal\n");
    res.set(http::field::content_disposition,
            "attachment; filename=\"" + journal->filename().string() + "\"");
    return finish(http::status::ok, "application/x-ndjson", std::move(*text));
  }
  if (path == "/")
    path = "/index.html";
  // Static files: only names of the built front end, never outside its folder.
  if (path.find("..") != std::string::npos || path.find('\\') != std::string::npos ||
      path.find('\0') != std::string::npos)
    return finish(http::status::not_found, "text/plain", "404 not found\n");
  const std::filesystem::path file = options_.web_root / path.substr(1);
  auto body = read_file(file);
  if (!body || std::filesystem::is_directory(file))
    return finish(http::status::not_found, "text/plain", "404 not found\n");
  if (path == "/index.html") {
    res.set(http::field::set_cookie,
            "tandem_token=" + token_ + "; Path=/; HttpOnly; SameSite=Strict");
    res.set("Content-Security-Policy",
            "default-src 'self'; connect-src 'self' ws://" + std::string(req[http::field::host]) +
                "; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:");
  }
  return finish(http::status::ok, mime_type(file), std::move(*body));
}

void check_server_options(const ServerOptions& options) {
  if (!std::filesystem::exists(options.web_root / "index.html")) {
    throw InputError(options.web_root.string(),
                     "the viewer's front end is not built here (scripts/build builds it, with npm "
                     "ci and vite in web/); or run with --headless");
  }
  listen_address(options.host);
}

ViewerServer::ViewerServer(ViewerState& state, ViewerControl& control,
                           const ServerOptions& options) {
  check_server_options(options);
  impl_ = std::make_unique<Impl>(state, control, options);
}

ViewerServer::~ViewerServer() = default;

std::string ViewerServer::url() const {
  return impl_->url();
}

unsigned short ViewerServer::port() const {
  return impl_->port_;
}

std::size_t ViewerServer::clients() const {
  return impl_->clients_.load();
}

std::size_t ViewerServer::connections() const {
  return impl_->connections_.load();
}

}  // namespace tandem
