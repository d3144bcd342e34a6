// A libFuzzer program for one target: TANDEM_FUZZ_TARGET names it (fuzz/CMakeLists.txt builds one
// program per target, fuzz_<name>).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "targets/fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const tandem::fuzz::Target* target = [] {
    const tandem::fuzz::Target* t = tandem::fuzz::find_target(TANDEM_FUZZ_TARGET);
    if (t == nullptr) {
      std::fprintf(stderr, "fuzz: no target '%s'\n", TANDEM_FUZZ_TARGET);
      std::abort();
    }
    return t;
  }();
  (void)target->run({reinterpret_cast<const char*>(data), size});
  return 0;
}
