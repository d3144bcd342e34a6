#include "tandem/experiments/experiment.hpp"

#include <toml++/toml.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "tandem/core/error.hpp"
#include "tandem/io/text.hpp"

namespace tandem {
namespace {

std::string at(const std::string& source, const toml::node& n) {
  return source + ":" + std::to_string(n.source().begin.line);
}

/// A value of parameter `key` from a TOML node, checked against the parameter's kind.
ParamValue read_param(const std::string& source, const std::string& key, const toml::node& n) {
  const auto& kinds = run_parameter_kinds();
  auto it = kinds.find(key);
  if (it == kinds.end()) {
    std::string names;
    for (const auto& [k, v] : kinds)
      names += (names.empty() ? "" : ", ") + k;
    throw InputError(at(source, n), "unknown run parameter '" + key + "' (known: " + names + ")");
  }
  const std::string& kind = it->second;
  if (kind == "real") {
    auto v = n.value<double>();
    if (!v || !(n.is_floating_point() || n.is_integer()) || !std::isfinite(*v)) {
      throw InputError(at(source, n), key + " must be a number");
    }
    return *v;
  }
  if (kind == "integer") {
    auto v = n.value<std::int64_t>();
    if (!v || !n.is_integer() || *v < 0)
      throw InputError(at(source, n), key + " must be a non-negative integer");
    return *v;
  }
  auto v = n.value<std::string>();
  if (!v || !n.is_string())
    throw InputError(at(source, n), key + " must be a string");
  return *v;
}

/// Checks a configuration's values (ranges, names) by building a run spec from it.
void validate(const RunConfig& c, const std::string& where) {
  try {
    (void)c.spec(1, 1.0);
  } catch (const InputError& e) {
    throw InputError(where, std::string("configuration ") + c.label() + ": " + e.what());
  }
}

}  // namespace

std::string format_param(const ParamValue& v) {
  if (const auto* d = std::get_if<double>(&v)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", *d);
    return buf;
  }
  if (const auto* i = std::get_if<std::int64_t>(&v))
    return std::to_string(*i);
  return std::get<std::string>(v);
}

const std::map<std::string, std::string>& run_parameter_kinds() {
  static const std::map<std::string, std::string> kKinds = {{"mode", "text"},
                                                            {"operator", "text"},
                                                            {"operator_speed", "real"},
                                                            {"operator_period", "integer"},
                                                            {"alpha", "real"},
                                                            {"contact_samples", "integer"},
                                                            {"contact_distance", "real"},
                                                            {"sampling", "text"},
                                                            {"sigma", "real"},
                                                            {"force_mix", "real"},
                                                            {"neighbours", "integer"},
                                                            {"uniform_every", "integer"},
                                                            {"extend", "text"},
                                                            {"range", "real"},
                                                            {"goal_bias", "real"}};
  return kKinds;
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
  RunSpec s;
  s.settings.seed = seed;
  s.operator_seed = seed;
  s.time_limit = time_limit;
  auto real = [&](const char* k, double fallback) {
    auto it = values.find(k);
    return it == values.end() ? fallback : std::get<double>(it->second);
  };
  auto integer = [&](const char* k, std::int64_t fallback) {
    auto it = values.find(k);
    return it == values.end() ? fallback : std::get<std::int64_t>(it->second);
  };
  auto text = [&](const char* k, const std::string& fallback) {
    auto it = values.find(k);
    return it == values.end() ? fallback : std::get<std::string>(it->second);
  };
  const std::string mode = text("mode", "birrt");
  const auto m = parse_planner_mode(mode);
  if (!m)
    throw InputError("mode", "unknown mode '" + mode + "'");
  s.mode = *m;
  s.operator_name = text("operator", "experienced");
  s.operator_speed = real("operator_speed", 1.0);
  if (!(s.operator_speed > 0.0))
    throw InputError("operator_speed", "must be positive");
  s.operator_period = static_cast<std::uint64_t>(integer("operator_period", 10));
  if (s.operator_period == 0)
    throw InputError("operator_period", "must be at least 1");
  InteractionSettings& i = s.settings.interaction;
  i.alpha = real("alpha", is_interactive(s.mode) ? 0.5 : 1.0);
  if (i.alpha < 0.0 || i.alpha > 1.0)
    throw InputError("alpha", "must be in [0, 1]");
  i.contact_samples = static_cast<int>(integer("contact_samples", 10));
  if (i.contact_samples < 1)
    throw InputError("contact_samples", "must be at least 1");
  i.contact_distance = real("contact_distance", 0.0);
  if (i.contact_distance < 0.0)
    throw InputError("contact_distance", "must not be negative");
  const std::string sampling = text("sampling", "mag");
  const auto sm = parse_irrt_sampling(sampling);
  if (!sm)
    throw InputError("sampling", "unknown I-RRT sampling mode '" + sampling + "'");
  i.sampling = *sm;
  i.sigma = real("sigma", 0.0);
  if (i.sigma < 0.0)
    throw InputError("sigma", "must not be negative");
  i.force_mix = real("force_mix", 0.5);
  if (i.force_mix < 0.0 || i.force_mix > 1.0)
    throw InputError("force_mix", "must be in [0, 1]");
  i.neighbours = static_cast<int>(integer("neighbours", 10));
  if (i.neighbours < 1)
    throw InputError("neighbours", "must be at least 1");
  i.uniform_every = static_cast<int>(integer("uniform_every", 10));
  if (i.uniform_every < 1)
    throw InputError("uniform_every", "must be at least 1");
  const auto e = parse_extend_mode(text("extend", hints.extend.value_or("classic")));
  if (!e)
    throw InputError("extend", "must be classic or last-valid");
  s.settings.extend = *e;
  const auto hinted_range = hints.range.find(s.mode == PlannerMode::rrt ? "rrt" : "birrt");
  s.settings.range = real("range", hinted_range != hints.range.end() ? hinted_range->second : 0.0);
  if (s.settings.range < 0.0)
    throw InputError("range", "must not be negative");
  s.settings.goal_bias = real("goal_bias", hints.goal_bias.value_or(0.05));
  if (s.settings.goal_bias < 0.0 || s.settings.goal_bias > 1.0)
    throw InputError("goal_bias", "must be in [0, 1]");
  return s;
}

Experiment parse_experiment(const std::string& text, const std::string& source,
                            const std::filesystem::path& base_dir) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line),
                     "invalid TOML: " + std::string(e.description()));
  }
  static const std::set<std::string> kTop = {"name",  "description", "problem",
                                             "seeds", "seed_start",  "time_limit",
                                             "base",  "sweep",       "report"};
  for (auto&& [key, node] : root) {
    if (kTop.count(std::string(key.str())) == 0) {
      throw InputError(at(source, node),
                       "unknown key '" + std::string(key.str()) + "' in the experiment");
    }
  }
  Experiment x;
  x.base_dir = base_dir;
  auto require_string = [&](const char* key) {
    const toml::node* n = root.get(key);
    if (!n)
      throw InputError(source, "the experiment needs '" + std::string(key) + "'");
    auto v = n->value<std::string>();
    if (!v || !n->is_string() || v->empty())
      throw InputError(at(source, *n), std::string(key) + " must be a non-empty string");
    return *v;
  };
  x.name = require_string("name");
  for (char c : x.name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) {
      throw InputError(at(source, *root.get("name")),
                       "name may hold letters, digits, '-', '_' and '.' only (it names files)");
    }
  }
  x.problem = require_string("problem");
  if (const toml::node* n = root.get("description"))
    x.description = n->value<std::string>().value_or("");
  auto positive_int = [&](const char* key, std::uint64_t& out) {
    if (const toml::node* n = root.get(key)) {
      auto v = n->value<std::int64_t>();
      if (!v || !n->is_integer() || *v < 1)
        throw InputError(at(source, *n), std::string(key) + " must be a positive integer");
      out = static_cast<std::uint64_t>(*v);
    }
  };
  positive_int("seeds", x.seeds);
  positive_int("seed_start", x.seed_start);
  if (const toml::node* n = root.get("time_limit")) {
    auto v = n->value<double>();
    if (!v || !(*v > 0.0) || !std::isfinite(*v))
      throw InputError(at(source, *n), "time_limit must be a positive number");
    x.time_limit = *v;
  }

  RunConfig base;
  std::string base_where = source;
  if (const toml::node* n = root.get("base")) {
    base_where = at(source, *n);
    const toml::table* t = n->as_table();
    if (!t)
      throw InputError(at(source, *n), "base must be a table");
    for (auto&& [key, value] : *t)
      base.values[std::string(key.str())] = read_param(source, std::string(key.str()), value);
  }

  std::vector<std::pair<RunConfig, std::string>> configs;
  const toml::node* sweeps = root.get("sweep");
  if (sweeps == nullptr) {
    configs.emplace_back(base, base_where);
  } else {
    const toml::array* list = sweeps->as_array();
    if (!list || list->empty())
      throw InputError(at(source, *sweeps), "sweep must be an array of tables ([[sweep]])");
    for (const auto& entry : *list) {
      const toml::table* t = entry.as_table();
      if (!t)
        throw InputError(at(source, entry), "sweep must be an array of tables ([[sweep]])");
      std::vector<RunConfig> product{base};
      for (auto&& [key, value] : *t) {
        const std::string k(key.str());
        std::vector<ParamValue> options;
        if (const toml::array* a = value.as_array()) {
          if (a->empty())
            throw InputError(at(source, value), k + " has no values");
          for (const auto& v : *a)
            options.push_back(read_param(source, k, v));
        } else {
          options.push_back(read_param(source, k, value));
        }
        std::vector<RunConfig> next;
        for (const auto& c : product) {
          for (const auto& o : options) {
            RunConfig d = c;
            d.values[k] = o;
            next.push_back(std::move(d));
          }
        }
        product = std::move(next);
      }
      for (auto& c : product)
        configs.emplace_back(std::move(c), at(source, entry));
    }
  }
  std::set<std::string> seen;
  for (auto& [c, where] : configs) {
    validate(c, where);
    if (seen.insert(c.label()).second)
      x.configs.push_back(std::move(c));
  }

  if (const toml::node* n = root.get("report")) {
    const toml::table* t = n->as_table();
    if (!t)
      throw InputError(at(source, *n), "report must be a table");
    for (auto&& [key, value] : *t) {
      const std::string k(key.str());
      if (k == "title" || k == "rows") {
        auto v = value.value<std::string>();
        if (!v || !value.is_string())
          throw InputError(at(source, value), "report." + k + " must be a string");
        (k == "title" ? x.report.title : x.report.rows) = *v;
      } else if (k == "panels") {
        auto v = value.value<std::string>();
        if (!v || run_parameter_kinds().count(*v) == 0) {
          throw InputError(at(source, value), "report.panels must name a run parameter");
        }
        x.report.panels = *v;
      } else if (k == "columns") {
        const toml::array* a = value.as_array();
        if (!a)
          throw InputError(at(source, value), "report.columns must be an array of parameter names");
        for (const auto& v : *a) {
          auto s = v.value<std::string>();
          if (!s || run_parameter_kinds().count(*s) == 0) {
            throw InputError(at(source, v), "report.columns must name run parameters");
          }
          x.report.columns.push_back(*s);
        }
      } else if (k == "paper") {
        const toml::table* p = value.as_table();
        if (!p)
          throw InputError(at(source, value), "report.paper must be a table of row value = text");
        for (auto&& [pk, pv] : *p)
          x.report.paper[std::string(pk.str())] = pv.value<std::string>().value_or("");
      } else {
        throw InputError(at(source, value), "unknown key '" + k + "' in report");
      }
    }
    if (!x.report.rows.empty() && run_parameter_kinds().count(x.report.rows) == 0) {
      throw InputError(at(source, *n), "report.rows must name a run parameter");
    }
  }
  if (x.report.title.empty())
    x.report.title = x.name;
  return x;
}

Experiment load_experiment(const std::filesystem::path& file) {
  return parse_experiment(read_text_file(file), file.string(),
                          std::filesystem::absolute(file).parent_path());
}

}  // namespace tandem
