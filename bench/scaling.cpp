// How tandem's costs grow with the size of what it is given. A benchmark, not a test: it prints
// markdown tables and writes one JSON line per measurement (--jsonl) for bench/plot_scaling.py.
//
// - parts: the box field (scene/box_field.hpp: N boxes at a constant free volume per part, a
//   0.6 m bar), N from 10 to 10 000: the checker's build time and memory; yes/no checks, distance
//   queries (nearest obstacle, with its points) and clearance bounds per second on uniform
//   configurations of the fixed 3 m region, through the linear loop and through the broad phase;
//   the operator loop's rate (nearest obstacle and contact frame, the guide from start to goal);
//   and the planning time of the fixed problem (`plan`'s default planner, threads as --threads).
// - meshes: one obstacle, a sphere of T triangles (10^3 to 10^6) written as a binary STL and
//   loaded through tandem's loader (assimp): load and build time, memory, and checks and distance
//   queries per second for the bar near its surface.
// - trees: a planner's tree (tree.hpp: nodes, parents, the k-d tree) grown to 10^6 nodes of
//   uniform configurations, each added at its nearest node: memory per node and the time of a
//   nearest-neighbour query at each size (the median of five passes over 10 000 queries).
//
//   build/bench/tandem-scaling --jsonl scaling.jsonl > scaling.md

#include <malloc.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "guide_walk.hpp"
#include "parse_arguments.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/planning/tree.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/scene/box_field.hpp"
#include "tandem/scene/mesh_loader.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Options {
  std::vector<std::size_t> parts = {10, 30, 100, 300, 1000, 3000, 5000, 10000};
  std::vector<std::size_t> triangles = {1000, 10000, 100000, 1000000};
  std::vector<std::size_t> nodes = {1000, 10000, 100000, 1000000};
  int states = 20000;
  int plan_runs = 20;  // run times are heavy-tailed: 5 seeds moved the median by 1.8x
  double time_limit = 30.0;
  unsigned threads = 2;
  std::string only;
  std::string jsonl;
};

/// Memory allocated through malloc now (MiB; glibc's count, so memory freed earlier and reused
/// does not hide what a structure takes, as a resident-size difference would).
double allocated_mib() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}

/// Peak resident memory of the process so far (MiB).
double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

/// Calls per second of `query` over the configurations (timed as a whole).
double rate(const std::vector<tandem::Config>& states,
            const std::function<double(const tandem::Config&)>& query) {
  volatile double sink = 0.0;
  const tandem::Stopwatch watch;
  for (const tandem::Config& q : states)
    sink = sink + query(q);
  return static_cast<double>(states.size()) / watch.seconds();
}

class Output {
 public:
  explicit Output(const std::string& path) {
    if (!path.empty()) {
      file_.open(path);
      if (!file_)
        throw tandem::InputError("--jsonl", "cannot write " + path);
    }
  }
  void record(const json& j) {
    if (file_.is_open())
      file_ << j.dump() << '\n' << std::flush;
  }

 private:
  std::ofstream file_;
};

std::vector<tandem::Config> uniform_states(const tandem::Problem& p, int count) {
  tandem::Rng rng(7);
  std::vector<tandem::Config> out;
  for (int i = 0; i < count; ++i)
    out.push_back(p.space.sample_uniform(rng));
  return out;
}

/// The operator loop's rate (states a second) walking the problem's guide for `seconds`.
double operator_rate(const tandem::Problem& p, const tandem::CollisionChecker& checker,
                     double seconds) {
  const bench::GuideWalk walk = bench::walk_guide(p, checker, seconds);
  return static_cast<double>(walk.states) / walk.seconds;
}

struct PlanTimes {
  int solved = 0;
  double median_s = 0.0;
  double checks_per_s = 0.0;  ///< the planner's configuration checks per second, median of the runs
};

