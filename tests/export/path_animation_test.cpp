// The animated glTF: read back with tinygltf, it has the scene's bodies with their colours, the
// object's animation keyed at every state (times at constant speed, quaternions on one hemisphere
// so each step is the shorter arc), and the envelope when given; the player page inlines it.

#include "tandem/export/path_animation.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <numbers>

#include "tandem/core/error.hpp"
#include "tandem/export/player_page.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;
using Vec = Eigen::Vector3d;

Scene scene() {
  Scene s;
  s.object = {"part", {{Box{{0.2, 0.1, 0.1}}, Eigen::Isometry3d::Identity()}}, {0.9, 0.8, 0.1, 1}};
  Body wall{"wall", {{Box{{0.1, 1, 1}}, Eigen::Isometry3d::Identity()}}, {0.2, 0.3, 0.9, 1}};
  wall.parts.push_back({Cylinder{0.05, 0.4}, Eigen::Isometry3d(Eigen::Translation3d(0, 0, 1))});
  s.obstacles = {wall, Body{"post", {{Sphere{0.1}, Eigen::Isometry3d::Identity()}}, {}}};
  return s;
}

Config state(double x, double angle) {
  return {Vec(x, 0.5, 0), Eigen::Quaterniond(Eigen::AngleAxisd(angle, Vec::UnitZ()))};
}

tinygltf::Model read_back(const std::string& glb) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(glb.data()),
                                              static_cast<unsigned>(glb.size()));
  EXPECT_TRUE(ok) << err;
  EXPECT_EQ(warn, "");
  return model;
}

std::vector<float> floats(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::size_t n = a.count * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(
                                      static_cast<std::uint32_t>(a.type)));
  std::vector<float> out(n);
  std::memcpy(out.data(), m.buffers[0].data.data() + v.byteOffset + a.byteOffset,
              n * sizeof(float));
  return out;
}

const tinygltf::Node& node(const tinygltf::Model& m, const std::string& name) {
  for (const auto& n : m.nodes)
    if (n.name == name)
      return n;
  throw std::runtime_error("no node " + name);
}

class PathAnimationTest : public ::testing::Test {
 protected:
  SE3Space space_{SpaceKind::se3, Bounds{{-2, -2, -2}, {2, 2, 2}}};
  Scene scene_ = scene();
  // The last turn goes from 170 to -170 degrees: 20 degrees the short way.
  Path path_{state(0, 0), state(1, 0), state(1, 170 * std::numbers::pi / 180),
             state(1, -170 * std::numbers::pi / 180)};
};

TEST_F(PathAnimationTest, KeyframesAreAtConstantSpeedInTheMetric) {
  const auto times = keyframe_times(path_, space_, 8.0);
  const double total = 1.0 + 0.5 * (170 + 20) * std::numbers::pi / 180;
  ASSERT_EQ(times.size(), 4u);
  EXPECT_DOUBLE_EQ(times[0], 0.0);
  EXPECT_NEAR(times[1], 8.0 / total, 1e-9);
  EXPECT_DOUBLE_EQ(times[3], 8.0);
  EXPECT_EQ(keyframe_times({state(0, 0), state(0, 0), state(0, 0)}, space_, 2.0),
            (std::vector<double>{0.0, 1.0, 2.0}));
}

TEST_F(PathAnimationTest, HasTheBodiesTheirColoursAndTheObjectsAnimation) {
  const std::string glb = path_animation_glb(scene_, path_, space_, {6.0, nullptr, "t"});
  ASSERT_EQ(glb.substr(0, 4), "glTF");
  const tinygltf::Model m = read_back(glb);
  const auto& root = node(m, "tandem-z-up");
  EXPECT_NEAR(root.rotation[0], -std::sqrt(0.5), 1e-12);
  EXPECT_EQ(root.children.size(), 3u);  // wall, post, object: no envelope
  const auto& wall = m.meshes.at(static_cast<std::size_t>(node(m, "wall").mesh));
  const auto& colour =
      m.materials.at(static_cast<std::size_t>(wall.primitives[0].material)).pbrMetallicRoughness;
  EXPECT_EQ(colour.baseColorFactor, (std::vector<double>{0.2, 0.3, 0.9, 1}));
  ASSERT_EQ(m.animations.size(), 1u);
  const tinygltf::Animation& a = m.animations[0];
  ASSERT_EQ(a.channels.size(), 2u);
  const int object = static_cast<int>(&node(m, "object") - m.nodes.data());
  for (const auto& c : a.channels) {
    EXPECT_EQ(c.target_node, object);
    EXPECT_EQ(a.samplers[static_cast<std::size_t>(c.sampler)].interpolation, "LINEAR");
  }
  const auto times = floats(m, a.samplers[0].input);
  ASSERT_EQ(times.size(), 4u);
  EXPECT_FLOAT_EQ(times.back(), 6.0f);
  const auto t = floats(m, a.samplers[0].output);
  const auto q = floats(m, a.samplers[1].output);
  EXPECT_EQ(a.channels[0].target_path, "translation");
  EXPECT_FLOAT_EQ(t[9], 1.0f);
  EXPECT_FLOAT_EQ(t[10], 0.5f);
  for (std::size_t i = 1; i < 4; ++i) {  // consecutive keys on one hemisphere: the shorter arc
    double dot = 0;
    for (std::size_t k = 0; k < 4; ++k)
      dot += static_cast<double>(q[4 * i + k] * q[4 * (i - 1) + k]);
    EXPECT_GT(dot, 0) << "key " << i;
  }
  const Eigen::Quaterniond last(q[15], q[12], q[13], q[14]);
  EXPECT_NEAR(std::abs(last.dot(path_.back().q)), 1.0, 1e-6);
}

TEST_F(PathAnimationTest, CarriesTheEnvelopeAndRejectsBadInput) {
  TriangleMesh envelope;
  envelope.vertices = {Vec(0, 0, 0), Vec(1, 0, 0), Vec(0, 1, 0)};
  envelope.triangles = {{0, 1, 2}};
  const tinygltf::Model m =
      read_back(path_animation_glb(scene_, path_, space_, {6.0, &envelope, "t"}));
  const auto& mesh = m.meshes.at(static_cast<std::size_t>(node(m, "envelope").mesh));
  const auto& material = m.materials.at(static_cast<std::size_t>(mesh.primitives[0].material));
  EXPECT_EQ(material.alphaMode, "BLEND");
  EXPECT_THROW(path_animation_glb(scene_, {}, space_, {}), InputError);
  EXPECT_THROW(path_animation_glb(scene_, path_, space_, {0.0, nullptr, "t"}), InputError);
}

TEST(PlayerPage, InlinesTheAnimationAndAScriptThatCannotEndItsElement) {
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64(std::string("\xff\x00", 2)), "/wA=");
  const std::string page = player_page("glb!", "let s = '</script>';", "a <b> & \"c\"");
  EXPECT_THAT(page, HasSubstr("<title>a &lt;b&gt; &amp; &quot;c&quot;</title>"));
  EXPECT_THAT(page, HasSubstr(">" + base64("glb!") + "</script>"));
  EXPECT_THAT(page, HasSubstr("let s = '<\\/script>';"));
  EXPECT_EQ(page.find("'</script>"), std::string::npos);
}

}  // namespace
}  // namespace tandem
