#pragma once
// The viewer's protocol: what tandem sends the browser and what it accepts from it.
//
// Server to browser, over the WebSocket:
//   text  {"type":"hello", …}      the session: problem, mode, settings, inputs, generation
//   text  {"type":"status", …}     statistics, mode, elapsed time, rates, input latency
//   text  {"type":"operator", …}   q_device, the nearest obstacle, the contact plane, F_a
//   text  {"type":"solution","path":[[x,y,z,qx,qy,qz,qw], …]}
//   text  {"type":"reset","generation":g}   the planner started over: clear the trees
//   text  {"type":"error","message":"…"}    a message of the browser's was refused
//   binary nodes of one tree, new since the last message (see encode_nodes()): only deltas
// Browser to server (text, at most kMaxMessageBytes):
//   {"type":"pose","q":[x,y,z,qx,qy,qz,qw],"id":n}   the browser moves the part (takes over)
//   {"type":"input","input":"simulated|browser|spacemouse"}
//   {"type":"params", NAME: value, ...}   live tunables of interaction_parameters(), each within
//                                        its declared range (the hello announces them)
//   {"type":"command","command":"pause|resume|step|reset"}
//   {"type":"take_out","part":"a/b/c"}   choosing an assembly's part to take out (a path in its
//                                        tree, 1 to 1024 bytes; only while choosing one)
// Anything else, or a value out of range, is refused with a ProtocolError naming the fault.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/interaction/interaction_settings.hpp"
#include "tandem/operators/operator_switch.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

inline constexpr std::size_t kMaxMessageBytes = 16 * 1024;

class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ClientMessage {
  enum class Kind : std::uint8_t { pose, input, params, command, take_out } kind = Kind::pose;
  Config q;                                      ///< pose: finite, unit quaternion (normalised)
  std::uint64_t id = 0;                          ///< pose: the event's id
  OperatorInput input = OperatorInput::browser;  ///< input
  InteractionSettings settings;  ///< params: `current` with the message's fields applied
  std::string command;           ///< command: pause, resume, step or reset
  std::string part;              ///< take_out: the part's path in the assembly tree
};

/// Parses and validates a message. `current` is what a "params" message changes. Throws
/// ProtocolError.
ClientMessage parse_client_message(std::string_view text, const InteractionSettings& current);

/// The live tunables `planner` reads, as the hello message announces them to the tuning panel
/// (see param_spec_json), with the session's starting values as defaults.
nlohmann::json announced_parameters(std::string_view planner, const InteractionSettings& defaults);

/// The scene for the viewer: every body as triangles in its frame (obstacles in the world frame,
/// the object in its own frame), with colours, the bounds, start, goal and guide. JSON.
std::string encode_scene(const Problem& problem);

/// One tree's new nodes, for a binary WebSocket message (little endian):
///   u8 kind = 1, u8 tree, u16 0, u32 generation, u32 first node index, u32 count,
///   f32 position[3 count], u32 parent[count] (0xffffffff for a root), u8 source[count]
///   (0 root, 1 random, 2 operator, 3 contact), zero padding to a multiple of 4,
///   f32 label[count] (the I-RRT's distance-to-goal label over the space's extent, or -1).
struct NodeBatch {
  std::uint8_t tree = 0;
  std::uint32_t generation = 0;
  std::uint32_t first = 0;
  std::vector<float> positions;
  std::vector<std::uint32_t> parents;
  std::vector<std::uint8_t> sources;
  std::vector<float> labels;
  std::size_t size() const { return parents.size(); }
};
std::string encode_nodes(const NodeBatch& batch);

}  // namespace tandem