/// `plan`'s default planner on the problem, seeds 1..runs; unsolved runs count at the limit.
PlanTimes plan_times(const tandem::Problem& p, const tandem::CollisionChecker& checker,
                     const Options& o) {
  std::vector<double> times, rates;
  PlanTimes out;
  for (int seed = 1; seed <= o.plan_runs; ++seed) {
    tandem::RunSpec spec = tandem::default_spec(tandem::kMixedPortfolio, p.hints);
    spec.settings.seed = static_cast<std::uint64_t>(seed);
    spec.settings.threads = o.threads;
    spec.time_limit = o.time_limit;
    tandem::CollisionChecker mine = checker.clone();
    const tandem::Stopwatch watch;
    const tandem::RunOutcome r = tandem::execute_run(p, spec, mine);
    const bool solved = r.status == tandem::PlannerStatus::solved;
    out.solved += solved ? 1 : 0;
    const double seconds = watch.seconds();
    times.push_back(solved ? seconds : o.time_limit);
    rates.push_back(static_cast<double>(r.stats.collision_checks) / seconds);
  }
  std::sort(times.begin(), times.end());
  std::sort(rates.begin(), rates.end());
  out.median_s = times.empty() ? 0.0 : times[times.size() / 2];
  out.checks_per_s = rates.empty() ? 0.0 : rates[rates.size() / 2];
  return out;
}

void measure_parts(const Options& o, Output& out) {
  std::printf(
      "\n### Parts (box field, uniform states in the 3 m region)\n\n"
      "| parts | build (s) | memory (MiB) | checks/s linear | checks/s broad phase "
      "| distances/s linear | distances/s broad phase | clearances/s linear "
      "| clearances/s broad phase | checks/s with the distance grid "
      "| operator loop (Hz) | plan solved | plan median (s) | plan checks/s |\n"
      "|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const std::size_t n : o.parts) {
    tandem::Problem p = tandem::box_field_problem({.parts = n, .seed = 1});
    p.guide = {p.start, p.goal};
    const double mib0 = allocated_mib();
    const tandem::Stopwatch build;
    tandem::CollisionChecker tree(p.scene);
    const double build_s = build.seconds();
    const double mib = allocated_mib() - mib0;
    tree.use_broad_phase(tandem::BroadPhase::tree);
    tandem::CollisionChecker linear = tree.clone();
    linear.use_broad_phase(tandem::BroadPhase::linear);
    const auto states = uniform_states(p, o.states);
    const double cap = p.space.translation_step();
    const double c_lin = rate(states, [&](const auto& q) { return linear.is_collision_free(q); });
    const double c_tree = rate(states, [&](const auto& q) { return tree.is_collision_free(q); });
    const double d_lin =
        rate(states, [&](const auto& q) { return linear.nearest_obstacle(q).distance; });
    const double d_tree =
        rate(states, [&](const auto& q) { return tree.nearest_obstacle(q).distance; });
    const double k_lin =
        rate(states, [&](const auto& q) { return linear.clearance_bound(q, cap); });
    const double k_tree = rate(states, [&](const auto& q) { return tree.clearance_bound(q, cap); });
    tandem::CollisionChecker automatic = tree.clone();
    automatic.use_broad_phase(tandem::BroadPhase::automatic);
    // As the planner's motion validator checks: the distance grid first (built here, outside
    // the timing), then the broad phase.
    tandem::CollisionChecker gridded = automatic.clone();
    gridded.use_distance_grid(p.space.bounds(), 0.5 * cap);
    const double g_auto = rate(states, [&](const auto& q) { return gridded.is_collision_free(q); });
    const double op_hz = operator_rate(p, automatic, 1.0);
    const PlanTimes plan = plan_times(p, automatic, o);
    std::printf(
        "| %zu | %.3f | %.1f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %d/%d | "
        "%.3f "
        "| %.0f |\n",
        n, build_s, mib, c_lin, c_tree, d_lin, d_tree, k_lin, k_tree, g_auto, op_hz, plan.solved,
        o.plan_runs, plan.median_s, plan.checks_per_s);
    out.record({{"kind", "parts"},
                {"parts", n},
                {"build_s", build_s},
                {"memory_mib", mib},
                {"checks_linear", c_lin},
                {"checks_tree", c_tree},
                {"distances_linear", d_lin},
                {"distances_tree", d_tree},
                {"clearances_linear", k_lin},
                {"clearances_tree", k_tree},
                {"checks_grid", g_auto},
                {"operator_hz", op_hz},
                {"plan_solved", plan.solved},
                {"plan_runs", o.plan_runs},
                {"plan_median_s", plan.median_s},
                {"plan_checks_per_s", plan.checks_per_s}});
  }
}

