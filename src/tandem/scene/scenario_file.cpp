#include "tandem/scene/scenario_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/io/text.hpp"
#include "tandem/scene/mesh_loader.hpp"
#include "tandem/scene/urdf_loader.hpp"

namespace tandem {
namespace {

/// A TOML table that remembers which keys were read, so that unknown (misspelt) keys are reported.
class Table {
 public:
  Table(const toml::table& table, std::string source, std::string where)
      : table_(table), source_(std::move(source)), where_(std::move(where)) {}

  const std::string& where() const { return where_; }

  std::string at(const toml::node& node) const {
    return source_ + ":" + std::to_string(node.source().begin.line);
  }
  std::string at_table() const {
    return table_.source().begin.line > 0
               ? source_ + ":" + std::to_string(table_.source().begin.line)
               : source_;
  }

  bool has(std::string_view key) const { return table_.contains(key); }

  const toml::node* get(std::string_view key) {
    used_.insert(std::string(key));
    return table_.get(key);
  }

  const toml::node& require(std::string_view key) {
    const toml::node* n = get(key);
    if (!n)
      throw InputError(at_table(), where_ + " needs '" + std::string(key) + "'");
    return *n;
  }

  [[noreturn]] void fail(const toml::node& node, std::string_view key,
                         const std::string& fault) const {
    throw InputError(at(node), where_ + "." + std::string(key) + " " + fault);
  }

  double number(const toml::node& node, std::string_view key) const {
    auto v = node.value<double>();
    if (!v || !(node.is_floating_point() || node.is_integer()))
      fail(node, key, "must be a number");
    if (!std::isfinite(*v))
      fail(node, key, "must be finite");
    return *v;
  }
  double number(std::string_view key) { return number(require(key), key); }
  std::optional<double> optional_number(std::string_view key) {
    const toml::node* n = get(key);
    if (!n)
      return std::nullopt;
    return number(*n, key);
  }
  double positive(std::string_view key) {
    const toml::node& n = require(key);
    const double v = number(n, key);
    if (!(v > 0.0))
      fail(n, key, "must be positive");
    return v;
  }

  std::string string(std::string_view key) {
    const toml::node& n = require(key);
    auto v = n.value<std::string>();
    if (!v || !n.is_string())
      fail(n, key, "must be a string");
    return *v;
  }
  std::optional<std::string> optional_string(std::string_view key) {
    if (!has(key))
      return std::nullopt;
    return string(key);
  }

  std::vector<double> numbers(const toml::node& node, std::string_view key, std::size_t min_count,
                              std::size_t max_count) const {
    const toml::array* a = node.as_array();
    if (!a)
      fail(node, key, "must be an array of numbers");
    if (a->size() < min_count || a->size() > max_count) {
      fail(node, key,
           min_count == max_count ? "must have " + std::to_string(min_count) + " numbers"
                                  : "must have " + std::to_string(min_count) + " to " +
                                        std::to_string(max_count) + " numbers");
    }
    std::vector<double> out;
    for (const auto& e : *a)
      out.push_back(number(e, key));
    return out;
  }
  std::vector<double> numbers(std::string_view key, std::size_t min_count, std::size_t max_count) {
    return numbers(require(key), key, min_count, max_count);
  }

  Table subtable(std::string_view key) {
    const toml::node& n = require(key);
    const toml::table* t = n.as_table();
    if (!t)
      fail(n, key, "must be a table");
    return Table(*t, source_, where_ + "." + std::string(key));
  }

  void reject_unknown() const {
    for (auto&& [key, node] : table_) {
      if (used_.count(std::string(key.str())) == 0) {
        throw InputError(at(node), "unknown key '" + std::string(key.str()) + "' in " + where_);
      }
    }
  }

