#include "run_options.hpp"

#include "tandem/core/error.hpp"

namespace tandem::cli {
namespace {

constexpr double kDefaultTimeLimit = 60.0;
/// The papers' authority sharing when the operator takes part (Blin et al. 2016: alpha = 0.5).
constexpr double kDefaultInteractiveAlpha = 0.5;

}  // namespace

RunSpec make_spec(const RunArgs& args, const Problem& problem) {
  RunSpec spec;
  // --mode, else --planner, else the problem's planner.
  if (args.mode && args.planner)
    throw InputError("--mode", "give --mode or --planner, not both");
  const std::string mode =
      args.mode.value_or(args.planner.value_or(problem.hints.planner.value_or("birrt")));
  spec.mode = *parse_planner_mode(mode);
  const std::string range_key = spec.mode == PlannerMode::rrt ? "rrt" : "birrt";

  PlannerSettings& s = spec.settings;
  s.seed = args.seed.value_or(problem.hints.seed.value_or(1));
  if (args.range) {
    s.range = *args.range;
  } else if (auto it = problem.hints.range.find(range_key); it != problem.hints.range.end()) {
    s.range = it->second;
  }
  s.goal_bias = args.goal_bias.value_or(problem.hints.goal_bias.value_or(s.goal_bias));
  s.extend = *parse_extend_mode(args.extend.value_or(problem.hints.extend.value_or("classic")));
  spec.time_limit = args.time_limit.value_or(problem.hints.time_limit.value_or(kDefaultTimeLimit));

  InteractionSettings& i = s.interaction;
  i.alpha = args.alpha.value_or(is_interactive(spec.mode) ? kDefaultInteractiveAlpha : 1.0);
  if (args.alpha && !is_interactive(spec.mode)) {
    throw InputError("--alpha",
                     "needs an interactive mode (--mode interactive or interactive-contact)");
  }
  i.contact_samples = args.contact_samples;
  i.contact_distance = args.contact_distance;
  i.sampling = *parse_irrt_sampling(args.sampling);
  i.sigma = args.sigma;
  i.force_mix = args.force_mix;
  i.neighbours = args.neighbours;
  i.uniform_every = args.uniform_every;

  spec.operator_name = args.operator_name;
  spec.operator_speed = args.operator_speed;
  spec.operator_seed = args.operator_seed.value_or(s.seed);
  spec.operator_period = args.operator_period;
  return spec;
}

void add_run_options(CLI::App& app, RunArgs& args) {
  add_problem_args(app, args.problem);
  app.add_option(
         "--mode", args.mode,
         "birrt (the computer alone, default), rrt, interactive (authority sharing, Blin et "
         "al. 2016 Alg. 1), interactive-contact (with contact sampling, Alg. 3) or irrt "
         "(Taix & Flavigne 2011)")
      ->check(CLI::IsMember(planner_mode_names()));
  app.add_option("--planner", args.planner, "Planner without an operator: birrt (default) or rrt")
      ->check(CLI::IsMember({"birrt", "rrt"}));
  app.add_option("--seed", args.seed,
                 "Random seed (default: the problem's, else 1); same seed, same path")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--time-limit", args.time_limit,
                 "Seconds before giving up (default: the problem's, else 60)")
      ->check(CLI::PositiveNumber);
  app.add_option("--range", args.range,
                 "Longest motion added per extension (default: the problem's, else 0.2 x the "
                 "space's extent)")
      ->check(CLI::PositiveNumber);
  app.add_option("--goal-bias", args.goal_bias,
                 "RRT's and the I-RRT's probability of extending toward the goal (default 0.05)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--extend", args.extend,
                 "How a tree grows toward a target it cannot reach: classic (all or nothing; the "
                 "default unless the problem says otherwise) or last-valid (keep the last valid "
                 "configuration, the papers' Add_Tree)")
      ->check(CLI::IsMember({"classic", "last-valid"}));

  const char* human = "Human loop";
  app.add_option(
         "--operator", args.operator_name,
         "The operator in interactive modes: experienced (default) or inexperienced, following "
         "the problem's [guide] in virtual time, or trace:FILE (a recorded trace in ticks)")
      ->group(human);
  app.add_option("--operator-speed", args.operator_speed,
                 "Multiplies the simulated operator's speed along the guide (default 1)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--operator-seed", args.operator_seed,
                 "Seed of the simulated operator's tremor and hesitation (default: --seed)")
      ->check(CLI::NonNegativeNumber)
      ->group(human);
  app.add_option("--operator-period", args.operator_period,
                 "Planner iterations per operator update in virtual time (default 10)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}))
      ->group(human);
  app.add_option("--alpha", args.alpha,
                 "Authority sharing: the probability that the computer (a uniform sample) has "
                 "authority in an iteration (default 0.5 in interactive modes)")
      ->check(CLI::Range(0.0, 1.0))
      ->group(human);
  app.add_option("--contact-samples", args.contact_samples,
                 "N: samples on the tangent plane each time contact mode is entered (default 10)")
      ->check(CLI::Range(1, 100000))
      ->group(human);
  app.add_option("--contact-distance", args.contact_distance,
                 "d: contact mode within this distance of an obstacle (default 1.5% of the bounds' "
                 "diagonal)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--sampling", args.sampling,
                 "I-RRT sampling mode: mag (around the user, default), path (around the user's "
                 "path), mag+cs, path+cs (with uniform samples)")
      ->check(CLI::IsMember({"mag", "path", "mag+cs", "path+cs"}))
      ->group(human);
  app.add_option("--sigma", args.sigma,
                 "I-RRT: standard deviation of the Gaussian shooting area (default 2% of the "
                 "bounds' diagonal)")
      ->check(CLI::PositiveNumber)
      ->group(human);
  app.add_option("--force-mix", args.force_mix,
                 "I-RRT: F_r = mix F_u + (1 - mix) F_a (the 2011 paper's alpha; default 0.5)")
      ->check(CLI::Range(0.0, 1.0))
      ->group(human);
  app.add_option("--neighbours", args.neighbours,
                 "I-RRT: p, nodes near the user for the centre of mass (default 10)")
      ->check(CLI::Range(1, 10000))
      ->group(human);
  app.add_option("--uniform-every", args.uniform_every,
                 "I-RRT +CS modes: one uniform sample every x shots (default 10)")
      ->check(CLI::Range(1, 1000000))
      ->group(human);
}

}  // namespace tandem::cli
