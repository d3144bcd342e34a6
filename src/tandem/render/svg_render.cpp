#include "tandem/render/svg_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tandem {
namespace {

struct WorldTriangle {
  Eigen::Vector3d p[3];
  Color color;
};

std::vector<WorldTriangle> world_triangles(const Body& body, const Eigen::Isometry3d& X_WB) {
  std::vector<WorldTriangle> out;
  for (const Part& part : body.parts) {
    const TriangleMesh mesh = tessellate(part.geometry, 16);
    const Eigen::Isometry3d X = X_WB * part.pose;
    for (const auto& t : mesh.triangles) {
      out.push_back({{X * mesh.vertices[t[0]], X * mesh.vertices[t[1]], X * mesh.vertices[t[2]]},
                     body.color});
    }
  }
  return out;
}

std::string hex(const Color& c, double shade) {
  auto channel = [&](double v) {
    return static_cast<int>(std::clamp(v * shade, 0.0, 1.0) * 255.0 + 0.5);
  };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
  return buf;
}

/// One orthographic view: world axes (u, v) to the panel, `depth` toward the viewer.
struct View {
  int u, v, depth;
  const char* title;
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
  double scale = 1.0;
  double x0 = 0.0, y0 = 0.0;

  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    return {x0 + (p[u] - lo.x()) * scale, y0 + (hi.y() - p[v]) * scale};
  }
};

}  // namespace

std::string render_svg(const Problem& problem, const Path& path, const SvgOptions& options) {
  std::vector<WorldTriangle> scene;
  for (const Body& b : problem.scene.obstacles) {
    auto tris = world_triangles(b, Eigen::Isometry3d::Identity());
    scene.insert(scene.end(), tris.begin(), tris.end());
  }
  if (scene.size() > options.max_triangles) {
    // Keep every k-th triangle: a large mesh stays recognisable and the file stays small.
    const std::size_t k = (scene.size() + options.max_triangles - 1) / options.max_triangles;
    std::vector<WorldTriangle> thinned;
    for (std::size_t i = 0; i < scene.size(); i += k)
      thinned.push_back(scene[i]);
    scene.swap(thinned);
  }

  // Extent: the bounds, the obstacles and the object along the path.
  const Bounds& bounds = problem.space.bounds();
  Eigen::Vector3d lo = bounds.min, hi = bounds.max;
  for (const auto& t : scene) {
    for (const auto& p : t.p) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  std::vector<Config> snapshots;
  if (!path.empty()) {
    snapshots.push_back(path.front());
    const double total = path_length(problem.space, path);
    const int n = std::max(0, options.object_snapshots);
    double walked = 0.0;
    std::size_t seg = 0;
    for (int i = 1; i <= n && total > 0.0; ++i) {
      const double target = total * i / (n + 1);
      while (seg + 1 < path.size() &&
             walked + problem.space.distance(path[seg], path[seg + 1]) < target) {
        walked += problem.space.distance(path[seg], path[seg + 1]);
        ++seg;
      }
      if (seg + 1 >= path.size())
        break;
      const double d = problem.space.distance(path[seg], path[seg + 1]);
      snapshots.push_back(
          problem.space.interpolate(path[seg], path[seg + 1], d > 0 ? (target - walked) / d : 0.0));
    }
    snapshots.push_back(path.back());
  } else {
    snapshots = {problem.start, problem.goal};
  }
  std::vector<std::vector<WorldTriangle>> objects;
  for (const Config& q : snapshots) {
    objects.push_back(world_triangles(problem.scene.object, q.pose()));
    for (const auto& t : objects.back()) {
      for (const auto& p : t.p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  }

  const bool planar = problem.space.planar();
  std::vector<View> views = {{0, 1, 2, "top view (x right, y up)"}};
  if (!planar)
    views.push_back({0, 2, 1, "side view (x right, z up)"});
  const double margin = 30.0;
  double y = margin;
  const double width = options.panel_width;
  for (View& view : views) {
    view.lo = {lo[view.u], lo[view.v]};
    view.hi = {hi[view.u], hi[view.v]};
    const Eigen::Vector2d size = (view.hi - view.lo).cwiseMax(1e-9);
    view.scale = width / size.x();
    view.x0 = margin;
    view.y0 = y + 20.0;
    y = view.y0 + size.y() * view.scale + margin;
  }

  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(1);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width + 2 * margin
      << "\" height=\"" << y
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"#ffffff\"/>\n";
  svg << "<title>tandem: " << problem.name << "</title>\n";
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();

  auto draw = [&](const View& view, std::vector<WorldTriangle> tris, double opacity,
                  const char* stroke) {
    // Painter's order: farthest from the viewer first.
    const double sign = view.depth == 1 ? -1.0 : 1.0;  // the side view looks along +y
    std::sort(tris.begin(), tris.end(), [&](const WorldTriangle& a, const WorldTriangle& b) {
      return sign * (a.p[0][view.depth] + a.p[1][view.depth] + a.p[2][view.depth]) <
             sign * (b.p[0][view.depth] + b.p[1][view.depth] + b.p[2][view.depth]);
    });
    for (const auto& t : tris) {
      const Eigen::Vector3d n = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]);
      const double len = n.norm();
      const double shade = len > 0 ? 0.55 + 0.45 * std::abs(n.dot(light)) / len : 1.0;
      svg << "<polygon points=\"";
      for (const auto& p : t.p) {
        const Eigen::Vector2d s = view.project(p);
        svg << s.x() << ',' << s.y() << ' ';
      }
      svg << "\" fill=\"" << hex(t.color, shade) << "\" fill-opacity=\"" << opacity << "\"";
      if (stroke)
        svg << " stroke=\"" << stroke << "\" stroke-width=\"0.3\" stroke-opacity=\"0.5\"";
      svg << "/>\n";
    }
  };

  for (const View& view : views) {
    svg << "<text x=\"" << view.x0 << "\" y=\"" << view.y0 - 6 << "\">" << problem.name << " - "
        << view.title << "</text>\n";
    const Eigen::Vector2d a = view.project(bounds.min), b = view.project(bounds.max);
    svg << "<rect x=\"" << std::min(a.x(), b.x()) << "\" y=\"" << std::min(a.y(), b.y())
        << "\" width=\"" << std::abs(b.x() - a.x()) << "\" height=\"" << std::abs(b.y() - a.y())
        << "\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
    draw(view, scene, 0.85, nullptr);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      std::vector<WorldTriangle> tris = objects[i];
      const bool endpoint = i == 0 || i + 1 == objects.size();
      const Color c =
          i == 0 ? Color{0.1, 0.7, 0.2, 1}
                 : (i + 1 == objects.size() ? Color{0.85, 0.1, 0.1, 1} : Color{0.95, 0.6, 0.1, 1});
      for (auto& t : tris)
        t.color = c;
      draw(view, tris, endpoint ? 0.6 : 0.25, "#333");
    }
    if (path.size() > 1) {
      svg << "<polyline fill=\"none\" stroke=\"#d02090\" stroke-width=\"2\" points=\"";
      for (const Config& q : path) {
        const Eigen::Vector2d s = view.project(q.t);
        svg << s.x() << ',' << s.y() << ' ';
      }
      svg << "\"/>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tandem
