#include "tandem/runs/run_spec.hpp"

// The tables name only the fields of a ParamSpec that matter for each tunable (designated
// initializers); the others keep their defaults, which GCC's -Wextra would warn about.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include "tandem/core/error.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

ParamTable<RunSpec> make_operator_table() {
  const double inf = std::numeric_limits<double>::infinity();
  ParamTable<RunSpec> t;
  t.push_back(text_param<RunSpec>(
      {.name = "operator",
       .label = "operator",
       .help = "The simulated operator: experienced or inexperienced (following the problem's "
               "[guide]), or trace:FILE (a recorded trace)",
       .group = "operator"},
      &RunSpec::operator_name));
  t.push_back(
      real_param<RunSpec>({.name = "operator_speed",
                           .label = "operator speed",
                           .min = 0.0,
                           .max = inf,
                           .min_open = true,
                           .help = "Multiplies the simulated operator's speed along the guide",
                           .group = "operator"},
                          &RunSpec::operator_speed));
  t.push_back(
      integer_param<RunSpec>({.name = "operator_period",
                              .label = "operator period",
                              .min = 1.0,
                              .max = 1000000.0,
                              .help = "Planner iterations per operator update in virtual time",
                              .group = "operator"},
                             &RunSpec::operator_period));
  return t;
}

/// A member table of a settings struct inside RunSpec, lifted to RunSpec.
template <class Settings, class Member>
void lift(ParamTable<RunSpec>& out, const ParamTable<Settings>& table, Member member) {
  for (const Param<Settings>& p : table) {
    out.push_back({p.spec, [get = p.get, member](const RunSpec& s) { return get(member(s)); },
                   [set = p.set, member](RunSpec& s, const ParamValue& v) { set(member(s), v); }});
  }
}

ParamTable<RunSpec> make_run_table() {
  ParamTable<RunSpec> t;
  lift(
      t, planner_parameters(), [](auto& s) -> auto& { return s.settings; });
  lift(
      t, interaction_parameters(), [](auto& s) -> auto& { return s.settings.interaction; });
  for (const auto& p : operator_parameters())
    t.push_back(p);
  return t;
}

std::string known_names() {
  std::string names;
  for (const auto& p : run_tunables())
    names += (names.empty() ? "" : ", ") + std::string(p.spec.name);
  return names;
}

}  // namespace

const ParamTable<RunSpec>& operator_parameters() {
  static const ParamTable<RunSpec> kTable = make_operator_table();
  return kTable;
}

const ParamTable<RunSpec>& run_tunables() {
  static const ParamTable<RunSpec> kTable = make_run_table();
  return kTable;
}

void set_tunable(RunSpec& spec, std::string_view name, const ParamValue& value,
                 const std::string& where) {
  const Param<RunSpec>* p = find_param(run_tunables(), name);
  if (p == nullptr) {
    throw InputError(
        where, "unknown parameter '" + std::string(name) + "' (known: " + known_names() + ")");
  }
  if (auto fault = param_fault(p->spec, value))
    throw InputError(where, std::string(name) + " " + *fault);
  p->set(spec, normalise_param(p->spec, value));
}

void require_used(const RunSpec& spec, std::string_view name, const std::string& where) {
  const Param<RunSpec>* p = find_param(run_tunables(), name);
  if (p == nullptr || planner_uses(spec.mode, p->spec))
    return;
  throw InputError(where, "planner '" + spec.mode + "' does not use " + std::string(name) +
                              " (used by " + planner_users(p->spec) + ")");
}

bool uses_operator(const RunSpec& spec) {
  const PlannerEntry* e = find_planner(spec.mode);
  return e != nullptr && e->uses_operator;
}

RunSpec default_spec(std::string_view mode, const ProblemPlannerHints& hints) {
  const PlannerEntry* entry = find_planner(mode);
  if (entry == nullptr)
    throw InputError("mode", unknown_planner(mode));
  RunSpec spec;
  spec.mode = std::string(mode);
  spec.settings = default_settings(mode);
  spec.settings.seed = hints.seed.value_or(1);
  spec.operator_seed = spec.settings.seed;
  if (hints.time_limit)
    spec.time_limit = *hints.time_limit;
  // OMPL.app gives ranges per planner: RRT's for rrt, RRT-Connect's for the others.
  const auto range = hints.range.find(std::string(entry->ompl_range));
  if (range != hints.range.end())
    spec.settings.range = range->second;
  for (const auto& [name, value, where] : hints.values)
    set_tunable(spec, name, value, where);
  return spec;
}

void check_hints(const ProblemPlannerHints& hints, const std::string& source) {
  if (hints.planner && find_planner(*hints.planner) == nullptr)
    throw InputError(source, "planner.name: " + unknown_planner(*hints.planner));
  (void)default_spec("birrt", hints);
}

std::map<std::string, ParamValue> used_tunables(const RunSpec& spec) {
  std::map<std::string, ParamValue> out;
  for (const auto& p : run_tunables()) {
    if (planner_uses(spec.mode, p.spec))
      out.emplace(p.spec.name, p.get(spec));
  }
  return out;
}

}  // namespace tandem
