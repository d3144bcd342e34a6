#include "tandem/nn/linear_nn.hpp"

#include <algorithm>
#include <limits>

namespace tandem {

NodeId LinearNearestNeighbors::nearest(const Config& q) const {
  NodeId best = ids_.front();
  double best_d = std::numeric_limits<double>::infinity();
  for (NodeId id : ids_) {
    const double d = space_.distance(q, points_[id]);
    if (d < best_d) {
      best_d = d;
      best = id;
    }
  }
  return best;
}

void LinearNearestNeighbors::k_nearest(const Config& q, std::size_t k,
                                       std::vector<NodeId>& out) const {
  std::vector<std::pair<double, NodeId>> all;
  all.reserve(ids_.size());
  for (NodeId id : ids_)
    all.emplace_back(space_.distance(q, points_[id]), id);
  k = std::min(k, all.size());
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k), all.end());
  out.clear();
  for (std::size_t i = 0; i < k; ++i)
    out.push_back(all[i].second);
}

}  // namespace tandem
