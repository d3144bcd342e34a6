#pragma once
// The options of the commands that serve the web viewer (interactive, demo, replay).

#include <CLI/CLI.hpp>
#include <string>

#include "tandem/web/viewer_server.hpp"

namespace tandem::cli {

struct ViewerArgs {
  std::string host = "127.0.0.1";
  int port = 8170;
  std::string web_root;
  std::string
      token;  ///< not an option: empty for a random one; set to keep a page's across servers
};

void add_viewer_options(CLI::App& app, ViewerArgs& args);
ServerOptions server_options(const ViewerArgs& args);

}  // namespace tandem::cli
