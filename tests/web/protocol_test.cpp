// The viewer's protocol: every hostile message is refused with a reason, and node deltas are laid
// out as the browser decodes them.

#include "tandem/web/protocol.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "tandem/planning/tree.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

std::string refusal(const std::string& text) {
  try {
    parse_client_message(text, InteractionSettings{});
  } catch (const ProtocolError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Protocol, RefusesEveryMalformedOrHostileMessage) {
  EXPECT_THAT(refusal("not json"), HasSubstr("not JSON"));
  EXPECT_THAT(refusal("[1,2]"), HasSubstr("JSON object"));
  EXPECT_THAT(refusal("{\"type\":5}"), HasSubstr("\"type\""));
  EXPECT_THAT(refusal("{\"type\":\"nope\"}"), HasSubstr("unknown message type"));
  EXPECT_THAT(refusal("{\"type\":\"pose\"}"), HasSubstr("needs q"));
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[1,2,3]}"), HasSubstr("7 numbers"));
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[0,0,0,0,0,0,0]}"), HasSubstr("zero"));
  // At most kMinQuaternionNorm, as every other reader of a rotation refuses it.
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[0,0,0,0,0,5e-10,5e-10]}"), HasSubstr("zero"));
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[1e308,0,0,0,0,0,1]}"), HasSubstr("q must be in"));
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[\"a\",0,0,0,0,0,1]}"), HasSubstr("number"));
  EXPECT_THAT(refusal("{\"type\":\"pose\",\"q\":[0,0,0,0,0,0,1],\"id\":-1}"),
              HasSubstr("non-negative"));
  EXPECT_THAT(refusal("{\"type\":\"params\"}"), HasSubstr("no parameter"));
  EXPECT_THAT(refusal("{\"type\":\"params\",\"alpha\":7}"),
              HasSubstr("alpha must be a number in [0, 1], not 7"));
  EXPECT_THAT(refusal("{\"type\":\"params\",\"contact\":1}"), HasSubstr("true or false"));
  EXPECT_THAT(refusal("{\"type\":\"params\",\"contact_samples\":0}"), HasSubstr("contact_samples"));
  EXPECT_THAT(refusal("{\"type\":\"params\",\"sampling\":\"x\"}"), HasSubstr("sampling"));
  EXPECT_THAT(refusal("{\"type\":\"params\",\"seed\":3}"), HasSubstr("unknown parameter"));
  EXPECT_THAT(refusal("{\"type\":\"input\",\"input\":\"joystick\"}"), HasSubstr("input must"));
  EXPECT_THAT(refusal("{\"type\":\"command\",\"command\":\"quit\"}"), HasSubstr("command must"));
  EXPECT_THAT(refusal(std::string(kMaxMessageBytes + 1, ' ')), HasSubstr("too long"));
  EXPECT_THAT(refusal("{\"type\":\"take_out\"}"), HasSubstr("take_out needs a part"));
  EXPECT_THAT(refusal("{\"type\":\"take_out\",\"part\":3}"), HasSubstr("take_out needs a part"));
  EXPECT_THAT(refusal("{\"type\":\"take_out\",\"part\":\"\"}"), HasSubstr("1 to 1024 bytes"));
  EXPECT_THAT(refusal("{\"type\":\"take_out\",\"part\":\"" + std::string(1025, 'x') + "\"}"),
              HasSubstr("1 to 1024 bytes"));
}

TEST(Protocol, ParsesWhatTheViewerSends) {
  const ClientMessage pose =
      parse_client_message("{\"type\":\"pose\",\"q\":[1,2,3,0,0,0,2],\"id\":9}", {});
  EXPECT_EQ(pose.kind, ClientMessage::Kind::pose);
  EXPECT_EQ(pose.q.t, Eigen::Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(pose.q.q.w(), 1.0) << "normalised";
  EXPECT_EQ(pose.id, 9u);
  // Above kMinQuaternionNorm, a direction however short (the threshold was 1e-6 here, 1e-9 in
  // the files' readers).
  const ClientMessage small =
      parse_client_message("{\"type\":\"pose\",\"q\":[0,0,0,1e-8,0,0,1e-8]}", {});
  EXPECT_NEAR(small.q.q.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(small.q.q.w(), std::sqrt(0.5), 1e-15);
  InteractionSettings current;
  current.contact_samples = 4;
  const ClientMessage params = parse_client_message(
      "{\"type\":\"params\",\"alpha\":0.25,\"contact\":true,\"sampling\":\"path+cs\"}", current);
  EXPECT_EQ(params.settings.alpha, 0.25);
  EXPECT_TRUE(params.settings.contact);
  EXPECT_EQ(params.settings.sampling, IrrtSampling::path_cs);
  EXPECT_EQ(params.settings.contact_samples, 4) << "what the message does not name is kept";
  EXPECT_EQ(parse_client_message("{\"type\":\"input\",\"input\":\"simulated\"}", {}).input,
            OperatorInput::simulated);
  EXPECT_EQ(parse_client_message("{\"type\":\"command\",\"command\":\"step\"}", {}).command,
            "step");
  const ClientMessage take_out =
      parse_client_message("{\"type\":\"take_out\",\"part\":\"bracket/walls/wall-left\"}", {});
  EXPECT_EQ(take_out.kind, ClientMessage::Kind::take_out);
  EXPECT_EQ(take_out.part, "bracket/walls/wall-left");
}

TEST(Protocol, NodeMessagesAreLaidOutAsTheBrowserReadsThem) {
  NodeBatch b;
  b.tree = 1;
  b.generation = 2;
  b.first = 10;
  b.positions = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  b.parents = {Tree::kNoParent, 10, 11};
  b.sources = {0, 2, 3};
  b.labels = {-1, 0.5f, 0.25f};
  const std::string m = encode_nodes(b);
  const std::size_t n = 3, pad = 1;
  ASSERT_EQ(m.size(), 16 + 12 * n + 4 * n + n + pad + 4 * n);
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, m.data() + at, 4);
    return v;
  };
  auto f32 = [&](std::size_t at) {
    float v;
    std::memcpy(&v, m.data() + at, 4);
    return v;
  };
  EXPECT_EQ(m[0], 1);
  EXPECT_EQ(m[1], 1);
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), 10u);
  EXPECT_EQ(u32(12), 3u);
  EXPECT_EQ(f32(16 + 4 * 8), 9.0f);
  EXPECT_EQ(u32(16 + 12 * n), Tree::kNoParent);
  EXPECT_EQ(u32(16 + 12 * n + 8), 11u);
  EXPECT_EQ(m[16 + 16 * n + 2], 3);
  EXPECT_EQ(f32(16 + 17 * n + pad + 4), 0.5f);
}

}  // namespace
}  // namespace tandem
