#include "tandem/planning/passage_islands.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "tandem/collision/distance_grid.hpp"

namespace tandem {
namespace {

/// Passage configurations tried per new island.
constexpr int kAttempts = 8;
/// Step 3: motions of half the longest half extent, at most eight each way.
constexpr double kSlideStep = 0.5;
constexpr int kSlideSteps = 8;

}  // namespace

PassageIslands::PassageIslands(MotionValidator& validator, std::uint64_t seed)
    : validator_(validator), rng_(seed) {}

void PassageIslands::find() {
  passages_.emplace();
  const DistanceGrid* grid = validator_.checker().distance_grid();
  if (grid == nullptr || validator_.space().planar())
    return;
  // 1. The tubes narrower than the part's longest half extent.
  extent_ = validator_.checker().object_extent();
  *passages_ = find_passages(*grid, extent_.half_extents(0));
  if (passages_->empty())
    return;
  double lo = passages_->front().clearance;
  double hi = lo;
  for (const Passage& p : *passages_) {
    lo = std::min(lo, p.clearance);
    hi = std::max(hi, p.clearance);
  }
  std::vector<std::vector<std::size_t>> bands(kBands);
  const double span = std::log(hi / lo);
  for (std::size_t i = 0; i < passages_->size(); ++i) {
    const double x = span > 0.0 ? std::log((*passages_)[i].clearance / lo) / span : 0.0;
    bands[std::min(kBands - 1, static_cast<std::size_t>(x * kBands))].push_back(i);
  }
  for (auto& b : bands) {
    if (!b.empty())
      bands_.push_back(std::move(b));
  }
}

std::optional<IslandEnd> PassageIslands::next_target(int tree) {
  if (!passages_)
    find();
  if (passages_->empty())
    return std::nullopt;
  if (islands_.empty() || rng_.uniform01() < 0.5)
    make_island();
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < islands_.size(); ++i) {
    if (!islands_[i].joined[static_cast<std::size_t>(tree)])
      open.push_back(i);
  }
  if (open.empty())
    return std::nullopt;
  return IslandEnd{open[rng_.below(open.size())], rng_.uniform01() < 0.5};
}

bool PassageIslands::make_island() {
  const double h = validator_.checker().distance_grid()->spacing();
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    // 2. A passage configuration.
    const auto [index, band] = draw_passage();
    const Passage& p = (*passages_)[index];
    const Eigen::Vector3d axis =
        rng_.uniform01() < 0.5 ? p.direction : Eigen::Vector3d(-p.direction);
    Config q;
    q.t = p.point + h * Eigen::Vector3d(rng_.uniform(-0.5, 0.5), rng_.uniform(-0.5, 0.5),
                                        rng_.uniform(-0.5, 0.5));
    q.q = Eigen::AngleAxisd(rng_.uniform(-M_PI, M_PI), axis) *
          Eigen::Quaterniond::FromTwoVectors(extent_.axes.col(0), axis);
    q.q.normalize();
    if (!validator_.is_valid(q) || !open_enough(q))
      continue;
    // 3. Slide both ways.
    std::vector<Config> back = slide(q, -axis);
    const std::vector<Config> ahead = slide(q, axis);
    if (back.empty() && ahead.empty())
      continue;
    // 4. The chain, from the end behind to the end ahead.
    Island island;
    island.band = band;
    island.chain.assign(back.rbegin(), back.rend());
    island.chain.push_back(q);
    island.chain.insert(island.chain.end(), ahead.begin(), ahead.end());
    keep(std::move(island));
    return true;
  }
  return false;
}

double PassageIslands::margin() const {
  return kSweepStopSteps * validator_.space().translation_step();
}

bool PassageIslands::open_enough(const Config& q) {
  return validator_.checker().clearance_bound(q, margin()) >= margin();
}

std::pair<std::size_t, std::size_t> PassageIslands::draw_passage() {
  const std::size_t band = rng_.below(bands_.size());
  return {bands_[band][rng_.below(bands_[band].size())], band};
}

void PassageIslands::keep(Island island) {
  std::size_t in_band = 0;
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i < islands_.size(); ++i) {
    if (islands_[i].band != island.band)
      continue;
    ++in_band;
    if (!islands_[i].joined[0] && !islands_[i].joined[1])
      free.push_back(i);
  }
  if (in_band < kIslandsPerBand)
    islands_.push_back(std::move(island));
  else if (!free.empty())
    islands_[free[rng_.below(free.size())]] = std::move(island);
}

std::vector<Config> PassageIslands::slide(const Config& q, const Eigen::Vector3d& direction) {
  const double longest = extent_.half_extents(0);
  const Eigen::Vector3d step = kSlideStep * longest * direction;
  std::vector<Config> out;
  std::size_t most_open = 0;
  double best = -1.0;
  Config from = q;
  for (int k = 0; k < kSlideSteps; ++k) {
    Config to = from;
    to.t += step;
    if (!validator_.space().satisfies_bounds(to) || !validator_.check_motion(from, to))
      break;
    const double clearance = validator_.checker().clearance_bound(to, longest);
    if (clearance < margin())
      break;
    out.push_back(to);
    if (clearance >= best) {
      best = clearance;
      most_open = out.size();
    }
    from = to;
  }
  out.resize(most_open);
  return out;
}

}  // namespace tandem
