#pragma once
// One self-contained HTML page that plays an animation (.glb) with no network: the glb inlined as
// base64, the player script (three.js, its GLTFLoader and OrbitControls, tandem's player:
// web/src/player, built by scripts/build-web into web/dist/player/player.js) inlined whole.

#include <filesystem>
#include <optional>
#include <string>

namespace tandem {

/// The page's text. `player_script`: the built player (an IIFE); `title`: the page's title
/// (escaped here).
std::string player_page(const std::string& glb, const std::string& player_script,
                        const std::string& title);

/// The built player under a web root (web/dist, or $TANDEM_WEB_ROOT): player/player.js's text,
/// or nullopt when it is not built.
std::optional<std::string> read_player_script(const std::filesystem::path& web_root);

/// Standard base64 (RFC 4648, with padding).
std::string base64(const std::string& bytes);

}  // namespace tandem
