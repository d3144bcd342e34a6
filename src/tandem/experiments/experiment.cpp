#include "tandem/experiments/experiment.hpp"

#include <cctype>
#include <set>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/core/toml_table.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

/// A value of parameter `key`, checked against its declaration (or the registry, for "mode").
ParamValue read_param(const TomlTable& t, const std::string& key, const toml::node& n) {
  const ParamValue v = toml_param(n);
  if (key == "mode") {
    const auto* name = std::get_if<std::string>(&v);
    if (name == nullptr || find_planner(*name) == nullptr) {
      throw InputError(t.at(n), "mode: " + unknown_planner(format_param(v)));
    }
    return v;
  }
  RunSpec scratch;
  set_tunable(scratch, key, v, t.at(n));
  return find_param(run_tunables(), key)->get(scratch);
}

/// The values of one [[sweep]] key: a list, or one value.
std::vector<ParamValue> read_options(const TomlTable& t, const std::string& key,
                                     const toml::node& n) {
  std::vector<ParamValue> options;
  if (const toml::array* a = n.as_array()) {
    if (a->empty())
      throw InputError(t.at(n), key + " has no values");
    for (const auto& v : *a)
      options.push_back(read_param(t, key, v));
  } else {
    options.push_back(read_param(t, key, n));
  }
  return options;
}

/// One [[sweep]]: the product of its lists, on top of the base.
std::vector<RunConfig> sweep_configs(TomlTable& sweep, const RunConfig& base) {
  std::vector<RunConfig> product{base};
  sweep.each([&](const std::string& key, const toml::node& value) {
    const std::vector<ParamValue> options = read_options(sweep, key, value);
    std::vector<RunConfig> next;
    for (const RunConfig& c : product) {
      for (const ParamValue& o : options) {
        RunConfig d = c;
        d.values[key] = o;
        next.push_back(std::move(d));
      }
    }
    product = std::move(next);
  });
  return product;
}

/// Checks a configuration as a whole (its mode) by building a run spec from it.
void validate(const RunConfig& c, const std::string& where) {
  try {
    (void)c.spec(1, 1.0);
  } catch (const InputError& e) {
    throw InputError(where, std::string("configuration ") + c.label() + ": " + e.what());
  }
}

void read_header(TomlTable& root, Experiment& x) {
  x.name = root.string("name");
  if (x.name.empty())
    root.fail(root.require("name"), "name", "must be a non-empty string");
  for (char c : x.name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) {
      throw InputError(root.at(root.require("name")),
                       "name may hold letters, digits, '-', '_' and '.' only (it names files)");
    }
  }
  x.problem = root.string("problem");
  if (x.problem.empty())
    root.fail(root.require("problem"), "problem", "must be a non-empty string");
  x.description = root.optional_string("description").value_or("");
  if (root.has("seeds"))
    x.seeds = root.positive_integer("seeds");
  if (root.has("seed_start"))
    x.seed_start = root.positive_integer("seed_start");
  if (root.has("time_limit")) {
    const toml::node& n = root.require("time_limit");
    const auto v = n.value<double>();
    if (!v || !(*v > 0.0) || !std::isfinite(*v))
      throw InputError(root.at(n), "time_limit must be a positive number");
    x.time_limit = *v;
  }
  if (const auto clock = root.optional_string("clock")) {
    if (*clock != "virtual" && *clock != "wall") {
      throw InputError(root.at(root.require("clock")),
                       "clock must be \"virtual\" (planner iterations) or \"wall\" (human time), "
                       "not \"" +
                           *clock + "\"");
    }
    x.clock = *clock;
  }
}

