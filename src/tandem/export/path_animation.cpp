#include "tandem/export/path_animation.hpp"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

constexpr int kSegments = 48;  // facets around a circle in the tessellated primitives
constexpr double kEnvelopeAlpha = 0.35;

/// Appends to one buffer and indexes it with views and accessors.
class GlbBuilder {
 public:
  GlbBuilder() { model_.buffers.emplace_back(); }

  /// An accessor of `count` elements of `type` (TINYGLTF_TYPE_*) over float data.
  int floats(const std::vector<float>& data, int type, int count, int target = 0) {
    const int view = append(data.data(), data.size() * sizeof(float), target);
    return accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
  }

  int indices(const std::vector<std::uint32_t>& data) {
    const int view = append(data.data(), data.size() * sizeof(std::uint32_t),
                            TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return accessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                    static_cast<int>(data.size()));
  }

  tinygltf::Model& model() { return model_; }
  tinygltf::Accessor& accessor_at(int index) {
    return model_.accessors.at(static_cast<std::size_t>(index));
  }

 private:
  int append(const void* bytes, std::size_t size, int target) {
    auto& data = model_.buffers[0].data;
    while (data.size() % 4 != 0)
      data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  int accessor(int view, int component, int type, int count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = component;
    a.type = type;
    a.count = static_cast<std::size_t>(count);
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  tinygltf::Model model_;
};

int add_material(tinygltf::Model& model, const std::string& name, const Color& c) {
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorFactor = {c.r, c.g, c.b, c.a};
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 0.7;
  m.alphaMode = c.a < 1.0 ? "BLEND" : "OPAQUE";
  m.doubleSided = true;  // CAD tessellations do not always face one way
  model.materials.push_back(m);
  return static_cast<int>(model.materials.size()) - 1;
}

/// A node with the mesh (positions with their bounds, indices, one material); -1 if it is empty.
int add_mesh_node(GlbBuilder& glb, const std::string& name, const TriangleMesh& mesh,
                  const Color& color) {
  if (mesh.triangles.empty())
    return -1;
  std::vector<float> positions;
  for (const Eigen::Vector3d& v : mesh.vertices)
    positions.insert(positions.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()),
                                       static_cast<float>(v.z())});
  std::vector<std::uint32_t> indices;
  for (const auto& t : mesh.triangles)
    indices.insert(indices.end(), t.begin(), t.end());
  tinygltf::Model& model = glb.model();
  tinygltf::Primitive primitive;
  const int position =
      glb.floats(positions, TINYGLTF_TYPE_VEC3, static_cast<int>(mesh.vertices.size()),
                 TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.attributes["POSITION"] = position;
  const auto [lo, hi] = mesh.bounding_box();
  glb.accessor_at(position).minValues = {lo.x(), lo.y(), lo.z()};
  glb.accessor_at(position).maxValues = {hi.x(), hi.y(), hi.z()};
  primitive.indices = glb.indices(indices);
  primitive.material = add_material(model, name, color);
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh m;
  m.name = name;
  m.primitives.push_back(primitive);
  model.meshes.push_back(m);
  tinygltf::Node node;
  node.name = name;
  node.mesh = static_cast<int>(model.meshes.size()) - 1;
  model.nodes.push_back(node);
  return static_cast<int>(model.nodes.size()) - 1;
}

/// The object node's channels: translation and rotation at every state (quaternions on one
/// hemisphere, so that each step is the shorter arc, as in the space's interpolation).
void add_path_animation(GlbBuilder& glb, int object, const Path& path,
                        const std::vector<double>& times) {
  std::vector<float> input, translation, rotation;
  Eigen::Quaterniond previous = path.front().q;
  for (std::size_t i = 0; i < path.size(); ++i) {
    Eigen::Quaterniond q = path[i].q.normalized();
    if (q.dot(previous) < 0)
      q.coeffs() = -q.coeffs();
    previous = q;
    input.push_back(static_cast<float>(times[i]));
    const Eigen::Vector3d& t = path[i].t;
    translation.insert(translation.end(), {static_cast<float>(t.x()), static_cast<float>(t.y()),
                                           static_cast<float>(t.z())});
    rotation.insert(rotation.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                     static_cast<float>(q.z()), static_cast<float>(q.w())});
  }
  const int n = static_cast<int>(path.size());
  tinygltf::Model& model = glb.model();
  const int time = glb.floats(input, TINYGLTF_TYPE_SCALAR, n);
  glb.accessor_at(time).minValues = {times.front()};
  glb.accessor_at(time).maxValues = {times.back()};
  tinygltf::Animation animation;
  animation.name = "path";
  const std::pair<const char*, int> outputs[] = {
      {"translation", glb.floats(translation, TINYGLTF_TYPE_VEC3, n)},
      {"rotation", glb.floats(rotation, TINYGLTF_TYPE_VEC4, n)}};
  for (const auto& [target, output] : outputs) {
    tinygltf::AnimationSampler sampler;
    sampler.input = time;
    sampler.output = output;
    sampler.interpolation = "LINEAR";
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
    channel.target_node = object;
    channel.target_path = target;
    animation.channels.push_back(channel);
  }
  model.animations.push_back(animation);
}

