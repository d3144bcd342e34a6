#include "viewer_options.hpp"

namespace tandem::cli {

void add_viewer_options(CLI::App& app, ViewerArgs& args) {
  app.add_option("--host", args.host,
                 "Address the viewer listens on (default 127.0.0.1: this machine only)");
  app.add_option("--port", args.port, "The viewer's port (default 8170; 0: any free port)")
      ->check(CLI::Range(0, 65535));
  app.add_option("--web-root", args.web_root,
                 "The built front end to serve (default: web/dist of the source tree, or "
                 "$TANDEM_WEB_ROOT)");
}

ServerOptions server_options(const ViewerArgs& args) {
  ServerOptions o;
  o.host = args.host;
  o.port = static_cast<unsigned short>(args.port);
  o.token = args.token;
  o.web_root = args.web_root.empty() ? default_web_root() : std::filesystem::path(args.web_root);
  return o;
}

}  // namespace tandem::cli