/// A UV sphere of radius 1 about the origin with about `triangles` triangles.
tandem::TriangleMesh sphere_mesh(std::size_t triangles) {
  const auto rings =
      static_cast<int>(std::max(4.0, std::sqrt(static_cast<double>(triangles) / 2.0)));
  const int segments = rings;
  tandem::TriangleMesh m;
  for (int i = 0; i <= rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * M_PI * j / segments;
      m.vertices.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
    }
  }
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(i * segments + (j % segments));
  };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      if (i > 0)
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + 1 < rings)
        m.triangles.push_back({at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
    }
  }
  return m;
}

/// Writes the mesh as a binary STL.
void write_stl(const tandem::TriangleMesh& m, const fs::path& file) {
  std::ofstream out(file, std::ios::binary);
  const char header[80] = "tandem-scaling sphere";
  out.write(header, sizeof header);
  const auto count = static_cast<std::uint32_t>(m.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : m.triangles) {
    float v[12] = {0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d)
        v[3 + 3 * k + d] = static_cast<float>(m.vertices[t[static_cast<std::size_t>(k)]][d]);
    }
    out.write(reinterpret_cast<const char*>(v), sizeof v);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
  if (!out)
    throw tandem::InputError(file.string(), "cannot write the mesh");
}

/// Configurations of the bar with its centre within 0.1 of the unit sphere, turned at random.
std::vector<tandem::Config> near_sphere(const tandem::SE3Space& space, int count) {
  tandem::Rng rng(11);
  std::vector<tandem::Config> out;
  while (static_cast<int>(out.size()) < count) {
    tandem::Config q = space.sample_uniform(rng);
    const double r = q.t.norm();
    if (r < 1e-6)
      continue;
    q.t *= rng.uniform(1.05, 1.4) / r;
    out.push_back(q);
  }
  return out;
}

void measure_meshes(const Options& o, Output& out) {
  std::printf(
      "\n### Meshes (one obstacle: a sphere of T triangles; the bar near its surface)\n\n"
      "| triangles | STL load (s) | build (s) | memory (MiB) | checks/s | distances/s | "
      "clearances/s |\n|--:|--:|--:|--:|--:|--:|--:|\n");
  const fs::path dir = fs::temp_directory_path() / ("tandem-scaling-" + std::to_string(getpid()));
  fs::create_directories(dir);
  for (const std::size_t t : o.triangles) {
    const fs::path file = dir / ("sphere-" + std::to_string(t) + ".stl");
    write_stl(sphere_mesh(t), file);
    const double mib0 = allocated_mib();
    const tandem::Stopwatch load;
    tandem::LoadedMesh loaded = tandem::load_mesh(file);
    const double load_s = load.seconds();
    const std::size_t count = loaded.mesh.triangles.size();
    tandem::Scene scene;
    scene.object.name = "bar";
    scene.object.parts.push_back(
        {tandem::Box{Eigen::Vector3d(0.6, 0.05, 0.05)}, Eigen::Isometry3d::Identity()});
    tandem::Body sphere{.name = "sphere", .parts = {}, .color = {}};
    sphere.parts.push_back(
        {tandem::MeshShape{std::make_shared<const tandem::TriangleMesh>(std::move(loaded.mesh)),
                           file.string()},
         Eigen::Isometry3d::Identity()});
    scene.obstacles.push_back(std::move(sphere));
    const tandem::Stopwatch build;
    tandem::CollisionChecker checker(scene);
    const double build_s = build.seconds();
    const double mib = allocated_mib() - mib0;
    const tandem::SE3Space space(tandem::SpaceKind::se3,
                                 {Eigen::Vector3d::Constant(-2.0), Eigen::Vector3d::Constant(2.0)});
    const auto states = near_sphere(space, o.states);
    const double cap = space.translation_step();
    const double checks = rate(states, [&](const auto& q) { return checker.is_collision_free(q); });
    const double dists =
        rate(states, [&](const auto& q) { return checker.nearest_obstacle(q).distance; });
    const double clears =
        rate(states, [&](const auto& q) { return checker.clearance_bound(q, cap); });
    std::printf("| %zu | %.3f | %.3f | %.0f | %.0f | %.0f | %.0f |\n", count, load_s, build_s, mib,
                checks, dists, clears);
    out.record({{"kind", "mesh"},
                {"triangles", count},
                {"load_s", load_s},
                {"build_s", build_s},
                {"memory_mib", mib},
                {"checks", checks},
                {"distances", dists},
                {"clearances", clears}});
    fs::remove(file);
  }
  fs::remove_all(dir);
}

