#include "tandem/session/journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <variant>

#include "tandem/core/digest.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/io/json_codec.hpp"

namespace tandem {
namespace {

using nlohmann::json;

constexpr const char* kMagic = "tandem session";
constexpr int kVersion = 1;

void mix_body(Digest& d, const Body& body) {
  d.mix_text(body.name);
  d.mix(body.parts.size());
  for (const Part& part : body.parts) {
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        d.mix(part.pose.matrix()(r, c));
    std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Box>) {
            d.mix('b');
            for (int k = 0; k < 3; ++k)
              d.mix(g.size[k]);
          } else if constexpr (std::is_same_v<G, Sphere>) {
            d.mix('s');
            d.mix(g.radius);
          } else if constexpr (std::is_same_v<G, Cylinder>) {
            d.mix('c');
            d.mix(g.radius);
            d.mix(g.length);
          } else {
            d.mix('m');
            d.mix(g.mesh->vertices.size());
            for (const auto& v : g.mesh->vertices)
              for (int k = 0; k < 3; ++k)
                d.mix(v[k]);
            d.mix(g.mesh->triangles.size());
            for (const auto& t : g.mesh->triangles)
              d.mix(t);
          }
        },
        part.geometry);
  }
}

json settings_json(const PlannerSettings& s) {
  json j = interaction_json(s.interaction);
  j.update(settings_json(planner_parameters(), s));
  return j;
}

/// The planner's settings of a header: every declared tunable, each within its range.
PlannerSettings settings_from_json(const json& j, std::uint64_t seed) {
  PlannerSettings s;
  s.seed = seed;
  read_settings_json(planner_parameters(), j, s);
  s.interaction = interaction_from_json(j);
  return s;
}

json digest_json(const JournalDigest& d) {
  json j;
  if (d.end_status)
    j["end"] = *d.end_status;
  j["digest"] = d.digest;
  j["steps"] = d.steps;
  j["iterations"] = d.iterations;
  j["nodes"] = d.nodes;
  return j;
}

}  // namespace

std::uint64_t problem_digest(const Problem& problem) {
  Digest d;
  mix_body(d, problem.scene.object);
  d.mix(problem.scene.obstacles.size());
  for (const Body& b : problem.scene.obstacles)
    mix_body(d, b);
  const Bounds& b = problem.space.bounds();
  for (int k = 0; k < 3; ++k) {
    d.mix(b.min[k]);
    d.mix(b.max[k]);
  }
  d.mix(problem.space.kind());
  d.mix(problem.space.resolution());
  d.mix(problem.space.weights().translation);
  d.mix(problem.space.weights().rotation);
  d.mix_pose(problem.start);
  d.mix_pose(problem.goal);
  return d.value();
}

JournalWriter::JournalWriter(const std::filesystem::path& file, const JournalHeader& h)
    : file_(file) {
  fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(file.string(), std::string("cannot be written: ") + std::strerror(errno));
  json j{{"journal", kMagic},
         {"version", kVersion},
         {"problem", h.problem},
         {"problem_digest", h.problem_digest},
         {"mode", h.mode},
         {"seed", h.settings.seed},
         {"settings", settings_json(h.settings)},
         {"operator", h.operator_description},
         {"started", h.started}};
  if (!h.take_out.part.empty()) {
    const TakeOutOptions& t = h.take_out;
    j["take_out"] = {{"part", t.part},
                     {"margin", t.margin},
                     {"seat_tolerance", t.seat_tolerance},
                     {"linear_deflection", t.cad.linear_deflection},
                     {"angular_deflection", t.cad.angular_deflection}};
  }
  write_line(j.dump());
}

JournalWriter::~JournalWriter() {
  if (fd_ >= 0)
    ::close(fd_);
}

