#include "tandem/scene/ompl_app_problem.hpp"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/scene/mesh_loader.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem {
namespace {

struct IniValue {
  std::string text;
  int line;
};

/// section -> key -> value; the INI dialect of boost::program_options config files.
using Ini = std::map<std::string, std::map<std::string, IniValue>>;

Ini read_ini(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::istringstream in(read_text_file(file));
  Ini ini;
  std::string section;
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string s = trim(raw);
    if (s.empty() || s[0] == '#' || s[0] == ';')
      continue;
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3)
        throw InputError(name + ":" + std::to_string(line), "malformed section header '" + s + "'");
      section = trim(s.substr(1, s.size() - 2));
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos) {
      throw InputError(name + ":" + std::to_string(line),
                       "expected 'key = value', got '" + s + "'");
    }
    if (section.empty())
      throw InputError(name + ":" + std::to_string(line), "key outside of any [section]");
    const std::string key = trim(s.substr(0, eq));
    if (key.empty())
      throw InputError(name + ":" + std::to_string(line), "empty key");
    auto& slot = ini[section];
    if (slot.count(key) != 0) {
      // OMPL.app's benchmark files may name a planner several times in [planner] to compare
      // settings ('aps=', 'aps.name=APS1', ..., then 'aps=', 'aps.name=APS4', ...): each
      // repetition starts a new planner entry. tandem plans with one entry per planner: the first.
      if (section == "planner")
        continue;
      throw InputError(
          name + ":" + std::to_string(line),
          "key '" + key + "' repeated (first on line " + std::to_string(slot[key].line) + ")");
    }
    slot[key] = IniValue{trim(s.substr(eq + 1)), line};
  }
  return ini;
}

class ProblemSection {
 public:
  ProblemSection(const std::string& file, const std::map<std::string, IniValue>& values)
      : file_(file), values_(values) {}

  bool has(const std::string& key) const { return values_.count(key) != 0; }

  std::string text(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end())
      throw InputError(file_, "[problem] has no '" + key + "'");
    return it->second.text;
  }

  /// A file name: refused, naming the key and its line, when it holds a NUL byte (the file opened
  /// would be named only up to it).
  std::string file_name(const std::string& key) const {
    std::string name = text(key);
    check_file_name(name, file_ + ":" + std::to_string(values_.at(key).line) + ": '" + key + "'");
    return name;
  }

  double number(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end())
      throw InputError(file_, "[problem] has no '" + key + "'");
    auto v = parse_double(it->second.text);
    if (!v || !std::isfinite(*v)) {
      throw InputError(file_ + ":" + std::to_string(it->second.line),
                       "'" + key + "' is not a finite number: '" + it->second.text + "'");
    }
    return *v;
  }

  double number_or(const std::string& key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }

 private:
  std::string file_;
  const std::map<std::string, IniValue>& values_;
};

Eigen::Quaterniond axis_angle(const ProblemSection& p, const std::string& prefix,
                              const std::string& file) {
  const double theta = p.number(prefix + ".theta");
  Eigen::Vector3d axis(p.number_or(prefix + ".axis.x", 1.0), p.number_or(prefix + ".axis.y", 0.0),
                       p.number_or(prefix + ".axis.z", 0.0));
  const std::optional<Eigen::Vector3d> unit = unit_direction(axis);
  if (!unit && theta != 0.0)
    throw InputError(file, prefix + ".axis is the zero vector");
  return Eigen::Quaterniond(Eigen::AngleAxisd(theta, unit.value_or(Eigen::Vector3d::UnitX())));
}

std::filesystem::path mesh_path(const std::filesystem::path& cfg, const std::string& file_name) {
  std::filesystem::path p(file_name);
  return p.is_absolute() ? p : cfg.parent_path() / p;
}

/// Throws at the first key of [problem] OMPL.app does not read.
void reject_unknown_keys(const std::string& name, const std::map<std::string, IniValue>& section) {
  static const std::set<std::string> kKnown = {
      "name", "robot", "world", "start.x", "start.y", "start.z", "start.theta", "start.axis.x",
      "start.axis.y", "start.axis.z", "goal.x", "goal.y", "goal.z", "goal.theta", "goal.axis.x",
      "goal.axis.y", "goal.axis.z", "volume.min.x", "volume.min.y", "volume.min.z", "volume.max.x",
      "volume.max.y", "volume.max.z",
      // Read by OMPL.app for other planners or objectives; they do not change the problem's
      // geometry.
      "sampler", "objective", "objective.threshold", "control"};
  for (const auto& [key, value] : section) {
    if (kKnown.count(key) == 0) {
      throw InputError(name + ":" + std::to_string(value.line),
                       "unknown key '" + key + "' in [problem]");
    }
  }
}

/// OMPL.app shifts every robot vertex by the mean of the robot's vertices (z kept for planar
/// problems), in single precision: v - c computed on floats, then widened.
void centre_robot(LoadedMesh& robot, bool planar) {
  Eigen::Vector3d centre = robot.vertex_mean;
  if (planar)
    centre.z() = 0.0;
  for (auto& v : robot.mesh.vertices) {
    for (int i = 0; i < 3; ++i) {
      v[i] = static_cast<double>(static_cast<float>(v[i]) - static_cast<float>(centre[i]));
    }
  }
}