void measure_trees(const Options& o, Output& out) {
  std::printf(
      "\n### Trees (uniform configurations of the box field's region, each added at its nearest "
      "node)\n\n| nodes | grow (s) | memory per node (bytes) | nearest query (us) |\n"
      "|--:|--:|--:|--:|\n");
  const tandem::Problem p = tandem::box_field_problem({.parts = 10, .seed = 1});
  const std::size_t largest = *std::max_element(o.nodes.begin(), o.nodes.end());
  tandem::Rng rng(13);
  const double mib0 = allocated_mib();
  tandem::Tree tree(p.space, "kdtree", p.start);
  const tandem::Stopwatch grow;
  std::size_t next = 0;
  std::vector<std::size_t> sizes = o.nodes;
  std::sort(sizes.begin(), sizes.end());
  while (tree.size() < largest) {
    const tandem::Config q = p.space.sample_uniform(rng);
    tree.add(q, tree.nearest(q));
    if (next < sizes.size() && tree.size() == sizes[next]) {
      const double grow_s = grow.seconds();
      const double bytes =
          (allocated_mib() - mib0) * 1024.0 * 1024.0 / static_cast<double>(tree.size());
      std::vector<tandem::Config> queries;
      for (int i = 0; i < 10000; ++i)
        queries.push_back(p.space.sample_uniform(rng));
      // The median of five passes: one pass at a million nodes moved by ±20% between runs.
      std::vector<double> passes;
      for (int pass = 0; pass < 5; ++pass)
        passes.push_back(rate(queries, [&](const auto& c) { return tree.nearest(c); }));
      std::nth_element(passes.begin(), passes.begin() + 2, passes.end());
      const double per_s = passes[2];
      std::printf("| %zu | %.2f | %.0f | %.2f |\n", tree.size(), grow_s, bytes, 1e6 / per_s);
      out.record({{"kind", "tree"},
                  {"nodes", tree.size()},
                  {"grow_s", grow_s},
                  {"bytes_per_node", bytes},
                  {"nearest_us", 1e6 / per_s}});
      ++next;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How tandem's costs grow with parts, triangles and tree nodes"};
  Options o;
  app.add_option("--parts", o.parts, "Box-field sizes (obstacles)")->capture_default_str();
  app.add_option("--triangles", o.triangles, "Sphere mesh sizes")->capture_default_str();
  app.add_option("--nodes", o.nodes, "Tree sizes")->capture_default_str();
  app.add_option("--states", o.states, "Configurations per query kind")
      ->check(CLI::Range(100, 10000000))
      ->capture_default_str();
  app.add_option("--plan-runs", o.plan_runs, "Planning runs (seeds) per box field")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  app.add_option("--time-limit", o.time_limit, "Planning time limit (s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--threads", o.threads, "Planner threads")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  app.add_option("--only", o.only, "Measure one family: parts, meshes or trees")
      ->check(CLI::IsMember({"parts", "meshes", "trees"}));
  app.add_option("--jsonl", o.jsonl, "Write one JSON line per measurement to this file");
  if (const auto code = bench::parse_arguments(app, argc, argv, "tandem-scaling"))
    return *code;
  try {
    Output out(o.jsonl);
    if (o.only.empty() || o.only == "parts")
      measure_parts(o, out);
    if (o.only.empty() || o.only == "meshes")
      measure_meshes(o, out);
    if (o.only.empty() || o.only == "trees")
      measure_trees(o, out);
    std::printf("\npeak memory of the process: %.0f MiB\n", peak_mib());
  } catch (const tandem::InputError& e) {
    std::fprintf(stderr, "tandem-scaling: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
