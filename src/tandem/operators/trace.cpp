#include "tandem/operators/trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem {

std::string format_trace(const Trace& trace) {
  std::string out = "# tandem operator trace 1\n# clock: ";
  out += trace.clock == OperatorClock::ticks ? "ticks" : "seconds";
  out += "\n# t x y z qx qy qz qw buttons\n";
  char buf[64];
  for (const TraceSample& s : trace.samples) {
    const double values[] = {s.t,       s.q.t.x(), s.q.t.y(), s.q.t.z(),
                             s.q.q.x(), s.q.q.y(), s.q.q.z(), s.q.q.w()};
    for (double v : values) {
      std::snprintf(buf, sizeof buf, "%.17g ", v);
      out += buf;
    }
    out += std::to_string(s.buttons);
    out += '\n';
  }
  return out;
}

Trace parse_trace(const std::string& text, const std::string& source) {
  Trace trace;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  bool have_format = false, have_clock = false;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = source + ":" + std::to_string(number);
    const std::string s = trim(line);
    if (s.empty())
      continue;
    if (s[0] == '#') {
      if (s == "# tandem operator trace 1")
        have_format = true;
      if (s.rfind("# clock:", 0) == 0) {
        const std::string clock = trim(s.substr(8));
        if (clock == "ticks")
          trace.clock = OperatorClock::ticks;
        else if (clock == "seconds")
          trace.clock = OperatorClock::seconds;
        else
          throw InputError(where, "unknown clock '" + clock + "' (ticks or seconds)");
        have_clock = true;
      }
      continue;
    }
    if (!have_format)
      throw InputError(
          source,
          "not a tandem operator trace (the first line must be '# tandem operator trace 1')");
    if (!have_clock)
      throw InputError(where, "the '# clock:' line must come before the samples");
    const auto fields = split_whitespace(s);
    if (fields.size() != 9) {
      throw InputError(where, "expected 9 fields (t x y z qx qy qz qw buttons), found " +
                                  std::to_string(fields.size()));
    }
    double v[8];
    for (std::size_t i = 0; i < 8; ++i) {
      auto d = parse_double(fields[i]);
      if (!d || !std::isfinite(*d))
        throw InputError(where, "'" + std::string(fields[i]) + "' is not a finite number");
      v[i] = *d;
    }
    auto buttons = parse_uint(fields[8]);
    if (!buttons || *buttons > UINT32_MAX)
      throw InputError(where, "buttons must be an unsigned 32-bit integer");
    TraceSample sample;
    sample.t = v[0];
    sample.q.t = {v[1], v[2], v[3]};
    const auto unit =
        unit_quaternion(v[7], v[4], v[5], v[6], kMinQuaternionNorm, kUnitQuaternionSlack);
    if (!unit)
      throw InputError(where, "the quaternion is zero");
    sample.q.q = *unit;
    sample.buttons = static_cast<std::uint32_t>(*buttons);
    if (sample.t < 0.0)
      throw InputError(where, "time must not be negative");
    if (!trace.samples.empty() && sample.t < trace.samples.back().t)
      throw InputError(where, "time goes backwards");
    trace.samples.push_back(sample);
  }
  if (!have_format)
    throw InputError(
        source, "not a tandem operator trace (the first line must be '# tandem operator trace 1')");
  if (trace.samples.empty())
    throw InputError(source, "the trace has no samples");
  return trace;
}

Trace read_trace_file(const std::filesystem::path& file) {
  return parse_trace(read_text_file(file), file.string());
}

void write_trace_file(const std::filesystem::path& file, const Trace& trace) {
  write_file_atomically(file, format_trace(trace));
}

TracePlayer::TracePlayer(const SE3Space& space, Trace trace)
    : space_(space), trace_(std::move(trace)) {
  if (trace_.samples.empty())
    throw std::invalid_argument("an empty trace");
}

Config TracePlayer::pose(double t) const {
  const auto& s = trace_.samples;
  if (t <= s.front().t)
    return s.front().q;
  if (t >= s.back().t)
    return s.back().q;
  auto it = std::upper_bound(s.begin(), s.end(), t,
                             [](double x, const TraceSample& a) { return x < a.t; });
  const TraceSample& b = *it;
  const TraceSample& a = *(it - 1);
  if (b.t <= a.t)
    return b.q;
  return space_.interpolate(a.q, b.q, (t - a.t) / (b.t - a.t));
}

DeviceReading TracePlayer::read(double t) const {
  DeviceReading r;
  r.q_device = pose(t);
  const auto& s = trace_.samples;
  auto it = std::upper_bound(s.begin(), s.end(), t,
                             [](double x, const TraceSample& a) { return x < a.t; });
  r.buttons = it == s.begin() ? s.front().buttons : (it - 1)->buttons;
  // Velocity: the rate of change over the sample interval around t.
  if (it != s.begin() && it != s.end() && it->t > (it - 1)->t) {
    const double dt = it->t - (it - 1)->t;
    r.velocity.head<3>() = (it->q.t - (it - 1)->q.t) / dt;
    Eigen::Quaterniond dq = it->q.q * (it - 1)->q.q.inverse();
    if (dq.w() < 0.0)
      dq.coeffs() = -dq.coeffs();
    const Eigen::AngleAxisd aa(dq);
    r.velocity.tail<3>() = aa.axis() * aa.angle() / dt;
  }
  return r;
}

std::string TracePlayer::describe() const {
  std::ostringstream os;
  os << "trace of " << trace_.samples.size() << " samples over " << end_time()
     << (trace_.clock == OperatorClock::ticks ? " ticks" : " s");
  return os.str();
}

}  // namespace tandem