/// The volume.* keys, or else the world's bounding box; flat (z = 0) for planar problems.
Bounds read_volume(const ProblemSection& p, const LoadedMesh& world, bool planar) {
  Bounds bounds;
  const char* axes[] = {"x", "y", "z"};
  if (p.has("volume.min.x")) {
    for (int i = 0; i < (planar ? 2 : 3); ++i) {
      bounds.min[i] = p.number(std::string("volume.min.") + axes[i]);
      bounds.max[i] = p.number(std::string("volume.max.") + axes[i]);
    }
  } else {
    auto [lo, hi] = world.mesh.bounding_box();
    bounds.min = lo;
    bounds.max = hi;
  }
  if (planar)
    bounds.min.z() = bounds.max.z() = 0.0;
  return bounds;
}

/// The start or goal (`prefix`): x, y, theta for planar problems; x, y, z and an axis-angle
/// rotation otherwise.
Config read_config(const ProblemSection& p, const std::string& prefix, bool planar,
                   const std::string& file) {
  Config q;
  if (planar) {
    q.t = {p.number(prefix + ".x"), p.number(prefix + ".y"), 0.0};
    q.q = Eigen::Quaterniond(
        Eigen::AngleAxisd(p.number(prefix + ".theta"), Eigen::Vector3d::UnitZ()));
  } else {
    q.t = {p.number(prefix + ".x"), p.number(prefix + ".y"), p.number(prefix + ".z")};
    q.q = axis_angle(p, prefix, file);
  }
  return q;
}

/// The robot as the object and the world as the one obstacle, both meshes.
Scene make_scene(LoadedMesh robot, const std::filesystem::path& robot_file, LoadedMesh world,
                 const std::filesystem::path& world_file) {
  Scene scene;
  scene.object.name = "robot";
  scene.object.parts.push_back(
      {MeshShape{std::make_shared<const TriangleMesh>(std::move(robot.mesh)), robot_file.string()},
       Eigen::Isometry3d::Identity()});
  scene.object.color = {0.85, 0.45, 0.2, 1.0};
  Body env;
  env.name = "world";
  env.parts.push_back(
      {MeshShape{std::make_shared<const TriangleMesh>(std::move(world.mesh)), world_file.string()},
       Eigen::Isometry3d::Identity()});
  env.color = {0.6, 0.65, 0.7, 1.0};
  scene.obstacles.push_back(std::move(env));
  return scene;
}

/// [benchmark] time_limit and run_count.
void read_benchmark_hints(const Ini& ini, const std::string& name, ProblemPlannerHints& hints) {
  auto b = ini.find("benchmark");
  if (b == ini.end())
    return;
  for (const auto& [key, value] : b->second) {
    if (key == "time_limit") {
      auto v = parse_double(value.text);
      if (!v || !(*v > 0.0))
        throw InputError(name + ":" + std::to_string(value.line),
                         "time_limit must be a positive number");
      hints.time_limit = *v;
    } else if (key == "run_count") {
      auto v = parse_uint(value.text);
      if (!v || *v == 0)
        throw InputError(name + ":" + std::to_string(value.line),
                         "run_count must be a positive integer");
      hints.run_count = static_cast<std::uint32_t>(*v);
    }
  }
}

/// [planner] rrt.range and rrtconnect.range (tandem's rrt and birrt).
void read_planner_ranges(const Ini& ini, const std::string& name, ProblemPlannerHints& hints) {
  auto pl = ini.find("planner");
  if (pl == ini.end())
    return;
  static const std::map<std::string, std::string> kPlannerNames = {{"rrt", "rrt"},
                                                                   {"rrtconnect", "birrt"}};
  for (const auto& [key, value] : pl->second) {
    const auto dot = key.find('.');
    if (dot == std::string::npos || key.substr(dot + 1) != "range")
      continue;
    auto it = kPlannerNames.find(key.substr(0, dot));
    if (it == kPlannerNames.end())
      continue;
    auto v = parse_double(value.text);
    if (!v || !(*v > 0.0))
      throw InputError(name + ":" + std::to_string(value.line), key + " must be a positive number");
    hints.range[it->second] = *v;
  }
}

}  // namespace

Problem load_ompl_app_problem(const std::filesystem::path& cfg_file) {
  const std::string name = cfg_file.string();
  const Ini ini = read_ini(cfg_file);
  auto section = ini.find("problem");
  if (section == ini.end())
    throw InputError(name, "no [problem] section");
  reject_unknown_keys(name, section->second);
  const ProblemSection p(name, section->second);
  const bool planar = !p.has("start.z");

  const std::filesystem::path robot_file = mesh_path(cfg_file, p.file_name("robot"));
  LoadedMesh robot = load_mesh(robot_file);
  const std::filesystem::path world_file = mesh_path(cfg_file, p.file_name("world"));
  LoadedMesh world = load_mesh(world_file);
  centre_robot(robot, planar);

  Bounds bounds = read_volume(p, world, planar);
  const Config start = read_config(p, "start", planar, name);
  const Config goal = read_config(p, "goal", planar, name);
  bounds.include(start.t);
  bounds.include(goal.t);
  const int dims = planar ? 2 : 3;
  if (!(bounds.min.head(dims).array() < bounds.max.head(dims).array()).all()) {
    throw InputError(name, "the volume is empty (volume.min must be below volume.max)");
  }

  Problem problem{p.has("name") ? p.text("name") : cfg_file.stem().string(),
                  name,
                  make_scene(std::move(robot), robot_file, std::move(world), world_file),
                  SE3Space(planar ? SpaceKind::planar : SpaceKind::se3, bounds),
                  start,
                  goal,
                  {},
                  {},
                  std::nullopt};
  read_benchmark_hints(ini, name, problem.hints);
  read_planner_ranges(ini, name, problem.hints);
  return problem;
}

}  // namespace tandem
