#include "tandem/web/routes.hpp"

#include <fstream>
#include <optional>
#include <sstream>

namespace tandem::viewer {
namespace {

std::optional<std::string> read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The response with its status, type and body (none for HEAD), ready to send.
http::response<http::string_body> finish(const http::request<http::string_body>& req,
                                         http::response<http::string_body> res, http::status status,
                                         std::string_view type, std::string body) {
  res.result(status);
  res.set(http::field::content_type, beast::string_view(type.data(), type.size()));
  res.body() = std::move(body);
  if (req.method() == http::verb::head)
    res.body().clear();
  res.prepare_payload();
  return res;
}

}  // namespace

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

http::response<http::string_body> Routes::respond(
    const http::request<http::string_body>& req) const {
  Response res{http::status::ok, req.version()};
  res.set(http::field::server, "tandem");
  res.set("X-Content-Type-Options", "nosniff");
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(req.keep_alive());
  if (req.method() != http::verb::get && req.method() != http::verb::head)
    return finish(req, std::move(res), http::status::method_not_allowed, "text/plain",
                  "405 GET only\n");
  const std::string path(req.target().substr(0, req.target().find('?')));
  if (path == "/api/scene")
    return finish(req, std::move(res), http::status::ok, "application/json", state_.scene_json());
  if (path == "/api/path") {
    auto text = state_.path_text();
    if (!text)
      return finish(req, std::move(res), http::status::not_found, "text/plain",
                    "no solution yet\n");
    res.set(http::field::content_disposition, "attachment; filename=\"tandem-path.path\"");
    return finish(req, std::move(res), http::status::ok, "text/plain; charset=utf-8",
                  std::move(*text));
  }
  if (path == "/api/session")
    return session_journal(req, std::move(res));
  if (path == "/api/clearance")
    return product(req, std::move(res), SolutionProduct::clearance_json, "application/json", "");
  if (path == "/api/animation.glb")
    return product(req, std::move(res), SolutionProduct::animation_glb, "model/gltf-binary",
                   "tandem-path.glb");
  if (path == "/api/animation.html")
    return product(req, std::move(res), SolutionProduct::animation_html, "text/html; charset=utf-8",
                   "tandem-path.html");
  if (path == "/api/envelope.stl")
    return product(req, std::move(res), SolutionProduct::envelope_stl, "model/stl",
                   "tandem-envelope.stl");
  return static_file(req, path == "/" ? "/index.html" : path, std::move(res));
}

Routes::Response Routes::session_journal(const http::request<http::string_body>& req,
                                         Response res) const {
  const auto journal = control_.journal();
  auto text = journal ? read_file(*journal) : std::nullopt;
  if (!text)
    return finish(req, std::move(res), http::status::not_found, "text/plain",
                  "no session journal\n");
  res.set(http::field::content_disposition,
          "attachment; filename=\"" + journal->filename().string() + "\"");
  return finish(req, std::move(res), http::status::ok, "application/x-ndjson", std::move(*text));
}

Routes::Response Routes::product(const http::request<http::string_body>& req, Response res,
                                 SolutionProduct which, std::string_view type,
                                 std::string_view download) const {
  auto bytes = products_.get(which);
  if (!bytes) {
    const std::string why = products_.missing(which);
    if (why == "computing")
      res.set(http::field::retry_after, "1");
    return finish(req, std::move(res),
                  why == "computing" ? http::status::service_unavailable : http::status::not_found,
                  "text/plain", why + "\n");
  }
  if (!download.empty())
    res.set(http::field::content_disposition,
            "attachment; filename=\"" + std::string(download) + "\"");
  return finish(req, std::move(res), http::status::ok, type, std::move(*bytes));
}

Routes::Response Routes::static_file(const http::request<http::string_body>& req,
                                     const std::string& path, Response res) const {
  // Only names of the built front end, never outside its folder.
  if (path.find("..") != std::string::npos || path.find('\\') != std::string::npos ||
      path.find('\0') != std::string::npos)
    return finish(req, std::move(res), http::status::not_found, "text/plain", "404 not found\n");
  const std::filesystem::path file = web_root_ / path.substr(1);
  auto body = read_file(file);
  if (!body || std::filesystem::is_directory(file))
    return finish(req, std::move(res), http::status::not_found, "text/plain", "404 not found\n");
  if (path == "/index.html") {
    res.set(http::field::set_cookie,
            "tandem_token=" + token_ + "; Path=/; HttpOnly; SameSite=Strict");
    res.set("Content-Security-Policy", "default-src 'self'; connect-src 'self' ws://" +
                                           std::string(req[http::field::host]) +
                                           "; style-src 'self' 'unsafe-inline'; img-src 'self' "
                                           "data: blob:; media-src 'self' blob:");
  }
  return finish(req, std::move(res), http::status::ok, mime_type(file), std::move(*body));
}

}  // namespace tandem::viewer
