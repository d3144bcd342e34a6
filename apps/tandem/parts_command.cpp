// tandem parts: the assembly tree of a STEP or IGES file, as tandem reads it.

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/scene/cad_loader.hpp"

namespace tandem::cli {
namespace {

std::string hex(const Color& c) {
  char s[8];
  auto byte = [](double x) { return static_cast<int>(std::lround(std::clamp(x, 0.0, 1.0) * 255)); };
  std::snprintf(s, sizeof s, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return s;
}

/// The part's size: its own bounding box's sides, in metres.
Eigen::Vector3d size(const CadNode& n) {
  const auto [lo, hi] = n.mesh.bounding_box();
  return n.mesh.vertices.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(hi - lo);
}

nlohmann::json to_json(const CadAssembly& a) {
  nlohmann::json nodes = nlohmann::json::array();
  for (const CadNode& n : a.nodes) {
    nlohmann::json j{{"name", n.name},
                     {"path", n.path},
                     {"product", n.product},
                     {"depth", n.depth},
                     {"assembly", n.assembly}};
    if (!n.assembly) {
      const Eigen::Vector3d s = size(n), t = n.placement.translation();
      const Eigen::Quaterniond q(n.placement.linear());
      j["size_m"] = {s.x(), s.y(), s.z()};
      j["position_m"] = {t.x(), t.y(), t.z()};
      j["quaternion"] = {q.x(), q.y(), q.z(), q.w()};
      j["triangles"] = n.mesh.triangle_count();
      j["color"] = n.has_color ? nlohmann::json(hex(n.color)) : nlohmann::json(nullptr);
    }
    nodes.push_back(j);
  }
  return {{"format", a.format},
          {"unit_m", a.unit_m},
          {"linear_deflection_m", a.linear_deflection},
          {"angular_deflection_rad", a.angular_deflection},
          {"nodes", nodes}};
}

void print(const CadAssembly& a, const std::string& file) {
  std::printf("%s: %s, length unit %g m, tessellated to %.3g m and %.3g rad\n", file.c_str(),
              a.format.c_str(), a.unit_m, a.linear_deflection, a.angular_deflection);
  for (const CadNode& n : a.nodes) {
    const std::string indent(2 * static_cast<std::size_t>(n.depth), ' ');
    const std::string product =
        n.product.empty() || n.product == n.name ? "" : " [" + n.product + "]";
    if (n.assembly) {
      std::printf("%s%s%s (assembly)\n", indent.c_str(), n.name.c_str(), product.c_str());
      continue;
    }
    const Eigen::Vector3d s = size(n);
    std::printf("%s%s%s  %.4g x %.4g x %.4g m, %zu triangles, %s\n", indent.c_str(), n.name.c_str(),
                product.c_str(), s.x(), s.y(), s.z(), n.mesh.triangle_count(),
                n.has_color ? hex(n.color).c_str() : "no colour");
  }
}

}  // namespace

Command add_parts_command(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto options = std::make_shared<CadOptions>();
  auto json = std::make_shared<bool>(false);
  app.add_option("FILE", *file, "A STEP (.step, .stp) or IGES (.iges, .igs) file")->required();
  add_tessellation_args(app, *options, "Options");
  app.add_flag("--json", *json, "Print the tree as JSON");
  return [file, options, json]() -> int {
    const CadAssembly a = load_cad(*file, *options);
    if (*json)
      std::cout << to_json(a).dump(2) << "\n";
    else
      print(a, *file);
    return 0;
  };
}

}  // namespace tandem::cli