 private:
  const toml::table& table_;
  std::string source_;
  std::string where_;
  std::set<std::string> used_;
};

Eigen::Vector3d vec3(const std::vector<double>& v) {
  return {v[0], v[1], v.size() > 2 ? v[2] : 0.0};
}

/// Orientation from one of rpy_deg, rpy (radians, fixed axes x-y-z as URDF), quaternion [x, y, z,
/// w], or, for planar spaces, yaw_deg / yaw.
Eigen::Quaterniond read_rotation(Table& t, bool planar) {
  const char* keys[] = {"rpy_deg", "rpy", "quaternion", "yaw_deg", "yaw"};
  int given = 0;
  for (const char* k : keys)
    given += t.has(k) ? 1 : 0;
  if (given > 1) {
    throw InputError(
        t.at_table(),
        t.where() + " gives its orientation more than once (use one of rpy_deg, rpy, quaternion" +
            std::string(planar ? ", yaw_deg, yaw)" : ")"));
  }
  auto rpy = [](double r, double p, double y) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(y, Eigen::Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()));
  };
  constexpr double kDeg = std::numbers::pi / 180.0;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  if (t.has("rpy_deg")) {
    auto v = t.numbers("rpy_deg", 3, 3);
    q = rpy(v[0] * kDeg, v[1] * kDeg, v[2] * kDeg);
  } else if (t.has("rpy")) {
    auto v = t.numbers("rpy", 3, 3);
    q = rpy(v[0], v[1], v[2]);
  } else if (t.has("quaternion")) {
    const toml::node& n = t.require("quaternion");
    auto v = t.numbers(n, "quaternion", 4, 4);
    Eigen::Quaterniond raw(v[3], v[0], v[1], v[2]);
    if (!(raw.norm() > 1e-9))
      t.fail(n, "quaternion", "must not be zero");
    q = raw.normalized();
  } else if (t.has("yaw_deg")) {
    q = rpy(0, 0, t.number("yaw_deg") * kDeg);
  } else if (t.has("yaw")) {
    q = rpy(0, 0, t.number("yaw"));
  }
  if (planar && (t.has("rpy_deg") || t.has("rpy") || t.has("quaternion"))) {
    const Eigen::Vector3d z = q * Eigen::Vector3d::UnitZ();
    if (std::abs(z.z() - 1.0) > 1e-9) {
      throw InputError(t.at_table(),
                       t.where() + " must rotate about z only in a planar space (use yaw_deg)");
    }
  }
  return q;
}

Eigen::Isometry3d read_pose(Table& t) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (t.has("position"))
    X.translation() = vec3(t.numbers("position", 3, 3));
  X.linear() = read_rotation(t, false).toRotationMatrix();
  return X;
}

Color read_color(Table& t) {
  Color c;
  const toml::node* n = t.get("color");
  if (!n)
    return c;
  if (auto s = n->value<std::string>(); s && n->is_string()) {
    const std::string& hex = *s;
    auto digit = [&](char ch) -> int {
      if (ch >= '0' && ch <= '9')
        return ch - '0';
      if (ch >= 'a' && ch <= 'f')
        return ch - 'a' + 10;
      if (ch >= 'A' && ch <= 'F')
        return ch - 'A' + 10;
      t.fail(*n, "color", "must be \"#rrggbb\" or [r, g, b] with components in [0, 1]");
    };
    if (hex.size() != 7 || hex[0] != '#')
      t.fail(*n, "color", "must be \"#rrggbb\" or [r, g, b] with components in [0, 1]");
    c.r = (digit(hex[1]) * 16 + digit(hex[2])) / 255.0;
    c.g = (digit(hex[3]) * 16 + digit(hex[4])) / 255.0;
    c.b = (digit(hex[5]) * 16 + digit(hex[6])) / 255.0;
    return c;
  }
  auto v = t.numbers(*n, "color", 3, 4);
  for (double x : v) {
    if (x < 0.0 || x > 1.0)
      t.fail(*n, "color", "components must be in [0, 1]");
  }
  c = {v[0], v[1], v[2], v.size() > 3 ? v[3] : 1.0};
  return c;
}

struct Context {
  std::string source;
  std::filesystem::path base;
  FileAccess access;
  bool base_is_file;
};

