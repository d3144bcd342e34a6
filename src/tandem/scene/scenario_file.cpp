#include "tandem/scene/scenario_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/core/toml_table.hpp"
#include "tandem/scene/cad_scene.hpp"
#include "tandem/scene/mesh_loader.hpp"
#include "tandem/scene/urdf_loader.hpp"
#include "tandem/space/unit_quaternion.hpp"

namespace tandem {
namespace {

Eigen::Vector3d vec3(const std::vector<double>& v) {
  return {v[0], v[1], v.size() > 2 ? v[2] : 0.0};
}

/// Orientation from one of rpy_deg, rpy (radians, fixed axes x-y-z as URDF), quaternion [x, y, z,
/// w], or, for planar spaces, yaw_deg / yaw.
Eigen::Quaterniond read_rotation(TomlTable& t, bool planar) {
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
    const auto unit = unit_quaternion(v[3], v[0], v[1], v[2]);
    if (!unit)
      t.fail(n, "quaternion", "must not be zero");
    q = *unit;
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

Eigen::Isometry3d read_pose(TomlTable& t) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (t.has("position"))
    X.translation() = vec3(t.numbers("position", 3, 3));
  X.linear() = read_rotation(t, false).toRotationMatrix();
  return X;
}

Color read_color(TomlTable& t) {
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

/// The geometry kinds of a shape table; exactly one must be given.
void check_one_geometry(const TomlTable& t) {
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
}

/// Loads the file a key names with `load`. Faults in it, and in the key, name both places:
/// "scene.toml:12: part.stl: no such file".
template <class Load>
auto load_referenced(TomlTable& t, const Context& ctx, std::string_view key, Load&& load) {
  const toml::node& n = t.require(key);
  try {
    const std::string name = t.string(key);
    if (!ctx.base_is_file)
      throw InputError(ctx.source, "a built-in scene cannot refer to the file '" + name + "'");
    return load(resolve_reference(name, ctx.base, ctx.access));
  } catch (const InputError& e) {
    throw InputError(t.at(n), e.what());
  }
}

Box read_box(TomlTable& t) {
  const toml::node& n = t.require("box");
  auto v = t.numbers(n, "box", 3, 3);
  for (double s : v) {
    if (!(s > 0.0))
      t.fail(n, "box", "sizes must be positive");
  }
  return Box{vec3(v)};
}

Cylinder read_cylinder(TomlTable& t) {
  TomlTable c = t.subtable("cylinder");
  Cylinder cyl{c.positive("radius"), c.positive("length")};
  c.reject_unknown();
  return cyl;
}

/// A mesh file's part, scaled by `scale` (one number or three).
Part read_mesh(TomlTable& t, const Context& ctx, const Eigen::Isometry3d& X) {
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
  return load_referenced(t, ctx, "mesh", [&](const std::filesystem::path& file) {
    LoadedMesh loaded = load_mesh(file);
    for (auto& v : loaded.mesh.vertices)
      v = v.cwiseProduct(scale);
    return Part{
        MeshShape{std::make_shared<const TriangleMesh>(std::move(loaded.mesh)), file.string()}, X};
  });
}

/// The parts of a URDF file's body, posed by X.
std::vector<Part> read_urdf(TomlTable& t, const Context& ctx, UrdfRole role,
                            const Eigen::Isometry3d& X) {
  Body body = load_referenced(t, ctx, "urdf", [&](const std::filesystem::path& file) {
    return load_urdf(file, role, ctx.access);
  });
  std::vector<Part> parts;
  for (auto& p : body.parts)
    parts.push_back({std::move(p.geometry), X * p.pose});
  return parts;
}

/// Parts from one geometry table: exactly one of box, sphere, cylinder, mesh, urdf; posed by its
/// position/orientation keys.
std::vector<Part> read_shape(TomlTable& t, const Context& ctx, UrdfRole role) {
  check_one_geometry(t);
  const Eigen::Isometry3d X = read_pose(t);
  if (t.has("box"))
    return {{read_box(t), X}};
  if (t.has("sphere"))
    return {{Sphere{t.positive("sphere")}, X}};
  if (t.has("cylinder"))
    return {{read_cylinder(t), X}};
  if (t.has("mesh"))
    return {read_mesh(t, ctx, X)};
  return read_urdf(t, ctx, role, X);
}

/// A body: either one geometry at the body's level or a `shapes` array of geometry tables.
Body read_body(TomlTable& t, const Context& ctx, UrdfRole role, const std::string& default_name) {
  Body body;
  body.name = t.optional_string("name").value_or(default_name);
  if (body.name.empty())
    throw InputError(t.at_table(), t.where() + ".name must not be empty");
  body.color = read_color(t);
  if (t.has("shapes")) {
    const toml::array& shapes = t.table_array("shapes", true);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      TomlTable shape =
          t.array_item(shapes[i], "shapes", t.where() + ".shapes[" + std::to_string(i) + "]");
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

Config read_config(TomlTable& t, const SE3Space& space) {
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

/// space.kind: true for "planar", false for "se3" (the default).
bool read_planar(TomlTable& space_t) {
  const std::string kind = space_t.optional_string("kind").value_or("se3");
  if (kind != "se3" && kind != "planar") {
    throw InputError(space_t.at(space_t.require("kind")),
                     "space.kind must be \"se3\" or \"planar\", got \"" + kind + "\"");
  }
  return kind == "planar";
}

Bounds read_bounds(TomlTable& space_t, bool planar) {
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
  return bounds;
}

/// The [space] table: kind, bounds, metric weights, resolution.
SE3Space read_space(TomlTable& top) {
  TomlTable space_t = top.subtable("space");
  const bool planar = read_planar(space_t);
  const Bounds bounds = read_bounds(space_t, planar);
  MetricWeights weights;
  weights.translation = space_t.optional_number("translation_weight").value_or(weights.translation);
  weights.rotation = space_t.optional_number("rotation_weight").value_or(weights.rotation);
  const double resolution =
      space_t.optional_number("resolution").value_or(SE3Space::kDefaultResolution);
  space_t.reject_unknown();
  try {
    return SE3Space(planar ? SpaceKind::planar : SpaceKind::se3, bounds, weights, resolution);
  } catch (const InputError& e) {
    throw InputError(space_t.at_table(), std::string("space: ") + e.what());
  }
}

/// The [[obstacle]] tables, each with a name of its own.
std::vector<Body> read_obstacles(TomlTable& top, const Context& ctx) {
  std::vector<Body> obstacles;
  if (!top.has("obstacle"))
    return obstacles;
  const toml::array& list = top.table_array("obstacle", false, " ([[obstacle]])");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    TomlTable o = top.array_item(list[i], "obstacle", "obstacle[" + std::to_string(i) + "]",
                                 " ([[obstacle]])");
    o.require("name");
    Body body = read_body(o, ctx, UrdfRole::obstacle, "");
    if (!names.insert(body.name).second)
      throw InputError(o.at_table(), "obstacle name '" + body.name + "' is used twice");
    obstacles.push_back(std::move(body));
  }
  return obstacles;
}

/// The [assembly] table: a STEP or IGES file whose parts are obstacles, but the one named `part`,
/// which is the object (none without an [assembly]).
std::optional<CadScene> read_assembly(TomlTable& top, const Context& ctx) {
  if (!top.has("assembly"))
    return std::nullopt;
  TomlTable a = top.subtable("assembly");
  const std::string part = a.optional_string("part").value_or("");
  CadOptions options;
  for (auto [key, value] : {std::pair{"linear_deflection", &options.linear_deflection},
                            std::pair{"angular_deflection", &options.angular_deflection}}) {
    if (a.has(key))
      *value = a.positive(key);
  }
  std::optional<double> seat;
  if (a.has("seat_tolerance")) {
    const toml::node& n = a.require("seat_tolerance");
    seat = a.number(n, "seat_tolerance");
    if (*seat < 0.0)
      a.fail(n, "seat_tolerance", "must not be negative");
  }
  CadScene scene = load_referenced(a, ctx, "file", [&](const std::filesystem::path& file) {
    const CadAssembly assembly = load_cad(file, options);
    return cad_scene(assembly, part, file.string(), a.where() + ".part",
                     seat.value_or(default_seat_tolerance(assembly)));
  });
  a.reject_unknown();
  return scene;
}

/// The object: the [object] table, or the assembly's part.
Body read_object(TomlTable& top, const Context& ctx, std::optional<CadScene>& cad) {
  if (cad && cad->object) {
    if (top.has("object"))
      throw InputError(top.at_table(), "the object is given twice: [object] and assembly.part");
    return *cad->object;
  }
  TomlTable object = top.subtable("object");
  return read_body(object, ctx, UrdfRole::object, "object");
}

/// The [[obstacle]] tables and the assembly's parts, each with a name of its own.
std::vector<Body> read_all_obstacles(TomlTable& top, const Context& ctx,
                                     std::optional<CadScene>& cad) {
  std::vector<Body> obstacles = read_obstacles(top, ctx);
  if (!cad)
    return obstacles;
  std::set<std::string> names;
  for (const Body& b : obstacles)
    names.insert(b.name);
  for (Body& b : cad->obstacles) {
    if (!names.insert(b.name).second)
      throw InputError(top.at_table(), "obstacle name '" + b.name +
                                           "' is both an [[obstacle]] and a part of the assembly");
    obstacles.push_back(std::move(b));
  }
  return obstacles;
}

/// The [guide] table's keyframes (none without a [guide]).
std::vector<Config> read_guide(TomlTable& top, const SE3Space& space) {
  std::vector<Config> guide;
  if (!top.has("guide"))
    return guide;
  TomlTable g = top.subtable("guide");
  const toml::array& keys = g.table_array("keyframes", true);
  if (keys.size() > kMaxGuideKeyframes) {
    g.fail(g.require("keyframes"), "keyframes",
           "has " + std::to_string(keys.size()) + " keyframes; a guide has at most " +
               std::to_string(kMaxGuideKeyframes));
  }
  for (std::size_t i = 0; i < keys.size(); ++i) {
    TomlTable k = g.array_item(keys[i], "keyframes", "guide.keyframes[" + std::to_string(i) + "]");
    Config q = read_config(k, space);
    if (!space.satisfies_bounds(q))
      throw InputError(k.at_table(), k.where() + " is outside the space's bounds");
    guide.push_back(q);
  }
  g.reject_unknown();
  return guide;
}

/// The [planner] table: the problem's planner (name), time limit and seed, and any declared
/// tunable by its name (range, extend, goal_bias, alpha, ...).
ProblemPlannerHints read_planner_hints(TomlTable& top) {
  ProblemPlannerHints hints;
  if (!top.has("planner"))
    return hints;
  TomlTable p = top.subtable("planner");
  hints.planner = p.optional_string("name");
  if (p.has("time_limit"))
    hints.time_limit = p.positive("time_limit");
  if (auto seed = p.optional_integer("seed", 0))
    hints.seed = static_cast<std::uint64_t>(*seed);
  for (const std::string& key : p.unread()) {
    const toml::node& n = p.require(key);
    hints.values.push_back({key, toml_param(n), p.at(n)});
  }
  return hints;
}

}  // namespace

Problem parse_scenario(std::string_view text, const std::string& source,
                       const std::filesystem::path& base, const FileAccess& access) {
  const toml::table root = parse_toml(text, source);
  const Context ctx{source, base, access, base.has_filename() && std::filesystem::exists(base)};
  TomlTable top(root, source, "scenario");
  const std::string name = top.optional_string("name").value_or(base.stem().string());
  top.optional_string("description");
  const SE3Space space = read_space(top);

  std::optional<CadScene> cad = read_assembly(top, ctx);
  Scene scene;
  scene.object = read_object(top, ctx, cad);
  scene.obstacles = read_all_obstacles(top, ctx, cad);
  Config start;
  if (cad && cad->seat && !top.has("start")) {
    start = *cad->seat;  // the part where it sits in the assembly
  } else {
    TomlTable start_t = top.subtable("start");
    start = read_config(start_t, space);
  }
  TomlTable goal_t = top.subtable("goal");
  const Config goal = read_config(goal_t, space);
  std::vector<Config> guide = read_guide(top, space);
  const ProblemPlannerHints hints = read_planner_hints(top);
  top.reject_unknown();
  return Problem{name, source, std::move(scene), space,       start,
                 goal, hints,  std::move(guide), std::nullopt};
}

Problem load_scenario_file(const std::filesystem::path& file, const FileAccess& access) {
  return parse_scenario(read_text_file(file), file.string(), file, access);
}

}  // namespace tandem
