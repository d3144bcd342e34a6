#include "tandem/web/access_policy.hpp"

namespace tandem::viewer {

bool equal_constant_time(std::string_view a, std::string_view b) {
  if (a.size() != b.size())
    return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

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

AccessPolicy::AccessPolicy(std::string token, const std::string& host, unsigned short port)
    : token_(std::move(token)) {
  const std::string p = std::to_string(port);
  allowed_hosts_ = {"127.0.0.1:" + p, "localhost:" + p, "[::1]:" + p};
  if (host != "127.0.0.1" && host != "::1")
    allowed_hosts_.insert(host + ":" + p);
}

std::optional<std::string> AccessPolicy::refusal(const RequestCredentials& request) const {
  const std::string host(request.host);
  if (!allowed_hosts_.contains(host))
    return "Host '" + host.substr(0, 80) + "' is not this server";
  if (request.origin && *request.origin != "http://" + host) {
    return "Origin '" + std::string(*request.origin).substr(0, 80) + "' is not this server's page";
  }
  const std::string_view target = request.target;
  const auto q = target.find('?');
  const std::string from_query =
      q == std::string_view::npos ? std::string() : field_value(target.substr(q + 1), "token", '&');
  const std::string from_cookie = field_value(request.cookie, "tandem_token", ';');
  if (!equal_constant_time(from_query, token_) && !equal_constant_time(from_cookie, token_))
    return "missing or wrong token (open the URL tandem printed)";
  return std::nullopt;
}

}  // namespace tandem::viewer
