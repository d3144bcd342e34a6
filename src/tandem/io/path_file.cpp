#include "tandem/io/path_file.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem {
namespace {

void append_number(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  out += buf;
}

}  // namespace

std::string format_path(const Path& path, const SE3Space& space) {
  std::string out;
  for (const Config& q : path) {
    if (space.planar()) {
      const double values[] = {q.t.x(), q.t.y(), SE3Space::yaw(q.q)};
      for (int i = 0; i < 3; ++i) {
        if (i)
          out += ' ';
        append_number(out, values[i]);
      }
    } else {
      const double values[] = {q.t.x(), q.t.y(), q.t.z(), q.q.x(), q.q.y(), q.q.z(), q.q.w()};
      for (int i = 0; i < 7; ++i) {
        if (i)
          out += ' ';
        append_number(out, values[i]);
      }
    }
    out += '\n';
  }
  return out;
}

void write_path_file(const std::filesystem::path& file, const Path& path, const SE3Space& space) {
  write_file_atomically(file, format_path(path, space));
}

Path parse_path(const std::string& text, const SE3Space& space, const std::string& source) {
  Path path;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  const std::size_t expected = space.planar() ? 3 : 7;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = source + ":" + std::to_string(number);
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#')
      continue;
    const auto fields = split_whitespace(t);
    if (fields.size() != expected) {
      throw InputError(where, "expected " + std::to_string(expected) + " numbers (" +
                                  (space.planar() ? "x y theta" : "x y z qx qy qz qw") +
                                  "), found " + std::to_string(fields.size()));
    }
    double v[7];
    for (std::size_t i = 0; i < expected; ++i) {
      auto d = parse_double(fields[i]);
      if (!d || !std::isfinite(*d))
        throw InputError(where, "'" + std::string(fields[i]) + "' is not a finite number");
      v[i] = *d;
    }
    if (space.planar()) {
      path.push_back(space.planar_config(v[0], v[1], v[2]));
      continue;
    }
    Config q;
    q.t = {v[0], v[1], v[2]};
    const auto unit =
        unit_quaternion(v[6], v[3], v[4], v[5], kMinQuaternionNorm, kUnitQuaternionSlack);
    if (!unit)
      throw InputError(where, "the quaternion is zero");
    q.q = *unit;
    path.push_back(q);
  }
  if (path.empty())
    throw InputError(source, "the path has no states");
  return path;
}

Path read_path_file(const std::filesystem::path& file, const SE3Space& space) {
  return parse_path(read_text_file(file), space, file.string());
}

}  // namespace tandem
