#include "tandem/web/viewer_state.hpp"

#include <nlohmann/json.hpp>

#include "tandem/io/json_codec.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {

using nlohmann::json;

ViewerState::ViewerState(const Problem& problem, std::string mode, bool replay)
    : problem_(problem),
      scene_(encode_scene(problem)),
      mode_(std::move(mode)),
      replay_(replay),
      // A replay cannot be tuned: it announces no tunable.
      parameters_(replay ? json::array()
                         : announced_parameters(mode_, default_settings(mode_).interaction)) {}

void ViewerState::observe(const LiveSession& session, const Planner& planner) {
  update(planner, live_status_json(session, planner),
         operator_json(session.operator_state(), session.interaction(), problem_.space,
                       session.guidance()));
}

void ViewerState::restarted() {
  const std::lock_guard lock(mutex_);
  ++generation_;
  trees_.clear();
  solution_.clear();
  ++solution_seq_;
  ++version_;
}

void ViewerState::update(const Planner& planner, std::string status, std::string op) {
  const std::vector<const Tree*> trees = planner.trees();
  const auto extent = static_cast<float>(problem_.space.max_extent());
  const std::lock_guard lock(mutex_);
  trees_.resize(trees.size());
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const Tree& tree = *trees[k];
    TreeCopy& copy = trees_[k];
    for (std::size_t i = copy.parents.size(); i < tree.size(); ++i) {
      const Eigen::Vector3d& p = tree.nodes[i].t;
      copy.positions.insert(
          copy.positions.end(),
          {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
      copy.parents.push_back(tree.parent[i]);
      copy.sources.push_back(static_cast<std::uint8_t>(tree.source[i]));
      const auto label = planner.node_label(k, static_cast<NodeId>(i));
      copy.labels.push_back(label ? static_cast<float>(*label) / extent : -1.0f);
    }
  }
  if (status != status_) {
    status_ = std::move(status);
    ++status_seq_;
  }
  if (op != op_) {
    op_ = std::move(op);
    ++op_seq_;
  }
  if (planner.status() == PlannerStatus::solved && solution_.empty()) {
    solution_ = planner.solution();
    ++solution_seq_;
  }
  ++version_;
}

std::uint64_t ViewerState::version() const {
  const std::lock_guard lock(mutex_);
  return version_;
}

std::size_t ViewerState::node_count() const {
  const std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const TreeCopy& t : trees_)
    n += t.parents.size();
  return n;
}

std::optional<std::string> ViewerState::path_text() const {
  const std::lock_guard lock(mutex_);
  if (solution_.empty())
    return std::nullopt;
  return format_path(solution_, problem_.space);
}

std::pair<std::uint64_t, std::vector<Config>> ViewerState::solution() const {
  const std::lock_guard lock(mutex_);
  return {solution_seq_, solution_};
}

std::vector<Frame> ViewerState::pending(Cursor& cursor, std::size_t max_nodes) const {
  std::vector<Frame> frames;
  const std::lock_guard lock(mutex_);
  if (!cursor.greeted || cursor.generation != generation_) {
    if (cursor.greeted)
      frames.push_back({false, json{{"type", "reset"}, {"generation", generation_}}.dump()});
    else
      frames.push_back({false, json{{"type", "hello"},
                                    {"problem", problem_.name},
                                    {"mode", mode_},
                                    {"replay", replay_},
                                    {"parameters", parameters_},
                                    {"generation", generation_}}
                                   .dump()});
    cursor = Cursor{};
    cursor.greeted = true;
    cursor.generation = generation_;
  }
  cursor.sent.resize(trees_.size(), 0);
  std::size_t budget = max_nodes;
  for (std::size_t k = 0; k < trees_.size() && budget > 0; ++k) {
    const TreeCopy& t = trees_[k];
    const std::size_t first = cursor.sent[k];
    const std::size_t n = std::min(t.parents.size() - first, budget);
    if (n == 0)
      continue;
    NodeBatch batch;
    batch.tree = static_cast<std::uint8_t>(k);
    batch.generation = generation_;
    batch.first = static_cast<std::uint32_t>(first);
    batch.positions.assign(t.positions.begin() + static_cast<std::ptrdiff_t>(3 * first),
                           t.positions.begin() + static_cast<std::ptrdiff_t>(3 * (first + n)));
    const auto a = static_cast<std::ptrdiff_t>(first), b = static_cast<std::ptrdiff_t>(first + n);
    batch.parents.assign(t.parents.begin() + a, t.parents.begin() + b);
    batch.sources.assign(t.sources.begin() + a, t.sources.begin() + b);
    batch.labels.assign(t.labels.begin() + a, t.labels.begin() + b);
    frames.push_back({true, encode_nodes(batch)});
    cursor.sent[k] = static_cast<std::uint32_t>(first + n);
    budget -= n;
  }
  if (cursor.op != op_seq_ && !op_.empty()) {
    frames.push_back({false, op_});
    cursor.op = op_seq_;
  }
  if (cursor.status != status_seq_ && !status_.empty()) {
    frames.push_back({false, status_});
    cursor.status = status_seq_;
  }
  if (cursor.solution != solution_seq_) {
    json path = json::array();
    for (const Config& q : solution_)
      path.push_back(config_json(q));
    frames.push_back({false, json{{"type", "solution"}, {"path", std::move(path)}}.dump()});
    cursor.solution = solution_seq_;
  }
  return frames;
}

