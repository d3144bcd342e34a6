#include "tandem/planning/planner_settings.hpp"

#include "tandem/core/enum_names.hpp"

// The tables name only the fields of a ParamSpec that matter for each tunable (designated
// initializers); the others keep their defaults, which GCC's -Wextra would warn about.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace tandem {
namespace {

using S = PlannerSettings;

/// How motions are checked: validation, tolerance, clearance, distance_grid.
void add_validation_params(ParamTable<S>& t) {
  const double inf = std::numeric_limits<double>::infinity();
  t.push_back(choice_param<S>(
      {.name = "validation",
       .label = "motion validation",
       .choices = {"exact", "discrete"},
       .help = "How motions are checked: exact (the whole continuous motion, certified by "
               "clearance bounds) or discrete (every 1% of the bounds' diagonal and of pi, "
               "OMPL's DiscreteMotionValidator; may step over thin obstacles)"},
      &S::validation, [](MotionValidation v) { return to_string(v); }, parse_motion_validation));
  t.push_back(real_param<S>(
      {.name = "tolerance",
       .label = "contact tolerance",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "Exact validation: closer than this to an obstacle counts as contact (0: 1e-6 x "
               "the bounds' diagonal)"},
      &S::tolerance));
  t.push_back(real_param<S>(
      {.name = "clearance",
       .label = "clearance",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "Exact validation: keep at least this far from every obstacle at every "
               "configuration of every motion, as a path finder's clash accuracy (0: only the "
               "contact tolerance)"},
      &S::clearance));
  t.push_back(choice_param<S>(
      {.name = "distance_grid",
       .label = "distance grid",
       .choices = {"on", "off"},
       .help = "Answer collision and clearance queries from a distance grid of the obstacles "
               "where it can certify them (free, or at least this far), FCL the rest; off: FCL "
               "alone. Same answers either way"},
      &S::distance_grid, [](bool on) { return std::string(on ? "on" : "off"); },
      [](std::string_view v) {
        return v == "on"    ? std::optional<bool>(true)
               : v == "off" ? std::optional<bool>(false)
                            : std::nullopt;
      }));
}

ParamTable<S> make_table() {
  const double inf = std::numeric_limits<double>::infinity();
  ParamTable<S> t;
  t.push_back(real_param<S>(
      {.name = "range",
       .label = "range",
       .unit = "m",
       .min = 0.0,
       .max = inf,
       .help = "Longest motion added per extension (0: the problem's, else 0.2 x the space's "
               "extent)"},
      &S::range));
  t.push_back(real_param<S>(
      {.name = "adaptive_step",
       .label = "adaptive step",
       .min = 1.0 / 1024.0,
       .max = 1.0,
       .help = "Classic extension: the smallest step, as a share of range; a blocked "
               "extension halves its node's step down to it, a new node starts at twice its "
               "parent's (at most range); a search without a path after 100 000 collision "
               "queries halves it, again at 4 times as many, down to 1/128; 1: every step is "
               "range, as OMPL's",
       .group = "portfolio"},
      &S::adaptive_step));
  t.push_back(real_param<S>(
      {.name = "passages",
       .label = "passage islands",
       .min = 0.0,
       .max = 1.0,
       .help = "RRT-Connect's share of iterations, after its first 2000, that aim at islands of "
               "valid motion made in the workspace's narrow tubes (found on the distance grid); "
               "0: none",
       .group = "passages"},
      &S::passages));
  t.push_back(real_param<S>(
      {.name = "guide",
       .label = "workspace guide",
       .min = 0.0,
       .max = 1.0,
       .help = "RRT-Connect's share of samples drawn along a route of the part from the start "
               "to the goal through the workspace's free space (found on the distance grid), "
               "from the first iteration where the route is open enough for the part lengthwise, "
               "else after 200; 0: none",
       .group = "passages"},
      &S::guide));
  t.push_back(
      real_param<S>({.name = "goal_bias",
                     .label = "goal bias",
                     .min = 0.0,
                     .max = 1.0,
                     .help = "RRT's and the I-RRT's probability of extending toward the goal",
                     .group = "goal_bias"},
                    &S::goal_bias));
  t.push_back(choice_param<S>(
      {.name = "extend",
       .label = "extension",
       .choices = {"classic", "last-valid"},
       .help = "How a tree grows toward a target it cannot reach: classic (all or nothing) or "
               "last-valid (keep the last valid configuration, the papers' Add_Tree)"},
      &S::extend, [](ExtendMode m) { return to_string(m); }, parse_extend_mode));
  t.push_back(choice_param<S>(
      {.name = "nearest_neighbors",
       .label = "nearest neighbours",
       .choices = {"kdtree", "linear"},
       .help = "The trees' nearest-neighbour index: a k-d tree, or a linear scan"},
      &S::nearest_neighbors, [](const std::string& n) { return n; },
      [](const std::string& n) { return std::optional<std::string>(n); }));
  add_validation_params(t);
  t.push_back(integer_param<S>(
      {.name = "threads",
       .label = "threads",
       .min = 0.0,
       .max = 256.0,
       .help = "Searches at once, each on a thread, seeded from the run's seed; the one solving "
               "with the least work (its queries' tests) wins (0: one per core). Where the part "
               "fits the route, the first search has two threads for its first 80 ms of work",
       .group = "portfolio"},
      &S::threads));
  return t;
}

}  // namespace

const ParamTable<PlannerSettings>& planner_parameters() {
  static const ParamTable<PlannerSettings> kTable = make_table();
  return kTable;
}

constexpr EnumNames<ExtendMode, 2> kExtendModes{{"classic", "last-valid"}};

std::string_view to_string(ExtendMode mode) {
  return kExtendModes.name(mode);
}

std::optional<ExtendMode> parse_extend_mode(std::string_view name) {
  return kExtendModes.parse(name);
}

}  // namespace tandem
