#pragma once
// What the viewer derives from the solution for the browser: its clearance along the whole motion
// (per motion, the certified minimum and the nearest obstacle, as JSON), the animation (.glb) and
// its offline page (.html), and the part's motion envelope (.stl). A thread of its own computes
// the clearance and the animation when a new solution appears, and the envelope when it is first
// asked for (it takes seconds; the server's thread must not wait), after which the animation and
// the page are made again with the envelope in them. A new solution or a reset drops them all.
//
// Threading: the worker thread reads the ViewerState (thread-safe) and computes; get() from any
// thread (one mutex, held for copies only). The destructor stops and joins the worker.

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "tandem/web/viewer_state.hpp"

namespace tandem {

enum class SolutionProduct { clearance_json, animation_glb, animation_html, envelope_stl };

class SolutionProducts {
 public:
  /// `web_root`: the built front end, whose player/player.js the page inlines (no page without).
  SolutionProducts(const ViewerState& state, std::filesystem::path web_root);
  ~SolutionProducts();
  SolutionProducts(const SolutionProducts&) = delete;
  SolutionProducts& operator=(const SolutionProducts&) = delete;

  /// The product for the current solution, if it is ready (asking for the envelope starts it).
  std::optional<std::string> get(SolutionProduct product) const;
  /// Why a product is not there: "no solution yet", "computing", or an error's message.
  std::string missing(SolutionProduct product) const;

 private:
  void run(std::stop_token stop);
  /// Drops the products of the previous solution; true if there is a solution now.
  bool start(std::uint64_t seq, bool has_solution);
  bool envelope_due() const;
  void clearance(std::uint64_t seq, const Path& path);
  /// The animation (with the envelope, if given) and its page.
  void animate(std::uint64_t seq, const Path& path, const TriangleMesh* envelope);
  void envelope(std::uint64_t seq, const Path& path, const std::stop_token& stop);
  /// Stores a product of solution `seq` unless the solution has changed since.
  void put(std::uint64_t seq, SolutionProduct product, std::string bytes);

  const ViewerState& state_;
  std::filesystem::path web_root_;
  mutable std::mutex mutex_;
  std::uint64_t seq_ = 0;  ///< the solution the products are of
  bool has_solution_ = false;
  std::map<SolutionProduct, std::string> products_;
  std::string error_;
  mutable bool envelope_wanted_ = false;
  bool no_player_ = false;             ///< the player is not built: no page
  std::optional<std::string> player_;  ///< the worker's: read once, when it starts
  std::jthread worker_;
};

}  // namespace tandem
