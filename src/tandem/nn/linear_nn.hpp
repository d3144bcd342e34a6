#pragma once
// Brute-force nearest neighbours: the reference the fast index is tested against.

#include "tandem/nn/nearest_neighbors.hpp"

namespace tandem {

class LinearNearestNeighbors final : public NearestNeighbors {
 public:
  using NearestNeighbors::NearestNeighbors;

  void add(NodeId id) override { ids_.push_back(id); }
  std::size_t size() const override { return ids_.size(); }
  void clear() override { ids_.clear(); }
  NodeId nearest(const Config& q) const override;
  void k_nearest(const Config& q, std::size_t k, std::vector<NodeId>& out) const override;

 private:
  std::vector<NodeId> ids_;
};

}  // namespace tandem
