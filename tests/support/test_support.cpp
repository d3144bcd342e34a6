#include "support/test_support.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <sstream>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/rng.hpp"

extern char** environ;

namespace tandem::test {

Config at(double x, double y, double z, double yaw) {
  Config q;
  q.t = {x, y, z};
  q.q = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return q;
}

Body box_body(const std::string& name, const Eigen::Vector3d& size,
              const Eigen::Vector3d& position) {
  Body b;
  b.name = name;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = position;
  b.parts.push_back({Box{size}, X});
  return b;
}

Problem wall_with_gap_problem() {
  Scene scene;
  scene.object.name = "bar";
  scene.object.parts.push_back({Box{{1.0, 0.2, 0.2}}, Eigen::Isometry3d::Identity()});
  scene.obstacles.push_back(box_body("wall-south", {0.1, 3.0, 2.0}, {0.0, -1.8, 0.0}));
  scene.obstacles.push_back(box_body("wall-north", {0.1, 3.0, 2.0}, {0.0, 1.8, 0.0}));
  Bounds bounds{{-3, -3, -1}, {3, 3, 1}};
  Config start, goal;
  start.t = {-2, 0, 0};
  goal.t = {2, 0, 0};
  return Problem{"wall-with-gap",
                 "test",
                 std::move(scene),
                 SE3Space(SpaceKind::se3, bounds),
                 start,
                 goal,
                 {},
                 {},
                 std::nullopt};
}

TempDir::TempDir() {
  std::random_device rd;
  const auto base = std::filesystem::temp_directory_path();
  for (int i = 0; i < 100; ++i) {
    auto p = base / ("tandem-test-" + std::to_string(rd()));
    if (std::filesystem::create_directory(p)) {
      path_ = p;
      return;
    }
  }
  throw std::runtime_error("cannot create a temporary folder");
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::filesystem::path TempDir::write(const std::string& name, const std::string& text) const {
  const auto p = path_ / name;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::filesystem::path source_dir() {
  return TANDEM_SOURCE_DIR;
}
std::filesystem::path shared_dir() {
  return std::filesystem::path(TANDEM_SHARED_DIR).lexically_normal();
}
bool have_shared_data() {
  return std::filesystem::exists(shared_dir() / "benchmarks" / "omplapp" / "3D" / "Easy.cfg");
}

std::vector<std::string> shipped_problems() {
  std::vector<std::string> names = {"cluttered-1", "cluttered-2", "maze", "labyrinth-2d"};
  const auto root = shared_dir() / "benchmarks" / "omplapp";
  if (!std::filesystem::exists(root))
    return names;
  for (const char* dim : {"3D", "2D"}) {
    for (const auto& entry : std::filesystem::directory_iterator(root / dim)) {
      if (entry.path().extension() == ".cfg")
        names.push_back(entry.path().string());
    }
  }
  return names;
}

std::vector<Config> near_contact_configs(const Problem& problem, std::uint64_t seed,
                                         std::size_t pairs) {
  CollisionChecker checker(problem.scene);
  Rng rng(seed);
  std::vector<Config> out;
  std::vector<Config> free, colliding;
  for (std::size_t tries = 0;
       tries < 200 * pairs && std::min(free.size(), colliding.size()) < pairs; ++tries) {
    const Config q = problem.space.sample_uniform(rng);
    (checker.is_collision_free(q) ? free : colliding).push_back(q);
  }
  for (std::size_t i = 0; i < std::min(free.size(), colliding.size()); ++i) {
    double lo = 0.0, hi = 1.0;  // free at lo, colliding at hi
    for (int k = 0; k < 40; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (checker.is_collision_free(problem.space.interpolate(free[i], colliding[i], mid)))
        lo = mid;
      else
        hi = mid;
    }
    out.push_back(problem.space.interpolate(free[i], colliding[i], lo));
    out.push_back(problem.space.interpolate(free[i], colliding[i], hi));
  }
  return out;
}

RunResult run_tandem(const std::vector<std::string>& args) {
  TempDir dir;
  const std::string out_file = (dir.path() / "out").string();
  const std::string err_file = (dir.path() / "err").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  std::vector<std::string> argv_storage = {TANDEM_BINARY};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_storage)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  RunResult r;
  if (posix_spawn(&pid, TANDEM_BINARY, &actions, nullptr, argv.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error("cannot run " + std::string(TANDEM_BINARY));
  }
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream o(out_file), e(err_file);
  std::stringstream so, se;
  so << o.rdbuf();
  se << e.rdbuf();
  r.out = so.str();
  r.err = se.str();
  return r;
}

}  // namespace tandem::test