/// Parts from one geometry table: exactly one of box, sphere, cylinder, mesh, urdf; posed by its
/// position/orientation keys.
std::vector<Part> read_shape(Table& t, const Context& ctx, UrdfRole role) {
  const char* kinds[] = {"box", "sphere", "cylinder", "mesh", "urdf"};
  int given = 0;
  for (const char* k : kinds)
    given += t.has(k) ? 1 : 0;
  if (given != 1) {
    throw InputError(t.at_table(),
                     t.where() +
                         " needs exactly one geometry: box, sphere, cylinder, mesh or urdf" +
                         (given > 1 ? " (several given)" : ""));
  }
  const Eigen::Isometry3d X = read_pose(t);
  auto file_ref = [&](std::string_view key) {
    const std::string name = t.string(key);
    if (!ctx.base_is_file) {
      throw InputError(ctx.source, "a built-in scene cannot refer to the file '" + name + "'");
    }
    return resolve_reference(name, ctx.base, ctx.access);
  };
  // Faults in a referenced file name both places: "scene.toml:12: part.stl: no such file".
  auto referenced = [&](std::string_view key, auto&& load) {
    const toml::node& n = t.require(key);
    try {
      return load(file_ref(key));
    } catch (const InputError& e) {
      throw InputError(t.at(n), e.what());
    }
  };
  if (t.has("box")) {
    const toml::node& n = t.require("box");
    auto v = t.numbers(n, "box", 3, 3);
    for (double s : v) {
      if (!(s > 0.0))
        t.fail(n, "box", "sizes must be positive");
    }
    return {{Box{vec3(v)}, X}};
  }
  if (t.has("sphere")) {
    return {{Sphere{t.positive("sphere")}, X}};
  }
  if (t.has("cylinder")) {
    Table c = t.subtable("cylinder");
    Cylinder cyl{c.positive("radius"), c.positive("length")};
    c.reject_unknown();
    return {{cyl, X}};
  }
  if (t.has("mesh")) {
    Eigen::Vector3d scale = Eigen::Vector3d::Ones();
    if (const toml::node* s = t.get("scale")) {
      if (s->is_array()) {
        scale = vec3(t.numbers(*s, "scale", 3, 3));
      } else {
        scale = Eigen::Vector3d::Constant(t.number(*s, "scale"));
      }
      if (!(scale.array() > 0.0).all())
        t.fail(*s, "scale", "must be positive");
    }
    return referenced("mesh", [&](const std::filesystem::path& file) {
      LoadedMesh loaded = load_mesh(file);
      for (auto& v : loaded.mesh.vertices)
        v = v.cwiseProduct(scale);
      return std::vector<Part>{
          {MeshShape{std::make_shared<const TriangleMesh>(std::move(loaded.mesh)), file.string()},
           X}};
    });
  }
  Body body = referenced(
      "urdf", [&](const std::filesystem::path& file) { return load_urdf(file, role, ctx.access); });
  std::vector<Part> parts;
  for (auto& p : body.parts)
    parts.push_back({std::move(p.geometry), X * p.pose});
  return parts;
}

/// A body: either one geometry at the body's level or a `shapes` array of geometry tables.
Body read_body(Table& t, const Context& ctx, UrdfRole role, const std::string& default_name) {
  Body body;
  body.name = t.optional_string("name").value_or(default_name);
  if (body.name.empty())
    throw InputError(t.at_table(), t.where() + ".name must not be empty");
  body.color = read_color(t);
  if (t.has("shapes")) {
    const toml::node& n = t.require("shapes");
    const toml::array* shapes = n.as_array();
    if (!shapes || shapes->empty())
      t.fail(n, "shapes", "must be a non-empty array of tables");
    for (std::size_t i = 0; i < shapes->size(); ++i) {
      const toml::table* st = (*shapes)[i].as_table();
      if (!st)
        t.fail((*shapes)[i], "shapes", "must contain tables");
      Table shape(*st, ctx.source, t.where() + ".shapes[" + std::to_string(i) + "]");
      for (auto& p : read_shape(shape, ctx, role))
        body.parts.push_back(std::move(p));
      shape.reject_unknown();
    }
  } else {
    body.parts = read_shape(t, ctx, role);
  }
  t.reject_unknown();
  return body;
}

Config read_config(Table& t, const SE3Space& space) {
  Config q;
  if (space.planar()) {
    auto p = t.numbers("position", 2, 2);
    q.t = Eigen::Vector3d(p[0], p[1], space.bounds().min.z());
  } else {
    q.t = vec3(t.numbers("position", 3, 3));
  }
  q.q = read_rotation(t, space.planar());
  t.reject_unknown();
  return q;
}

}  // namespace

