#pragma once
// What the viewer shows, handed from the planner thread to the server's thread.
//
// The planner thread calls update() a few tens of times a second (LiveSession's observer, or a
// replay): it appends the trees' new nodes to a copy kept here (a few floats each, so the planner
// loses almost nothing) and replaces the latest status, operator state and solution. The server's
// thread asks, for each browser, for what that browser has not had yet (a Cursor), so a slow or new
// browser simply gets a larger batch — nothing is queued per browser, and a browser that goes away
// never holds up the planner.
//
// Threading: update() and restarted() on the planner thread; the rest on any thread (one mutex,
// held for copies only).

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tandem/session/live_session.hpp"
#include "tandem/web/protocol.hpp"

namespace tandem {

struct Frame {
  bool binary = false;
  std::string data;
};

class ViewerState final : public LiveObserver {
 public:
  /// `mode` and `replay` go into the hello message.
  ViewerState(const Problem& problem, std::string mode, bool replay);

  // Planner thread.
  void observe(const LiveSession& session, const Planner& planner) override;
  void restarted() override;
  /// The planner's trees and solution; `status` and `op` as JSON text (already encoded).
  void update(const Planner& planner, std::string status, std::string op);

  // Any thread.
  struct Cursor {
    std::uint32_t generation = 0;
    bool greeted = false;
    std::vector<std::uint32_t> sent;  ///< nodes sent, per tree
    std::uint64_t status = 0, op = 0, solution = 0;
  };
  /// The messages a browser at `cursor` has not had, at most `max_nodes` nodes in all; advances
  /// the cursor.
  std::vector<Frame> pending(Cursor& cursor, std::size_t max_nodes = 50000) const;
  /// Increases whenever there is something new.
  std::uint64_t version() const;
  const std::string& scene_json() const { return scene_; }
  /// The solution in OMPL's path format, if there is one.
  std::optional<std::string> path_text() const;
  /// The solution (empty if none) and its number, which changes whenever the solution does.
  std::pair<std::uint64_t, std::vector<Config>> solution() const;
  const Problem& problem() const { return problem_; }
  std::size_t node_count() const;

 private:
  struct TreeCopy {
    std::vector<float> positions, labels;
    std::vector<std::uint32_t> parents;
    std::vector<std::uint8_t> sources;
  };

  const Problem& problem_;
  std::string scene_;
  std::string mode_;
  bool replay_;
  nlohmann::json parameters_;  ///< the hello's tunables
  mutable std::mutex mutex_;
  std::uint32_t generation_ = 0;
  std::vector<TreeCopy> trees_;
  std::string status_, op_;
  std::vector<Config> solution_;
  std::uint64_t status_seq_ = 0, op_seq_ = 0, solution_seq_ = 0, version_ = 0;
};

/// The status and operator messages of a live session (JSON text).
std::string live_status_json(const LiveSession& session, const Planner& planner);
/// The status message of a replay: "replaying", then the planner's status when `done`.
std::string replay_status_json(const Planner& planner, std::string_view mode, double elapsed_s,
                               bool done);
std::string operator_json(const OperatorState* state, const InteractionSettings& settings,
                          const SE3Space& space, const Guidance* guidance);

}  // namespace tandem