void JournalWriter::write_line(const std::string& line) {
  std::string text = line + '\n';
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      throw InputError(file_.string(), std::string("cannot be written: ") + std::strerror(errno));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void JournalWriter::operator_state(std::uint64_t iteration, const OperatorState& s) {
  const Twist& v = s.device.velocity;
  write_line(json{{"op", iteration},
                  {"seq", s.sequence},
                  {"t", s.time},
                  {"pace", s.pace},
                  {"q", config_json(s.device.q_device)},
                  {"v", json::array({v[0], v[1], v[2], v[3], v[4], v[5]})},
                  {"b", s.device.buttons}}
                 .dump());
}

void JournalWriter::params(std::uint64_t steps, const InteractionSettings& settings) {
  write_line(json{{"params", steps}, {"settings", interaction_json(settings)}}.dump());
}

void JournalWriter::digest(const JournalDigest& d) {
  write_line(digest_json(d).dump());
}

void JournalWriter::reset(std::uint64_t steps) {
  write_line(json{{"reset", steps}}.dump());
}

void JournalWriter::event(std::uint64_t steps, const std::string& what) {
  write_line(json{{"event", what}, {"steps", steps}}.dump());
}

namespace {

/// Where a record's fault is: "FILE: line N".
struct RecordAt {
  const std::filesystem::path& file;
  std::string line;
  [[noreturn]] void fail(const std::string& fault) const {
    throw InputError(file.string(), line + ": " + fault);
  }
};

/// A whole-number field. nlohmann's get<> converts a float or a negative number to an unsigned type
/// by a plain cast, undefined out of range (a finding of the journal fuzz target): check it first.
template <typename T>
T whole(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_number_unsigned() ||
      v.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) {
    throw std::invalid_argument(std::string("'") + key + "' must be a whole number from 0 to " +
                                std::to_string(std::numeric_limits<T>::max()));
  }
  return static_cast<T>(v.get<std::uint64_t>());
}

void read_header(const json& j, const std::filesystem::path& file, JournalHeader& h) {
  if (!j.is_object() || j.value("journal", "") != kMagic)
    throw InputError(file.string(), "not a tandem session journal (no header line)");
  if (whole<int>(j, "version") != kVersion) {
    throw InputError(file.string(), "journal version " + std::to_string(whole<int>(j, "version")) +
                                        " (this tandem reads version 1)");
  }
  h.problem = j.at("problem").get<std::string>();
  h.problem_digest = j.at("problem_digest").get<std::string>();
  h.mode = j.at("mode").get<std::string>();
  h.settings = settings_from_json(j.at("settings"), whole<std::uint64_t>(j, "seed"));
  h.operator_description = j.at("operator").get<std::string>();
  h.started = j.at("started").get<std::string>();
  if (j.contains("take_out")) {
    const json& t = j.at("take_out");
    h.take_out.part = t.at("part").get<std::string>();
    h.take_out.margin = t.at("margin").get<double>();
    h.take_out.seat_tolerance = t.at("seat_tolerance").get<double>();
    h.take_out.cad.linear_deflection = t.at("linear_deflection").get<double>();
    h.take_out.cad.angular_deflection = t.at("angular_deflection").get<double>();
  }
}

void read_operator_record(const json& j, const RecordAt& at, Journal& journal) {
  Journal::OperatorRecord r;
  r.iteration = whole<std::uint64_t>(j, "op");
  r.sequence = whole<std::uint64_t>(j, "seq");
  r.time = j.at("t").get<double>();
  r.pace = j.at("pace").get<double>();
  r.device.q_device = config_from_json(j.at("q"));
  const json& v = j.at("v");
  if (!v.is_array() || v.size() != 6)
    throw std::invalid_argument("a velocity is 6 numbers");
  for (std::size_t k = 0; k < 6; ++k)
    r.device.velocity[static_cast<Eigen::Index>(k)] = v[k].get<double>();
  r.device.buttons = whole<std::uint32_t>(j, "b");
  r.segment = journal.resets.size();
  if (!journal.operator_states.empty() && journal.operator_states.back().segment == r.segment &&
      r.iteration < journal.operator_states.back().iteration) {
    at.fail("operator record before the previous one");
  }
  journal.operator_states.push_back(r);
}

void read_digest(const json& j, const RecordAt& at, Journal& journal) {
  JournalDigest d;
  if (j.contains("end"))
    d.end_status = j.at("end").get<std::string>();
  d.digest = j.at("digest").get<std::string>();
  d.steps = whole<std::uint64_t>(j, "steps");
  d.iterations = whole<std::uint64_t>(j, "iterations");
  d.nodes = whole<std::size_t>(j, "nodes");
  d.segment = journal.resets.size();
  if (!journal.digests.empty() && d.steps < journal.digests.back().steps)
    at.fail("digest before the previous one");
  journal.digests.push_back(d);
}

/// A record after the header.
void read_record(const json& j, const RecordAt& at, Journal& journal) {
  if (j.contains("op")) {
    read_operator_record(j, at, journal);
  } else if (j.contains("params")) {
    JournalParams p;
    p.steps = whole<std::uint64_t>(j, "params");
    p.settings = interaction_from_json(j.at("settings"));
    if (!journal.params.empty() && p.steps < journal.params.back().steps)
      at.fail("parameters before the previous ones");
    journal.params.push_back(p);
  } else if (j.contains("event")) {
    journal.events.push_back({whole<std::uint64_t>(j, "steps"), j.at("event").get<std::string>()});
  } else if (j.contains("reset")) {
    const auto steps = whole<std::uint64_t>(j, "reset");
    if (!journal.resets.empty() && steps < journal.resets.back())
      at.fail("reset before the previous one");
    journal.resets.push_back(steps);
  } else if (j.contains("digest")) {
    read_digest(j, at, journal);
  } else {
    at.fail("unknown record");
  }
}

}  // namespace

Journal read_journal(const std::filesystem::path& file) {
  const std::string text = read_text_file(file);
  Journal journal;
  std::size_t line_no = 0, pos = 0;
  bool have_header = false;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const RecordAt at{file, "line " + std::to_string(++line_no)};
    if (end == std::string::npos) {
      // A last line without its newline: the process was killed while writing it.
      journal.torn = true;
      break;
    }
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (trim(line).empty())
      continue;
    json j;
    try {
      j = json::parse(line);
    } catch (const json::exception&) {
      at.fail("not a JSON object");
    }
    try {
      if (have_header)
        read_record(j, at, journal);
      else
        read_header(j, file, journal.header);
      have_header = true;
    } catch (const json::exception& e) {
      at.fail(std::string("malformed record (") + e.what() + ")");
    } catch (const std::invalid_argument& e) {
      at.fail(e.what());
    }
  }
  if (!have_header)
    throw InputError(file.string(), "empty: not a tandem session journal");
  return journal;
}

JournalHeader session_header(const Problem& problem, const std::string& problem_name,
                             const TakeOutOptions& take_out, const RunSpec& spec,
                             const std::string& operator_description) {
  JournalHeader h;
  h.problem = problem_name.empty() ? problem.source : problem_name;
  h.take_out = take_out;
  h.problem_digest = format_digest(problem_digest(problem));
  h.mode = spec.mode;
  h.settings = spec.settings;
  h.operator_description = operator_description;
  h.started = utc_now_iso8601();
  return h;
}

JournalDigest trees_digest(const Planner& planner, std::uint64_t steps,
                           const std::optional<std::string>& end_status) {
  JournalDigest d;
  d.steps = steps;
  d.iterations = planner.stats().iterations;
  d.nodes = planner.stats().nodes;
  d.digest = format_digest(tree_digest(planner.trees()));
  d.end_status = end_status;
  return d;
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace tandem
