// Every declared tunable, on every surface that reads it: the command line, scenario [planner]
// keys, experiment files, the viewer's "params" message and the journal. Each surface must accept
// exactly the declared range — the bounds themselves, not a step beyond, no NaN or infinity, no
// fraction for a whole number, no other choice — and refuse the rest naming the option or key.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

#include "run_options.hpp"
#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/io/json_codec.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/builtin_scenes.hpp"
#include "tandem/scene/problem_loader.hpp"
#include "tandem/scene/scenario_file.hpp"
#include "tandem/web/protocol.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

/// A value to try, as each surface writes it, and whether the declaration admits it.
struct Probe {
  std::string text;  ///< command line and TOML
  ParamValue value;  ///< JSON (journal, viewer)
  bool admitted;
};

std::string number_text(double v) {
  if (std::isnan(v))
    return "nan";
  if (std::isinf(v))
    return v > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// What the declaration says of a value, worked out here from the spec's fields (not through
/// param_fault, which is what is under test).
bool admits(const ParamSpec& s, double v) {
  if (!std::isfinite(v) || v > s.max || v < s.min || (s.min_open && v == s.min))
    return false;
  return s.kind != ParamKind::integer || v == std::floor(v);
}

std::vector<Probe> probes(const ParamSpec& s) {
  std::vector<Probe> out;
  if (s.kind == ParamKind::real || s.kind == ParamKind::integer) {
    const double step = s.kind == ParamKind::integer ? 1.0 : 1e-6;
    std::vector<double> values = {std::nan(""), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
    for (double b : {s.min, s.max}) {
      if (std::isfinite(b))
        values.insert(values.end(), {b, b - step, b + step});
    }
    if (s.kind == ParamKind::integer && std::isfinite(s.min))
      values.push_back(s.min + 0.5);
    if (!std::isfinite(s.max))
      values.push_back(1e12);
    for (double v : values) {
      ParamValue jv = v;
      if (s.kind == ParamKind::integer && std::isfinite(v) && v == std::floor(v))
        jv = static_cast<std::int64_t>(v);
      out.push_back({number_text(v), jv, admits(s, v)});
    }
  } else if (s.kind == ParamKind::choice) {
    for (std::string_view c : s.choices)
      out.push_back({std::string(c), std::string(c), true});
    out.push_back({"nope", std::string("nope"), false});
  } else if (s.kind == ParamKind::boolean) {
    out.push_back({"true", true, true});
    out.push_back({"false", false, true});
    out.push_back({"maybe", std::string("maybe"), false});
  }
  return out;
}

/// The first registered planner that reads the tunable.
std::string user_of(const ParamSpec& s) {
  for (const PlannerEntry& e : planner_registry()) {
    if (planner_uses(e.name, s))
      return std::string(e.name);
  }
  return "birrt";
}

std::string toml_text(const ParamSpec& s, const std::string& text) {
  return s.kind == ParamKind::choice || (s.kind == ParamKind::boolean && text == "maybe")
             ? "\"" + text + "\""
             : text;
}

/// "" when accepted, else the error's message.
std::string outcome(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return std::string(e.what()).empty() ? "error" : e.what();
  }
  return "";
}

void expect(const Probe& p, const std::string& got, const std::string& surface,
            const std::string& names) {
  if (p.admitted) {
    EXPECT_EQ(got, "") << surface << " refused " << p.text;
  } else {
    EXPECT_NE(got, "") << surface << " accepted " << p.text;
    if (!got.empty()) {
      EXPECT_THAT(got, HasSubstr(names)) << surface << " for " << p.text;
    }
  }
}

/// Tunables the operator family declares are text (the operator's name): checked by its user.
bool numeric_or_choice(const ParamSpec& s) {
  return s.kind != ParamKind::text;
}

TEST(ParameterSurfaces, TheCommandLineAcceptsExactlyTheDeclaredRange) {
  const Problem problem = load_problem("cluttered-1");
  for (const auto& param : run_tunables()) {
    const ParamSpec& s = param.spec;
    if (!numeric_or_choice(s))
      continue;
    for (const Probe& p : probes(s)) {
      cli::RunArgs args;
      args.mode = user_of(s);
      args.tunables[std::string(s.name)] = p.text;
      expect(p, outcome([&] { (void)cli::make_spec(args, problem); }), "command line",
             s.option() + ": ");
    }
  }
}

TEST(ParameterSurfaces, ExperimentFilesAcceptExactlyTheDeclaredRange) {
  for (const auto& param : run_tunables()) {
    const ParamSpec& s = param.spec;
    if (!numeric_or_choice(s))
      continue;
    for (const Probe& p : probes(s)) {
      const std::string text = "name = \"x\"\nproblem = \"cluttered-1\"\n[base]\nmode = \"" +
                               user_of(s) + "\"\n" + std::string(s.name) + " = " +
                               toml_text(s, p.text) + "\n";
      expect(p, outcome([&] { (void)parse_experiment(text, "x.toml", "."); }), "experiment",
             "x.toml:5: " + std::string(s.name) + " ");
    }
  }
}

TEST(ParameterSurfaces, ScenarioPlannerKeysAcceptExactlyTheDeclaredRange) {
  test::TempDir dir;
  // A built-in scene without its own [planner] table; the key under test makes a new one.
  std::string base = std::string(builtin_scenes().front().text);
  if (const auto at = base.find("[planner]"); at != std::string::npos) {
    const auto next = base.find("\n[", at);
    base.erase(at, next == std::string::npos ? std::string::npos : next + 1 - at);
  }
  for (const auto& param : run_tunables()) {
    const ParamSpec& s = param.spec;
    if (!numeric_or_choice(s))
      continue;
    for (const Probe& p : probes(s)) {
      const std::string text =
          base + "\n[planner]\n" + std::string(s.name) + " = " + toml_text(s, p.text) + "\n";
      const auto file = dir.write("s.toml", text);
      expect(p, outcome([&] {
               const Problem problem = load_problem(file.string());
               check_hints(problem.hints, problem.source);
             }),
             "scenario", "s.toml:");
    }
  }
}

TEST(ParameterSurfaces, TheViewerAndTheJournalAcceptExactlyTheDeclaredRange) {
  for (const auto& param : interaction_parameters()) {
    const ParamSpec& s = param.spec;
    for (const Probe& p : probes(s)) {
      nlohmann::json message = {{"type", "params"}};
      message[std::string(s.name)] = param_json(p.value);
      // JSON has no NaN or infinity: the browser cannot send them, and nlohmann writes null.
      expect(p, outcome([&] { (void)parse_client_message(message.dump(), {}); }), "viewer",
             std::string(s.name) + " ");
      nlohmann::json journal = interaction_json(InteractionSettings{});
      journal[std::string(s.name)] = param_json(p.value);
      expect(p, outcome([&] { (void)interaction_from_json(journal); }), "journal",
             std::string(s.name) + " ");
    }
  }
}

TEST(ParameterSurfaces, TheViewerIsToldEveryLiveTunableOfItsPlanner) {
  for (const PlannerEntry& e : planner_registry()) {
    const nlohmann::json list = announced_parameters(e.name, default_settings(e.name).interaction);
    std::vector<std::string> expected;
    for (const auto& p : interaction_parameters()) {
      if (p.spec.live && !p.spec.group.empty() && planner_uses(e.name, p.spec))
        expected.emplace_back(p.spec.name);
    }
    ASSERT_EQ(list.size(), expected.size()) << e.name;
    for (std::size_t i = 0; i < list.size(); ++i) {
      EXPECT_EQ(list[i]["name"], expected[i]);
      const ParamSpec& s = find_param(interaction_parameters(), expected[i])->spec;
      if (s.kind == ParamKind::real || s.kind == ParamKind::integer) {
        EXPECT_EQ(list[i]["min"].get<double>(), s.min);
        if (std::isfinite(s.max))
          EXPECT_EQ(list[i]["max"].get<double>(), s.max);
        else
          EXPECT_TRUE(list[i]["max"].is_null());
      }
    }
  }
  // Authority sharing announces alpha, automatic alpha, contact, N, d, the clearance, the
  // surfaces and the turn; the I-RRT its own; the computer alone nothing.
  EXPECT_EQ(announced_parameters("interactive-contact", {}).size(), 8u);
  EXPECT_EQ(announced_parameters("irrt", {}).size(), 5u);
  EXPECT_TRUE(announced_parameters("birrt", {}).empty());
}

TEST(ParameterSurfaces, TheJsonOutputAndTheJournalRoundTripEveryTunable) {
  InteractionSettings s;
  s.alpha = 0.123456789012345;
  s.contact = true;
  s.contact_samples = 77;
  s.sampling = IrrtSampling::path_cs;
  s.sigma = 0.3;
  s.uniform_every = 9;
  const InteractionSettings back = interaction_from_json(interaction_json(s));
  for (const auto& p : interaction_parameters())
    EXPECT_EQ(p.get(back), p.get(s)) << p.spec.name;
}

}  // namespace
}  // namespace tandem
