#pragma once
// FNV-1a, 64 bits, over the bytes of values: digests that tell whether two runs built the same
// trees, or two sessions ran on the same scene. Not a cryptographic hash.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>

namespace tandem {

class Digest {
 public:
  template <class T>
  void mix(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char b : bytes) {
      h_ ^= b;
      h_ *= 0x100000001b3ULL;
    }
  }
  /// A pose (anything with a translation t and a quaternion q): translation, then w, x, y, z.
  template <class Pose>
  void mix_pose(const Pose& p) {
    for (int k = 0; k < 3; ++k)
      mix(p.t[k]);
    mix(p.q.w());
    mix(p.q.x());
    mix(p.q.y());
    mix(p.q.z());
  }
  void mix_text(const std::string& text) {
    mix(text.size());
    for (char c : text)
      mix(c);
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

/// A digest as 16 hexadecimal digits.
inline std::string format_digest(std::uint64_t digest) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(digest));
  return buf;
}

}  // namespace tandem
