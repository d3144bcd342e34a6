#include "tandem/scene/urdf_loader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/scene/mesh_loader.hpp"

namespace tandem {
namespace {

/// Captures urdfdom's console messages instead of letting them reach stderr, so a parse failure
/// becomes one InputError with urdfdom's own reason.
class CapturingHandler final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error_.empty())
      first_error_ = text;
  }
  std::string first_error_;
};

Eigen::Isometry3d to_isometry(const urdf::Pose& p) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  double x, y, z, w;
  p.rotation.getQuaternion(x, y, z, w);
  X.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
  return X;
}

void require_positive(double v, const std::string& source, const std::string& what) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    std::ostringstream os;
    os << what << " must be a positive finite number, got " << v;
    throw InputError(source, os.str());
  }
}

Geometry to_geometry(const urdf::Geometry& g, const std::string& source, const std::string& link,
                     const std::filesystem::path& file, const FileAccess& access) {
  const std::string where = "link '" + link + "': ";
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(g);
      Box box{{b.dim.x, b.dim.y, b.dim.z}};
      for (int i = 0; i < 3; ++i)
        require_positive(box.size[i], source, where + "box size");
      return box;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(g);
      require_positive(s.radius, source, where + "sphere radius");
      return Sphere{s.radius};
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      require_positive(c.radius, source, where + "cylinder radius");
      require_positive(c.length, source, where + "cylinder length");
      return Cylinder{c.radius, c.length};
    }
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(g);
      const Eigen::Vector3d scale(m.scale.x, m.scale.y, m.scale.z);
      for (int i = 0; i < 3; ++i)
        require_positive(scale[i], source, where + "mesh scale");
      std::filesystem::path mesh_file;
      LoadedMesh loaded;
      try {
        mesh_file = resolve_reference(m.filename, file, access);
        loaded = load_mesh(mesh_file);
      } catch (const InputError& e) {
        // Name the URDF too: "robot.urdf: link 'a': part.stl: no such file".
        throw InputError(source, where + e.what());
      }
      for (auto& v : loaded.mesh.vertices)
        v = v.cwiseProduct(scale);
      return MeshShape{std::make_shared<const TriangleMesh>(std::move(loaded.mesh)),
                       mesh_file.string()};
    }
  }
  throw InputError(source, where + "unsupported geometry type");
}

/// The URDF text parsed by urdfdom. Throws InputError with urdfdom's own reason.
urdf::ModelInterfaceSharedPtr parse_model(const std::string& text, const std::string& source) {
  // console_bridge's handler is process-global.
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  CapturingHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  console_bridge::restorePreviousOutputHandler();
  if (!model) {
    throw InputError(
        source, "not a valid URDF" +
                    (handler.first_error_.empty() ? std::string() : ": " + handler.first_error_));
  }
  return model;
}

/// urdfdom's model, whose links' lists of children are cut when it goes: urdfdom holds a link's
/// children by shared_ptr, so joints that form a loop make a cycle that would never be freed (a
/// finding of the scenario fuzz target).
class ParsedModel {
 public:
  explicit ParsedModel(urdf::ModelInterfaceSharedPtr model) : model_(std::move(model)) {}
  ~ParsedModel() {
    for (auto& [name, link] : model_->links_) {
      link->child_links.clear();
      link->child_joints.clear();
    }
  }
  ParsedModel(const ParsedModel&) = delete;
  ParsedModel& operator=(const ParsedModel&) = delete;
  const urdf::ModelInterface* operator->() const { return model_.get(); }

 private:
  urdf::ModelInterfaceSharedPtr model_;
};

/// Throws InputError unless every link was reached once from the root: urdfdom accepts joints
/// that form a loop, whose links are then out of the tree or on an endless walk down it.
void require_tree(const ParsedModel& model, const std::set<std::string>& reached,
                  const std::string& source) {
  for (const auto& [name, link] : model->links_) {
    if (reached.count(name) == 0) {
      throw InputError(source, "link '" + name +
                                   "' is not in the tree of joints from the root link '" +
                                   model->getRoot()->name + "' (the joints form a loop)");
    }
  }
}

}  // namespace

Body load_urdf(const std::filesystem::path& file, UrdfRole role, const FileAccess& access) {
  const std::string source = file.string();
  const ParsedModel model(parse_model(read_text_file(file), source));
  const urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root)
    throw InputError(source, "the URDF has no root link");

  Body body;
  body.name = model->getName();
  bool have_color = false;
  std::set<std::string> reached;
  std::function<void(const urdf::LinkConstSharedPtr&, const Eigen::Isometry3d&)> visit =
      [&](const urdf::LinkConstSharedPtr& link, const Eigen::Isometry3d& X_RL) {
        if (!reached.insert(link->name).second) {
          throw InputError(source, "link '" + link->name +
                                       "' is the child of two joints (the joints form a loop)");
        }
        const bool use_collision = !link->collision_array.empty() || link->collision;
        if (use_collision) {
          auto add = [&](const urdf::CollisionSharedPtr& c) {
            if (c && c->geometry) {
              body.parts.push_back({to_geometry(*c->geometry, source, link->name, file, access),
                                    X_RL * to_isometry(c->origin)});
            }
          };
          if (link->collision_array.empty())
            add(link->collision);
          for (const auto& c : link->collision_array)
            add(c);
        } else {
          auto add = [&](const urdf::VisualSharedPtr& v) {
            if (v && v->geometry) {
              body.parts.push_back({to_geometry(*v->geometry, source, link->name, file, access),
                                    X_RL * to_isometry(v->origin)});
            }
          };
          if (link->visual_array.empty())
            add(link->visual);
          for (const auto& v : link->visual_array)
            add(v);
        }
        if (!have_color) {
          for (const auto& v : link->visual_array) {
            if (v && v->material) {
              const auto& c = v->material->color;
              body.color = {static_cast<double>(c.r), static_cast<double>(c.g),
                            static_cast<double>(c.b), c.a > 0.0f ? static_cast<double>(c.a) : 1.0};
              have_color = true;
              break;
            }
          }
        }
        for (const auto& joint : link->child_joints) {
          if (role == UrdfRole::object && joint->type != urdf::Joint::FIXED) {
            throw InputError(
                source,
                "joint '" + joint->name +
                    "' is movable; the moving object must be rigid (make its joints fixed)");
          }
          const auto child = model->getLink(joint->child_link_name);
          if (child)
            visit(child, X_RL * to_isometry(joint->parent_to_joint_origin_transform));
        }
      };
  visit(root, Eigen::Isometry3d::Identity());
  require_tree(model, reached, source);
  if (body.parts.empty())
    throw InputError(source, "no link has collision or visual geometry");
  return body;
}

}  // namespace tandem
