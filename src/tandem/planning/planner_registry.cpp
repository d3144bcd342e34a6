#include "tandem/planning/planner_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "tandem/planning/irrt.hpp"
#include "tandem/planning/rrt.hpp"
#include "tandem/planning/rrt_connect.hpp"
#include "tandem/sampling/authority_sharing.hpp"

// Registry entries name only the fields that differ from PlannerEntry's defaults.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace tandem {
namespace {

std::unique_ptr<TargetSampler> sharing(const PlannerContext& c) {
  return std::make_unique<AuthoritySharing>(c.validator.space(), *c.interaction,
                                            c.settings.interaction, c.settings.seed,
                                            c.settings.validation, &c.validator.checker());
}

std::unique_ptr<Planner> make_birrt(const PlannerContext& c) {
  return std::make_unique<RRTConnect>(c.validator, c.start, c.goal, c.settings, nullptr, c.route);
}
std::unique_ptr<Planner> make_rrt(const PlannerContext& c) {
  return std::make_unique<RRT>(c.validator, c.start, c.goal, c.settings);
}
std::unique_ptr<Planner> make_interactive(const PlannerContext& c) {
  // The papers' algorithms, with their fixed step (adaptive_step is the computer alone's).
  PlannerSettings settings = c.settings;
  settings.adaptive_step = 1.0;
  settings.passages = 0.0;
  settings.guide = 0.0;
  return std::make_unique<RRTConnect>(c.validator, c.start, c.goal, settings, sharing(c));
}
std::unique_ptr<Planner> make_irrt(const PlannerContext& c) {
  return std::make_unique<IRRT>(c.validator, c.start, c.goal, c.settings, *c.interaction);
}

void contact_off(PlannerSettings& s) {
  s.interaction.contact = false;
}
void contact_on(PlannerSettings& s) {
  s.interaction.contact = true;
}

const std::vector<PlannerEntry> kRegistry = {
    {.name = "birrt",
     .description = "the computer alone: RRT-Connect (bidirectional RRT)",
     .citation = "Kuffner & LaValle, ICRA 2000",
     .groups = {"portfolio", "passages"},
     .make = make_birrt},
    {.name = "rrt",
     .description = "the computer alone: single-tree RRT with goal bias",
     .citation = "LaValle, TR 98-11, 1998",
     .groups = {"goal_bias", "portfolio"},
     .make = make_rrt,
     .ompl_range = "rrt"},
    {.name = kMixedPortfolio,
     .description = "the computer alone, one search per thread: RRT-Connect and goal-biased RRT "
                    "on alternate threads, or RRT-Connect on every thread where the part fits the "
                    "workspace route lengthwise (one thread: RRT-Connect)",
     .citation = "Gomes & Selman, AI 2001 (algorithm portfolios)",
     .groups = {"goal_bias", "portfolio", "passages"},
     .make = make_birrt},
    {.name = "interactive",
     .description = "authority sharing: RRT-Connect growing toward a uniform sample (probability "
                    "alpha) or the operator's q_device",
     .citation = "Blin et al., IROS 2016, Algorithm 1",
     .uses_operator = true,
     .groups = {"sharing", "operator"},
     .preset = contact_off,
     .make = make_interactive},
    {.name = "interactive-contact",
     .description = "authority sharing with contact sampling: near an obstacle, N samples on its "
                    "tangent plane with the operator's orientation",
     .citation = "Blin et al., IROS 2016, Algorithm 3",
     .uses_operator = true,
     .groups = {"sharing", "operator"},
     .preset = contact_on,
     .make = make_interactive},
    {.name = "irrt",
     .description = "the Interactive RRT: pseudo-forces, Gaussian shooting around the operator, "
                    "node labels",
     .citation = "Taix & Flavigne, ECMS 2011",
     .uses_operator = true,
     .groups = {"irrt", "goal_bias", "operator"},
     .make = make_irrt},
};

}  // namespace

const std::vector<PlannerEntry>& planner_registry() {
  return kRegistry;
}

const PlannerEntry* find_planner(std::string_view name) {
  for (const PlannerEntry& e : kRegistry) {
    if (e.name == name)
      return &e;
  }
  return nullptr;
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const PlannerEntry& e : kRegistry)
    names.emplace_back(e.name);
  return names;
}

std::string unknown_planner(std::string_view name) {
  std::string known;
  for (const PlannerEntry& e : kRegistry)
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  return "unknown planner '" + std::string(name) + "' (known: " + known + ")";
}

PlannerSettings default_settings(std::string_view name) {
  PlannerSettings s;
  const PlannerEntry* e = find_planner(name);
  if (e != nullptr && e->preset != nullptr)
    e->preset(s);
  return s;
}

std::unique_ptr<Planner> make_planner(std::string_view name, MotionValidator& validator,
                                      const Config& start, const Config& goal,
                                      const PlannerSettings& settings,
                                      const Interaction* interaction) {
  return make_planner(name, {validator, start, goal, settings, interaction});
}

std::unique_ptr<Planner> make_planner(std::string_view name, const PlannerContext& c) {
  const PlannerEntry* e = find_planner(name);
  if (e == nullptr)
    throw std::invalid_argument(unknown_planner(name));
  const bool has_operator = c.interaction != nullptr && c.interaction->feed != nullptr;
  if (e->uses_operator && !has_operator)
    throw std::invalid_argument("planner '" + std::string(name) + "' needs an operator");
  if (!e->uses_operator && c.interaction != nullptr) {
    throw std::invalid_argument("planner '" + std::string(name) +
                                "' cannot use an operator (it plans alone)");
  }
  return e->make(c);
}

bool planner_uses(std::string_view name, const ParamSpec& spec) {
  if (spec.group.empty())
    return true;
  const PlannerEntry* e = find_planner(name);
  return e != nullptr &&
         std::find(e->groups.begin(), e->groups.end(), spec.group) != e->groups.end();
}

std::string planner_users(const ParamSpec& spec) {
  std::string users;
  for (const PlannerEntry& e : kRegistry) {
    if (planner_uses(e.name, spec))
      users += (users.empty() ? "" : ", ") + std::string(e.name);
  }
  return users;
}

}  // namespace tandem
