// The viewer's messages, as the WebSocket session hands a text frame to the decoder: refused with a
// ProtocolError (which the session answers with an "error" message) or accepted.

#include "fuzz_target.hpp"
#include "tandem/web/protocol.hpp"

namespace tandem::fuzz {

bool protocol(std::string_view input) {
  try {
    (void)parse_client_message(input, InteractionSettings{});
    return true;
  } catch (const ProtocolError&) {
    return false;
  }
}

}  // namespace tandem::fuzz
