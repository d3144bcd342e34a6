#pragma once
// What the parts of the viewer's server share (viewer_server.cpp, routes, socket_session): the
// names of Boost.Beast and Asio, and its log. Internal to src/tandem/web.

// Before Asio, whose awaitable.hpp uses std::exchange without including it.
#include <utility>
// Asio and Beast.
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <iostream>
#include <string>
#include <string_view>

namespace tandem::viewer {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

inline std::string_view sv(beast::string_view s) {
  return {s.data(), s.size()};
}

/// One line on stderr: refusals, closed sockets.
inline void log_line(const std::string& text) {
  std::cerr << "tandem viewer: " << text << '\n' << std::flush;
}

}  // namespace tandem::viewer