Problem parse_scenario(std::string_view text, const std::string& source,
                       const std::filesystem::path& base, const FileAccess& access) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line),
                     "invalid TOML: " + std::string(e.description()));
  }
  const Context ctx{source, base, access, base.has_filename() && std::filesystem::exists(base)};
  Table top(root, source, "scenario");
  const std::string name = top.optional_string("name").value_or(base.stem().string());
  top.optional_string("description");

  Table space_t = top.subtable("space");
  const std::string kind = space_t.optional_string("kind").value_or("se3");
  if (kind != "se3" && kind != "planar") {
    throw InputError(space_t.at(space_t.require("kind")),
                     "space.kind must be \"se3\" or \"planar\", got \"" + kind + "\"");
  }
  const bool planar = kind == "planar";
  Bounds bounds;
  bounds.min = vec3(space_t.numbers("min", planar ? 2 : 3, 3));
  bounds.max = vec3(space_t.numbers("max", planar ? 2 : 3, 3));
  if (planar && bounds.min.z() != bounds.max.z()) {
    throw InputError(
        space_t.at_table(),
        "space.min and space.max must have the same z in a planar space (the plane's height)");
  }
  if (!((bounds.min.head(planar ? 2 : 3).array() < bounds.max.head(planar ? 2 : 3).array())
            .all())) {
    throw InputError(space_t.at_table(), "space.min must be below space.max on every axis");
  }
  MetricWeights weights;
  weights.translation = space_t.optional_number("translation_weight").value_or(weights.translation);
  weights.rotation = space_t.optional_number("rotation_weight").value_or(weights.rotation);
  const double resolution =
      space_t.optional_number("resolution").value_or(SE3Space::kDefaultResolution);
  space_t.reject_unknown();
  std::optional<SE3Space> space;
  try {
    space.emplace(planar ? SpaceKind::planar : SpaceKind::se3, bounds, weights, resolution);
  } catch (const InputError& e) {
    throw InputError(space_t.at_table(), std::string("space: ") + e.what());
  }

  Scene scene;
  {
    Table object = top.subtable("object");
    scene.object = read_body(object, ctx, UrdfRole::object, "object");
  }
  if (const toml::node* obstacles = top.get("obstacle")) {
    const toml::array* list = obstacles->as_array();
    if (!list)
      top.fail(*obstacles, "obstacle", "must be an array of tables ([[obstacle]])");
    std::set<std::string> names;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const toml::table* ot = (*list)[i].as_table();
      if (!ot)
        top.fail((*list)[i], "obstacle", "must contain tables ([[obstacle]])");
      Table o(*ot, source, "obstacle[" + std::to_string(i) + "]");
      o.require("name");
      Body body = read_body(o, ctx, UrdfRole::obstacle, "");
      if (!names.insert(body.name).second) {
        throw InputError(o.at_table(), "obstacle name '" + body.name + "' is used twice");
      }
      scene.obstacles.push_back(std::move(body));
    }
  }

  Config start, goal;
  {
    Table s = top.subtable("start");
    start = read_config(s, *space);
    Table g = top.subtable("goal");
    goal = read_config(g, *space);
  }

  std::vector<Config> guide;
  if (top.has("guide")) {
    Table g = top.subtable("guide");
    const toml::node& n = g.require("keyframes");
    const toml::array* keys = n.as_array();
    if (!keys || keys->empty())
      g.fail(n, "keyframes", "must be a non-empty array of tables");
    if (keys->size() > kMaxGuideKeyframes) {
      g.fail(n, "keyframes",
             "has " + std::to_string(keys->size()) + " keyframes; a guide has at most " +
                 std::to_string(kMaxGuideKeyframes));
    }
    for (std::size_t i = 0; i < keys->size(); ++i) {
      const toml::table* kt = (*keys)[i].as_table();
      if (!kt)
        g.fail((*keys)[i], "keyframes", "must contain tables");
      Table k(*kt, source, "guide.keyframes[" + std::to_string(i) + "]");
      Config q = read_config(k, *space);
      if (!space->satisfies_bounds(q)) {
        throw InputError(k.at_table(), k.where() + " is outside the space's bounds");
      }
      guide.push_back(q);
    }
    g.reject_unknown();
  }

  ProblemPlannerHints hints;
  if (top.has("planner")) {
    Table p = top.subtable("planner");
    if (auto n = p.optional_string("name")) {
      if (*n != "birrt" && *n != "rrt")
        throw InputError(p.at(p.require("name")), "planner.name must be \"birrt\" or \"rrt\"");
      hints.planner = *n;
    }
    if (p.has("range")) {
      const double r = p.positive("range");
      hints.range["birrt"] = r;
      hints.range["rrt"] = r;
    }
    if (p.has("goal_bias")) {
      const toml::node& n = p.require("goal_bias");
      const double b = p.number(n, "goal_bias");
      if (b < 0.0 || b > 1.0)
        p.fail(n, "goal_bias", "must be in [0, 1]");
      hints.goal_bias = b;
    }
    if (auto e = p.optional_string("extend")) {
      if (*e != "classic" && *e != "last-valid")
        throw InputError(p.at(p.require("extend")),
                         "planner.extend must be \"classic\" or \"last-valid\"");
      hints.extend = *e;
    }
    if (p.has("time_limit"))
      hints.time_limit = p.positive("time_limit");
    if (p.has("seed")) {
      const toml::node& n = p.require("seed");
      auto v = n.value<std::int64_t>();
      if (!v || !n.is_integer() || *v < 0)
        p.fail(n, "seed", "must be a non-negative integer");
      hints.seed = static_cast<std::uint64_t>(*v);
    }
    p.reject_unknown();
  }
  top.reject_unknown();

  return Problem{name, source, std::move(scene), *space, start, goal, hints, std::move(guide)};
}

Problem load_scenario_file(const std::filesystem::path& file, const FileAccess& access) {
  return parse_scenario(read_text_file(file), file.string(), file, access);
}

}  // namespace tandem