namespace {

/// What every status message says: the planner, its run and its statistics.
json status_fields(const Planner& planner, std::string_view status, std::string_view mode,
                   double elapsed_s) {
  const PlannerStats& s = planner.stats();
  return json{{"type", "status"},
              {"status", status},
              {"mode", mode},
              {"planner", planner.name()},
              {"seed", planner.settings().seed},
              {"elapsed_s", elapsed_s},
              {"iterations", s.iterations},
              {"nodes", s.nodes},
              {"edges", s.edges},
              {"collision_checks", s.collision_checks},
              {"nodes_by_source", s.nodes_by_source},
              // Authority sharing's alpha now (automatic alpha moves it); null without sharing.
              {"alpha", std::isfinite(s.alpha) ? json(s.alpha) : json(nullptr)}};
}

}  // namespace

std::string live_status_json(const LiveSession& session, const Planner& planner) {
  const LiveProgress p = session.progress();
  const PlannerStats& s = planner.stats();
  const OperatorSwitch::Snapshot input = session.operator_input().snapshot();
  json j = status_fields(planner, to_string(p.status), session.spec().mode, p.elapsed_s);
  j.update(json{{"paused", p.paused},
                {"steps", p.steps},
                {"resets", p.resets},
                {"iterations_per_s", p.iterations_per_s},
                {"operator_iterations", s.operator_iterations},
                {"contact_entries", s.contact_entries},
                {"operator_rate_hz", p.operator_rate_hz},
                {"input", to_string(input.input)},
                {"simulated_available", input.simulated_available},
                {"spacemouse_available", input.spacemouse_available},
                {"spacemouse_status", input.spacemouse_status},
                {"input_latency_ms", 1000.0 * p.input_latency_s},
                {"input_latency_id", p.input_latency_id},
                {"settings", interaction_json(session.interaction())}});
  return j.dump();
}

std::string replay_status_json(const Planner& planner, std::string_view mode, double elapsed_s,
                               bool done) {
  json j =
      status_fields(planner, done ? to_string(planner.status()) : "replaying", mode, elapsed_s);
  j.update(json{{"paused", false}, {"input", "replay"}, {"replay", true}});
  return j.dump();
}

std::string operator_json(const OperatorState* state, const InteractionSettings& settings,
                          const SE3Space& space, const Guidance* guidance) {
  if (state == nullptr)
    return {};
  json j{{"type", "operator"},
         {"q", config_json(state->device.q_device)},
         {"time", state->time},
         {"in_collision", state->nearest.in_collision},
         {"distance", state->nearest.distance},
         {"obstacle", state->nearest.obstacle}};
  const bool contact_mode = settings.contact && state->frame &&
                            state->frame->distance <= contact_distance(settings, space);
  j["contact"] = contact_mode;
  if (state->frame) {
    const ContactFrame& f = *state->frame;
    j["plane"] = {{"point", {f.P_o.x(), f.P_o.y(), f.P_o.z()}},
                  {"normal", {f.n.x(), f.n.y(), f.n.z()}},
                  {"object_point", {f.P_n.x(), f.P_n.y(), f.P_n.z()}}};
  }
  if (guidance != nullptr) {
    const auto& f = guidance->force;
    j["force"] = {f[0], f[1], f[2], f[3], f[4], f[5]};
  }
  return j.dump();
}

}  // namespace tandem
