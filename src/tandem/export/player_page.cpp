#include "tandem/export/player_page.hpp"

#include <cstdint>
#include <fstream>
#include <sstream>

namespace tandem {
namespace {

std::string escape_html(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// A script's text with every "</script" (which would end the element early) written "<\/script".
std::string script_safe(const std::string& script) {
  std::string out;
  out.reserve(script.size());
  for (std::size_t i = 0; i < script.size(); ++i) {
    if (script.compare(i, 8, "</script") == 0) {
      out += "<\\/";
      i += 1;
      continue;
    }
    out += script[i];
  }
  return out;
}

constexpr const char* kStyle = R"(html, body { margin: 0; height: 100%; background: #1d2127;
  color: #e8e8e8; font: 14px system-ui, sans-serif; overflow: hidden; }
#view { position: absolute; inset: 0 0 48px 0; }
#bar { position: absolute; left: 0; right: 0; bottom: 0; height: 48px; display: flex; gap: 10px;
  align-items: center; padding: 0 12px; background: #2a2f37; box-sizing: border-box; }
#scrub { flex: 1; }
#title { position: absolute; left: 12px; top: 10px; opacity: 0.8; pointer-events: none; }
button { min-width: 64px; }
)";

}  // namespace

std::optional<std::string> read_player_script(const std::filesystem::path& web_root) {
  std::ifstream in(web_root / "player" / "player.js", std::ios::binary);
  if (!in)
    return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t word = 0;
    for (std::size_t k = 0; k < 3; ++k)
      word = word << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= n ? kDigits[(word >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string player_page(const std::string& glb, const std::string& player_script,
                        const std::string& title) {
  const std::string t = escape_html(title);
  return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         t + "</title>\n<style>\n" + kStyle + "</style>\n</head>\n<body>\n" +
         "<div id=\"view\"></div>\n<div id=\"title\">" + t + "</div>\n" +
         "<div id=\"bar\"><button id=\"play\">Pause</button>"
         "<input id=\"scrub\" type=\"range\" min=\"0\" max=\"1000\" step=\"1\" value=\"0\">"
         "<span id=\"time\"></span><label id=\"envelope-toggle\" hidden><input id=\"envelope\" "
         "type=\"checkbox\" checked> envelope</label></div>\n"
         "<script type=\"application/octet-stream\" id=\"tandem-glb\">" +
         base64(glb) + "</script>\n<script>\n" + script_safe(player_script) +
         "\n</script>\n</body>\n</html>\n";
}

}  // namespace tandem