void read_configs(TomlTable& root, Experiment& x) {
  RunConfig base;
  std::string base_where = root.source();
  if (root.has("base")) {
    TomlTable t = root.subtable("base");
    base_where = t.at_table();
    t.each([&](const std::string& key, const toml::node& value) {
      base.values[key] = read_param(t, key, value);
    });
  }
  std::vector<std::pair<RunConfig, std::string>> configs;
  if (!root.has("sweep")) {
    configs.emplace_back(base, base_where);
  } else {
    const char* hint = " ([[sweep]])";
    const toml::array& list = root.table_array("sweep", true, hint);
    for (const auto& entry : list) {
      TomlTable sweep = root.array_item(entry, "sweep", "sweep", hint);
      for (RunConfig& c : sweep_configs(sweep, base))
        configs.emplace_back(std::move(c), root.at(entry));
    }
  }
  std::set<std::string> seen;
  for (auto& [c, where] : configs) {
    validate(c, where);
    if (seen.insert(c.label()).second)
      x.configs.push_back(std::move(c));
  }
}

std::string parameter_name(const TomlTable& t, const toml::node& n, const std::string& key) {
  const auto v = n.value_exact<std::string>();
  if (!v || !is_run_parameter(*v))
    throw InputError(t.at(n), "report." + key + " must name a run parameter");
  return *v;
}

void read_report(TomlTable& root, Experiment& x) {
  if (!root.has("report"))
    return;
  TomlTable t = root.subtable("report");
  x.report.title = t.optional_string("title").value_or("");
  if (const toml::node* n = t.get("rows"))
    x.report.rows = parameter_name(t, *n, "rows");
  if (const toml::node* n = t.get("panels"))
    x.report.panels = parameter_name(t, *n, "panels");
  if (const toml::node* n = t.get("columns")) {
    const toml::array* a = n->as_array();
    if (!a)
      throw InputError(t.at(*n), "report.columns must be an array of parameter names");
    for (const auto& v : *a)
      x.report.columns.push_back(parameter_name(t, v, "columns"));
  }
  if (const toml::node* n = t.get("paper")) {
    const toml::table* p = n->as_table();
    if (!p)
      throw InputError(t.at(*n), "report.paper must be a table of row value = text");
    for (auto&& [pk, pv] : *p)
      x.report.paper[std::string(pk.str())] = pv.value<std::string>().value_or("");
  }
  t.reject_unknown();
}

}  // namespace

bool is_run_parameter(std::string_view name) {
  return name == "mode" || find_param(run_tunables(), name) != nullptr;
}

std::string RunConfig::label() const {
  std::string s;
  // The mode first, as a planner name reads.
  if (auto it = values.find("mode"); it != values.end())
    s = format_param(it->second);
  for (const auto& [k, v] : values) {
    if (k == "mode")
      continue;
    s += (s.empty() ? "" : " ") + k + "=" + format_param(v);
  }
  return s.empty() ? "birrt" : s;
}

std::string RunConfig::value_text(const std::string& name) const {
  auto it = values.find(name);
  return it == values.end() ? std::string() : format_param(it->second);
}

RunSpec RunConfig::spec(std::uint64_t seed, double time_limit,
                        const ProblemPlannerHints& hints) const {
  const auto mode = values.find("mode");
  RunSpec s =
      default_spec(mode == values.end() ? "birrt" : std::get<std::string>(mode->second), hints);
  s.settings.seed = seed;
  s.operator_seed = seed;
  s.time_limit = time_limit;
  // Parameters the planner does not use are allowed: a sweep's rows share a base, and a row of the
  // computer alone may stand at alpha = 1 in a table over alpha.
  for (const auto& [k, v] : values) {
    if (k != "mode")
      set_tunable(s, k, v, k);
  }
  return s;
}

Experiment parse_experiment(const std::string& text, const std::string& source,
                            const std::filesystem::path& base_dir) {
  const toml::table doc = parse_toml(text, source);
  TomlTable root(doc, source, "the experiment", "");
  Experiment x;
  x.base_dir = base_dir;
  read_header(root, x);
  read_configs(root, x);
  read_report(root, x);
  root.reject_unknown();
  if (x.report.title.empty())
    x.report.title = x.name;
  return x;
}

Experiment load_experiment(const std::filesystem::path& file) {
  return parse_experiment(read_text_file(file), file.string(),
                          std::filesystem::absolute(file).parent_path());
}

}  // namespace tandem
