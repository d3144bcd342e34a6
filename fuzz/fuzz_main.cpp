// A libFuzzer program for one target: TANDEM_FUZZ_TARGET names it (fuzz/CMakeLists.txt builds one
// program per target, fuzz_<name>).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "targets/fuzz_target.hpp"

namespace {

const tandem::fuzz::Target& the_target() {
  static const tandem::fuzz::Target* target = [] {
    const tandem::fuzz::Target* t = tandem::fuzz::find_target(TANDEM_FUZZ_TARGET);
    if (t == nullptr) {
      std::fprintf(stderr, "fuzz: no target '%s'\n", TANDEM_FUZZ_TARGET);
      std::abort();
    }
    return t;
  }();
  return *target;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  if (the_target().prepare != nullptr)
    the_target().prepare();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)the_target().run({reinterpret_cast<const char*>(data), size});
  return 0;
}
