#include "tandem/web/solution_products.hpp"

#include <chrono>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/export/motion_envelope.hpp"
#include "tandem/export/path_animation.hpp"
#include "tandem/export/player_page.hpp"
#include "tandem/export/stl_file.hpp"
#include "tandem/io/clearance_json.hpp"

namespace tandem {
namespace {

constexpr auto kPoll = std::chrono::milliseconds(100);

}  // namespace

SolutionProducts::SolutionProducts(const ViewerState& state, std::filesystem::path web_root)
    : state_(state),
      web_root_(std::move(web_root)),
      worker_([this](std::stop_token stop) { run(stop); }) {}

SolutionProducts::~SolutionProducts() {
  worker_.request_stop();
}

std::optional<std::string> SolutionProducts::get(SolutionProduct product) const {
  const std::lock_guard lock(mutex_);
  const auto it = products_.find(product);
  if (it != products_.end())
    return it->second;
  if (product == SolutionProduct::envelope_stl)
    envelope_wanted_ = true;
  return std::nullopt;
}

std::string SolutionProducts::missing(SolutionProduct product) const {
  const std::lock_guard lock(mutex_);
  if (!has_solution_)
    return "no solution yet";
  if (!error_.empty())
    return error_;
  if (product == SolutionProduct::animation_html && no_player_)
    return "the animation player is not built (run scripts/build-web)";
  return "computing";
}

void SolutionProducts::put(std::uint64_t seq, SolutionProduct product, std::string bytes) {
  const std::lock_guard lock(mutex_);
  if (seq == seq_)
    products_[product] = std::move(bytes);
}

bool SolutionProducts::start(std::uint64_t seq, bool has_solution) {
  const std::lock_guard lock(mutex_);
  seq_ = seq;
  has_solution_ = has_solution;
  products_.clear();
  error_.clear();
  envelope_wanted_ = false;
  return has_solution;
}

bool SolutionProducts::envelope_due() const {
  const std::lock_guard lock(mutex_);
  return has_solution_ && envelope_wanted_ && error_.empty() &&
         !products_.contains(SolutionProduct::envelope_stl);
}

void SolutionProducts::run(std::stop_token stop) {
  player_ = read_player_script(web_root_);
  {
    const std::lock_guard lock(mutex_);
    no_player_ = !player_;
  }
  std::uint64_t done = 0;
  while (!stop.stop_requested()) {
    const auto [seq, path] = state_.solution();
    try {
      if (seq != done && start(done = seq, !path.empty())) {
        clearance(seq, path);
        animate(seq, path, nullptr);
      }
      if (envelope_due())
        envelope(seq, path, stop);
    } catch (const std::exception& e) {
      const std::lock_guard lock(mutex_);
      error_ = e.what();
    }
    std::this_thread::sleep_for(kPoll);
  }
}

void SolutionProducts::clearance(std::uint64_t seq, const Path& path) {
  const Problem& problem = state_.problem();
  CollisionChecker checker(problem.scene);
  const PathClearance c =
      path_clearance(path, checker, problem.space, 0.01, 1e-9 * problem.space.max_extent());
  put(seq, SolutionProduct::clearance_json, clearance_json(c, checker).dump());
}

void SolutionProducts::animate(std::uint64_t seq, const Path& path, const TriangleMesh* envelope) {
  const Problem& problem = state_.problem();
  AnimationOptions options;
  options.title = "tandem: " + problem.name;
  options.envelope = envelope;
  const std::string glb = path_animation_glb(problem.scene, path, problem.space, options);
  put(seq, SolutionProduct::animation_glb, glb);
  if (player_)
    put(seq, SolutionProduct::animation_html, player_page(glb, *player_, options.title));
}

void SolutionProducts::envelope(std::uint64_t seq, const Path& path, const std::stop_token& stop) {
  const Problem& problem = state_.problem();
  const Body& object = problem.scene.object;
  const MotionEnvelope e =
      motion_envelope(object, path, problem.space, default_envelope_voxel(object), stop);
  if (stop.stop_requested())
    return;
  animate(seq, path, &e.mesh);
  std::ostringstream stl;
  write_stl(e.mesh, stl, "tandem motion envelope of " + problem.name);
  put(seq, SolutionProduct::envelope_stl, stl.str());
}

}  // namespace tandem
