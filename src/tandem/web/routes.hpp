#pragma once
// What the viewer's server answers over HTTP, to a request the access policy let through:
//   /              the front end's index.html (with the token cookie and a content security policy)
//   /<file>        the built front end's other files, never outside its folder
//   /api/scene     the scene, as JSON
//   /api/path      the solution, as a path file (404 until there is one)
//   /api/session   the session's journal (404 without one)
//   /api/clearance       the solution's clearance, as JSON (tandem clearance --json's form)
//   /api/animation.glb   the solution as an animated glTF binary (tandem export --glb)
//   /api/animation.html  its offline page (tandem export --html)
//   /api/envelope.stl    the part's motion envelope along the solution (asking starts it)
//   (each: 404 with no solution, 503 with a Retry-After while it is computed)
// GET and HEAD only.

#include <filesystem>
#include <string>
#include <string_view>

#include "tandem/web/server_io.hpp"
#include "tandem/web/solution_products.hpp"
#include "tandem/web/viewer_server.hpp"

namespace tandem::viewer {

/// The Content-Type of a front-end file, by its extension.
std::string_view mime_type(const std::filesystem::path& file);

/// Threading: respond() on the server's thread (it reads the ViewerState, which is thread-safe,
/// and asks the control for its journal).
class Routes {
 public:
  Routes(ViewerState& state, ViewerControl& control, const SolutionProducts& products,
         std::filesystem::path web_root, std::string token)
      : state_(state),
        control_(control),
        products_(products),
        web_root_(std::move(web_root)),
        token_(std::move(token)) {}

  http::response<http::string_body> respond(const http::request<http::string_body>& req) const;

 private:
  using Response = http::response<http::string_body>;
  /// A file of the front end (`path` starts with '/').
  Response static_file(const http::request<http::string_body>& req, const std::string& path,
                       Response res) const;
  Response session_journal(const http::request<http::string_body>& req, Response res) const;
  /// One of the solution's products, as a download named `download` (none: shown in the page).
  Response product(const http::request<http::string_body>& req, Response res,
                   SolutionProduct product, std::string_view type, std::string_view download) const;

  ViewerState& state_;
  ViewerControl& control_;
  const SolutionProducts& products_;
  std::filesystem::path web_root_;
  std::string token_;
};

}  // namespace tandem::viewer