/// The object's node, posed at the first state (what a viewer shows without the animation).
int add_object(GlbBuilder& glb, const Body& object, const Config& start) {
  const int node = add_mesh_node(glb, "object", body_mesh(object, kSegments), object.color);
  if (node < 0)
    throw InputError("scene", "the moving object has no geometry to export");
  tinygltf::Node& n = glb.model().nodes.at(static_cast<std::size_t>(node));
  n.translation = {start.t.x(), start.t.y(), start.t.z()};
  const Eigen::Quaterniond q = start.q.normalized();
  n.rotation = {q.x(), q.y(), q.z(), q.w()};
  return node;
}

std::string to_glb(tinygltf::Model& model) {
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw std::logic_error("tinygltf could not write the animation");
  return out.str();
}

}  // namespace

std::vector<double> keyframe_times(const Path& path, const SE3Space& space, double duration) {
  std::vector<double> along{0.0};
  for (std::size_t i = 1; i < path.size(); ++i)
    along.push_back(along.back() + space.distance(path[i - 1], path[i]));
  const double total = along.back();
  std::vector<double> times;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto last = static_cast<double>(path.size() - 1);
    const double share = total > 0  ? along[i] / total
                         : last > 0 ? static_cast<double>(i) / last
                                    : 0.0;
    times.push_back(duration * share);
  }
  return times;
}

std::string path_animation_glb(const Scene& scene, const Path& path, const SE3Space& space,
                               const AnimationOptions& options) {
  if (!(options.duration > 0) || !std::isfinite(options.duration))
    throw InputError("--duration", "must be a positive number of seconds");
  if (path.empty())
    throw InputError("path", "has no state");
  GlbBuilder glb;
  tinygltf::Model& model = glb.model();
  model.asset.version = "2.0";
  model.asset.generator = "tandem";
  model.asset.extras =
      tinygltf::Value(tinygltf::Value::Object{{"title", tinygltf::Value(options.title)}});
  tinygltf::Node root;
  root.name = "tandem-z-up";
  root.rotation = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};  // z up -> glTF's y up
  std::vector<int> children;
  for (const Body& body : scene.obstacles)
    if (const int node = add_mesh_node(glb, body.name, body_mesh(body, kSegments), body.color);
        node >= 0)
      children.push_back(node);
  const int object = add_object(glb, scene.object, path.front());
  children.push_back(object);
  if (options.envelope != nullptr)
    if (const int node =
            add_mesh_node(glb, "envelope", *options.envelope, {0.95, 0.55, 0.1, kEnvelopeAlpha});
        node >= 0)
      children.push_back(node);
  add_path_animation(glb, object, path, keyframe_times(path, space, options.duration));
  root.children = children;
  model.nodes.push_back(root);
  tinygltf::Scene s;
  s.name = options.title;
  s.nodes = {static_cast<int>(model.nodes.size()) - 1};
  model.scenes.push_back(s);
  model.defaultScene = 0;
  return to_glb(model);
}

}  // namespace tandem
