#pragma once
// Every core on one problem: a portfolio of independent searches (Gomes & Selman, "Algorithm
// portfolios", AI 2001). A sampling planner's run time is heavy-tailed — a few seeds take many
// times the median — so the first of k independent runs to finish is far sooner than one run,
// more than k times sooner in the tail. Member i runs the spec's planner with seed
// member_seed(seed, i), on its own thread (member 0 on the caller's), with its own clone of the
// collision checker; the members share one workspace route, found once (run_route). For
// "birrt+rrt": RRT-Connect on even members and goal-biased RRT on odd ones, which are fast where
// the other is slow (the alpha puzzle, whose difficulty is the part's orientation); but where the
// part fits the workspace route lengthwise (sampling/guided_sampler.hpp), the route leads
// RRT-Connect's samples and RRT-Connect on every member was measured faster (README). There, too,
// the searches are short and their run times light-tailed, so a second independent search buys
// little: member 0 starts with a helper thread (MotionValidator::use_helper_thread: its motions
// checked in rounds on two cores), and member 1 starts only when member 0 has done
// spec.helper_work without a solution and releases the helper (cubicles 21.7 -> 19.4 ms, Easy
// 1.7 -> 1.0 ms, bugtrap's heavy tail unchanged; README).
//
// Deterministic: the winner is the member that solves with the least work (its collision
// queries' tests of boxes and triangles, query_work(), as deterministic as its iterations and
// near proportional to their time), the lower index on a tie — not the first to finish in time,
// which depends on the machine. A member stops as soon as it can no longer win (its work passed
// the best solve's), so the result for a given seed and thread count is the same on any machine
// and under any load, unless the time limit ends the run first (as for one thread).

#include <cstdint>
#include <memory>
#include <string_view>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run.hpp"

namespace tandem {

/// The planner member `index` of a portfolio of `mode` runs: `mode` itself, but for
/// kMixedPortfolio: "birrt" on even members and "rrt" on odd ones, or "birrt" on every member
/// where the route leads (route_leads).
std::string_view member_planner(std::string_view mode, unsigned index, bool route_led = false);

/// The workspace route (sampling/guided_sampler.hpp) of a run whose RRT-Connect members follow
/// one (settings.guide > 0, a mode other than "rrt"), found once for them all; null otherwise.
std::shared_ptr<const WorkspaceRoute> run_route(const Problem& problem, const RunSpec& spec,
                                                const CollisionChecker& checker);

/// Whether spec is the mixed portfolio and its run's route (run_route) is one the part fits
/// lengthwise (fits_lengthwise, guided_sampler.hpp).
bool route_leads(const RunSpec& spec, const WorkspaceRoute* route);

/// The seed of member `index`: the run's seed for member 0 (one thread is the plain run), then
/// the run's seed generator's successive outputs.
std::uint64_t member_seed(std::uint64_t seed, unsigned index);

/// The thread count a spec asks for: settings.threads, 0 meaning one per core.
unsigned resolve_threads(const RunSpec& spec);

/// Runs spec (a planner that plans alone) as `threads` members and returns the winner's outcome:
/// its status, path, trees (tree_digest), statistics and index (member), but for collision_checks,
/// collision_time_s and nearest_time_s, which count every member's work, and time_s, the
/// portfolio's wall time.
/// Without a winner: member 0's outcome (timeout, iteration_limit, interrupted, invalid start or
/// goal), with the same totals. The checker is cloned for the members (they share its geometry
/// and distance grid); its own counters do not count their queries.
RunOutcome run_portfolio(const Problem& problem, const RunSpec& spec, CollisionChecker& checker,
                         unsigned threads);

}  // namespace tandem
