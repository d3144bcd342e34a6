#include "tandem/web/viewer_server.hpp"

#include <cstdlib>
#include <random>
#include <thread>

#include "tandem/core/error.hpp"
#include "tandem/web/access_policy.hpp"
#include "tandem/web/routes.hpp"
#include "tandem/web/server_io.hpp"
#include "tandem/web/socket_session.hpp"

namespace tandem {

using namespace viewer;  // NOLINT: the server's parts, in this file only

namespace {

constexpr std::chrono::milliseconds kTick{15};

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

/// An acceptor listening at options.host:options.port.
tcp::acceptor open_acceptor(net::io_context& ioc, const ServerOptions& options) {
  tcp::acceptor acceptor(ioc);
  boost::system::error_code ec;
  const tcp::endpoint endpoint(listen_address(options.host), options.port);
  acceptor.open(endpoint.protocol(), ec);
  if (!ec)
    acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec)
    acceptor.bind(endpoint, ec);
  if (!ec)
    acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) {
    throw InputError("--port", "cannot listen on " + options.host + ":" +
                                   std::to_string(options.port) + ": " + ec.message());
  }
  return acceptor;
}

RequestCredentials credentials(const http::request<http::string_body>& req) {
  RequestCredentials c;
  c.host = sv(req[http::field::host]);
  if (const auto origin = req.find(http::field::origin); origin != req.end())
    c.origin = sv(origin->value());
  c.target = sv(req.target());
  c.cookie = sv(req[http::field::cookie]);
  return c;
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

/// The listener: accepts connections, reads their HTTP requests (HttpSession), refuses what the
/// access policy refuses, answers the rest from the routes or hands them to a WebSocket session;
/// and every tick, sends each socket what is new.
///
/// Threading: the constructor starts one thread that runs the io_context; every handler, session
/// and the hub run there. The destructor stops that thread and joins it. url() and the hub's
/// counters may be read from any thread.
class ViewerServer::Impl {
 public:
  Impl(ViewerState& state, ViewerControl& control, const ServerOptions& options)
      : options_(options),
        acceptor_(open_acceptor(ioc_, options)),
        port_(acceptor_.local_endpoint().port()),
        policy_(options.token.empty() ? random_token() : options.token, options.host, port_),
        products_(state, options.web_root),
        routes_(state, control, products_, options.web_root, policy_.token()),
        hub_(state, control),
        tick_(ioc_) {
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
           std::to_string(port_) + "/?token=" + policy_.token();
  }

  void accept();
  void schedule_tick();

  ServerOptions options_;
  net::io_context ioc_{1};
  tcp::acceptor acceptor_;
  unsigned short port_ = 0;
  AccessPolicy policy_;
  SolutionProducts products_;  ///< before the routes, which answer from it
  Routes routes_;
  SocketHub hub_;  ///< server thread only, but for its counters
  net::steady_timer tick_;
  std::thread thread_;
};

namespace {

/// One HTTP connection: reads requests one after another until it closes, or until one becomes
/// a WebSocket. Threading: the server's thread.
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
    if (auto why = server_.policy_.refusal(credentials(req))) {
      log_line("refused " + target.substr(0, target.find('?')) + " from " + peer() + ": " + *why);
      write(plain_reply(http::status::forbidden, req.version(), "403 forbidden: " + *why + "\n"));
      return;
    }
    if (upgrade && server_.hub_.open() >= kMaxSockets) {
      log_line("refused a WebSocket from " + peer() + ": " + std::to_string(kMaxSockets) +
               " are open");
      write(
          plain_reply(http::status::service_unavailable, req.version(), "503 too many viewers\n"));
      return;
    }
    if (upgrade) {
      std::make_shared<SocketSession>(server_.hub_, stream_.release_socket())
          ->start(std::move(req));
      return;
    }
    write(server_.routes_.respond(req));
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

}  // namespace

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
    hub_.pump_all();
    schedule_tick();
  });
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
  return impl_->hub_.clients();
}

std::size_t ViewerServer::connections() const {
  return impl_->hub_.connections();
}

}  // namespace tandem
