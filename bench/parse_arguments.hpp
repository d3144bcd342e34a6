#pragma once
// The benchmark tools' command line, parsed as tandem's own: --help prints and exits 0, a bad
// option or value gets one error line naming it and exit code 2 (CLI11_PARSE would exit 105+).

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

namespace bench {

/// nullopt: go on; else the code to exit with.
inline std::optional<int> parse_arguments(CLI::App& app, int argc, char** argv,
                                          const std::string& tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": error: " << e.what() << " (see '" << tool << " --help')\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace bench
