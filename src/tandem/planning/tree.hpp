#pragma once
// A search tree: flat arrays of configurations and parent indices, with a nearest-neighbour index.
//
// Not movable: the index refers to `nodes` in place.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/core/digest.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/nn/nearest_neighbors.hpp"
#include "tandem/sampling/target_sampler.hpp"

namespace tandem {

struct Tree {
  static constexpr NodeId kNoParent = UINT32_MAX;

  Tree(const SE3Space& space, std::string_view nn_kind, const Config& root)
      : nn(make_nearest_neighbors(nn_kind, space, nodes)) {
    add(root, kNoParent, NodeSource::root);
  }
  Tree(const Tree&) = delete;
  Tree& operator=(const Tree&) = delete;

  NodeId add(const Config& q, NodeId parent_id, NodeSource from = NodeSource::random) {
    const auto id = static_cast<NodeId>(nodes.size());
    nodes.push_back(q);
    parent.push_back(parent_id);
    source.push_back(from);
    ++by_source[static_cast<std::size_t>(from)];
    nn->add(id);
    return id;
  }
  std::size_t size() const { return nodes.size(); }

  /// The node nearest to q; its time is added to *profile_seconds when that is set.
  NodeId nearest(const Config& q) const {
    if (profile_seconds == nullptr)
      return nn->nearest(q);
    const Stopwatch watch;
    const NodeId id = nn->nearest(q);
    *profile_seconds += watch.seconds();
    return id;
  }

  /// Configurations from the root to `id`, root first.
  std::vector<Config> path_from_root(NodeId id) const {
    std::vector<Config> path;
    for (NodeId n = id; n != kNoParent; n = parent[n])
      path.push_back(nodes[n]);
    return {path.rbegin(), path.rend()};
  }

  std::vector<Config> nodes;
  std::vector<NodeId> parent;  ///< kNoParent for the root
  std::vector<NodeSource> source;
  std::array<std::size_t, kNodeSources> by_source{};  ///< node counts per source
  std::unique_ptr<NearestNeighbors> nn;
  double* profile_seconds = nullptr;  ///< where nearest() adds its time, if profiling
};

/// A digest of the trees' contents (every node's configuration bits, parent and source, in order):
/// equal digests mean the same trees. For checking that a run is reproducible.
std::uint64_t tree_digest(const std::vector<const Tree*>& trees);

}  // namespace tandem
