#pragma once
// Who may use the viewer's server (see viewer_server.hpp): a request must carry the session's
// token, in the query (?token=…, the printed URL) or in the tandem_token cookie the page sets; its
// Host header must name this server (against DNS rebinding); its Origin, if sent (a browser always
// sends it with a WebSocket and with cross-site requests), must be this server's page.

#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace tandem::viewer {

/// Whether a and b are equal, in a time that depends on their lengths only (no early exit that
/// would tell an attacker how much of a guessed token was right).
bool equal_constant_time(std::string_view a, std::string_view b);

/// The value of `key` in a query string or a Cookie header ("a=1&b=2", "a=1; b=2"); "" if absent.
std::string field_value(std::string_view text, std::string_view key, char separator);

/// The parts of a request the policy looks at.
struct RequestCredentials {
  std::string_view host;                   ///< the Host header
  std::optional<std::string_view> origin;  ///< the Origin header, if sent
  std::string_view target;                 ///< path and query
  std::string_view cookie;                 ///< the Cookie header
};

/// Threading: immutable after construction, so any thread may ask it.
class AccessPolicy {
 public:
  /// `host` is the address the server listens on and `port` the port it got: the allowed Host
  /// headers are 127.0.0.1, localhost and [::1] at that port, and `host` itself.
  AccessPolicy(std::string token, const std::string& host, unsigned short port);

  const std::string& token() const { return token_; }

  /// Why a request is refused (403), if it is.
  std::optional<std::string> refusal(const RequestCredentials& request) const;

 private:
  std::string token_;
  std::set<std::string> allowed_hosts_;
};

}  // namespace tandem::viewer
