#pragma once
// Errors tandem reports to its user.
//
// InputError is the one exception type for bad input: a missing or malformed file, an impossible
// problem, a nonsensical option value. Its message always names the source (a file, or an option)
// and the fault, so the command-line program can print it as one line and exit with code 2.
// Programming errors are not InputErrors; they are std::logic_error and indicate a bug in tandem.

#include <stdexcept>
#include <string>

namespace tandem {

class InputError : public std::runtime_error {
 public:
  /// `source` names where the fault is (a file path, "--seed", "scenario 'x'"); `fault` says what
  /// is wrong.
  InputError(const std::string& source, const std::string& fault)
      : std::runtime_error(source.empty() ? fault : source + ": " + fault), source_(source) {}

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

}  // namespace tandem
