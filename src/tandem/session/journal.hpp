#pragma once
// The journal of a live session: everything needed to replay it exactly, written as it happens.
//
// Format: JSON Lines (one JSON object per line), in order:
//
//   {"journal":"tandem session","version":1,"problem":"cluttered-1","problem_digest":"…",
//    "mode":"interactive-contact","seed":1,"settings":{…},"operator":"…","started":"…"}
//   {"op":123,"seq":57,"t":0.0571,"pace":0.0571,"q":[x,y,z,qx,qy,qz,qw],"v":[6 numbers],"b":0}
//   {"params":4000,"settings":{…}}
//   {"digest":"…","steps":50000,"iterations":49999,"nodes":1234}
//   {"event":"pause","steps":52000}
//   {"reset":52000}
//   {"op":3,"seq":1234,…}
//   {"end":"solved","steps":61234,"iterations":61233,"nodes":2345,"digest":"…"}
//
// "op" records the planner iteration from which the planner used that operator state (what a
// LiveFeed records; the nearest obstacle and contact frame are recomputed from q_device on replay,
// which FCL does identically); "params" the planner step after which new interaction settings
// applied; "digest" records, written every few seconds, let a replay check itself even when the
// session was killed before its "end". "event" records what the user did that the replay needs
// no more than the records above (pause, resume, step, the input that holds the part: simulated,
// browser, spacemouse), for the record. "reset" records the step after which the user started the
// planner over (new trees, same seed): the "op" records after it count the new planner's
// iterations. Numbers are written so that they read back bit for bit.
//
// Each record is handed to the kernel with one write(2) as soon as it is made: a process that is
// killed loses nothing it recorded (a torn last line, if the kill came mid-write, is ignored when
// reading).
//
// Threading: a JournalWriter belongs to one thread (the planner thread).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tandem/interaction/operator_feed.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem.hpp"
#include "tandem/scene/take_out.hpp"

namespace tandem {

/// A digest of what a problem is: its bodies' geometry and poses, bounds, start and goal. Two
/// problems with equal digests plan identically.
std::uint64_t problem_digest(const Problem& problem);

struct JournalHeader {
  std::string problem;      ///< as given on the command line (a file or a built-in scene's name)
  TakeOutOptions take_out;  ///< for a STEP or IGES problem: the part taken out, and how
  std::string problem_digest;
  std::string mode;  ///< the planner's registry name
  PlannerSettings settings;
  std::string operator_description;
  std::string started;  ///< UTC, ISO 8601
};

struct JournalParams {
  std::uint64_t steps = 0;  ///< applied after this many planner steps
  InteractionSettings settings;
};

struct JournalDigest {
  std::uint64_t steps = 0;
  std::uint64_t iterations = 0;
  std::size_t nodes = 0;
  std::string digest;
  std::optional<std::string> end_status;  ///< set for the "end" record
  std::size_t segment = 0;  ///< resets before it: which planner's tree (set when read back)
};

struct Journal {
  JournalHeader header;
  /// The operator's device readings, with the iteration from which the planner used each.
  struct OperatorRecord {
    std::uint64_t iteration = 0;
    std::size_t segment = 0;  ///< resets before it: which planner used it
    std::uint64_t sequence = 0;
    double time = 0.0, pace = 0.0;
    DeviceReading device;
  };
  std::vector<OperatorRecord> operator_states;
  std::vector<JournalParams> params;
  std::vector<JournalDigest> digests;  ///< in order; the "end" record last, if the session ended
  std::vector<std::uint64_t> resets;   ///< steps after which the planner was started over
  struct Event {
    std::uint64_t steps = 0;
    std::string what;
  };
  std::vector<Event> events;  ///< the user's actions, for the record
  bool torn = false;          ///< the last line was cut short (the process was killed)
};

class JournalWriter {
 public:
  /// Creates (or truncates) the file and writes the header. Throws InputError naming the file.
  JournalWriter(const std::filesystem::path& file, const JournalHeader& header);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  void operator_state(std::uint64_t iteration, const OperatorState& state);
  void params(std::uint64_t steps, const InteractionSettings& settings);
  void digest(const JournalDigest& d);
  void reset(std::uint64_t steps);
  void event(std::uint64_t steps, const std::string& what);
  const std::filesystem::path& file() const { return file_; }

 private:
  void write_line(const std::string& line);

  std::filesystem::path file_;
  int fd_ = -1;
};

/// Throws InputError naming the file and the line for a missing or malformed header, a malformed
/// record (except a torn last line), or records out of order.
Journal read_journal(const std::filesystem::path& file);

/// The header of a session's journal: the problem as the user named it (else its source) and its
/// digest, the planner, the operator, and the time it starts.
JournalHeader session_header(const Problem& problem, const std::string& problem_name,
                             const TakeOutOptions& take_out, const RunSpec& spec,
                             const std::string& operator_description);

/// The digest record of the planner's trees after `steps` steps; `end_status` for the last one.
JournalDigest trees_digest(const Planner& planner, std::uint64_t steps,
                           const std::optional<std::string>& end_status);

/// The current UTC time, ISO 8601 (for journal headers).
std::string utc_now_iso8601();

}  // namespace tandem
