#pragma once
// The outcome of one EXTEND (Kuffner & LaValle 2000), with the I-RRT's classes (Taix & Flavigne
// 2011).

#include <cstdint>

namespace tandem {

enum class ExtendStatus : std::uint8_t {
  trapped,   ///< nothing added (the I-RRT's "Collision")
  advanced,  ///< a node was added one full range toward the target
  reached,   ///< the tree has a node equal to the target: added now, or there already (the
             ///< I-RRT's "Reached")
  stopped,   ///< last_valid mode: a node was added short of the target, at an obstacle ("Obstacle")
};

}  // namespace tandem
