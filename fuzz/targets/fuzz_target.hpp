#pragma once
// The fuzz targets: one per parser of what tandem reads from a user. Each takes the raw bytes of one
// input, hands them to the parser as the user's file or message would reach it, and returns quietly
// when the parser refuses them with its error (InputError; ProtocolError for the viewer's
// messages). Anything else escapes: an uncaught exception, a crash, a sanitizer report or a hang is
// a finding. fuzz_main.cpp makes a libFuzzer program of each; tests/fuzz replays the corpora
// through the same functions in the unit tests.
//
// Threading: a target runs on one thread; the targets that write files use a scratch folder of
// their process (scratch_folder.hpp).

#include <span>
#include <string_view>

namespace tandem::fuzz {

using TargetFunction = bool (*)(std::string_view input);

struct Target {
  std::string_view name;  ///< the program is fuzz_<name>; its corpora are in fuzz/*/<name>
  TargetFunction run;
  std::string_view what;  ///< what it parses, for scripts/fuzz --list
  /// Builds what every input uses (before the first input, outside libFuzzer's time limit), if set.
  void (*prepare)() = nullptr;
};

bool cfg(std::string_view input);
bool scenario(std::string_view input);
bool experiment(std::string_view input);
bool path(std::string_view input);
bool trace(std::string_view input);
bool journal(std::string_view input);
void prepare_journal();
bool protocol(std::string_view input);
bool step(std::string_view input);

/// Every target, in the order above.
std::span<const Target> targets();
/// The target called `name`, or nullptr.
const Target* find_target(std::string_view name);

}  // namespace tandem::fuzz
