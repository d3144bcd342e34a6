#include "tandem/render/svg_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tandem {
namespace {

constexpr double kMargin = 30.0;  ///< around and between the views, in pixels

/// Something to draw: a convex part (drawn as the outline of its projection) or one triangle of a
/// mesh.
struct Item {
  std::vector<Eigen::Vector3d> points;  ///< world frame
  Color color;
  bool convex;  ///< true: draw the convex hull of the projected points
};

void add_body(const Body& body, const Eigen::Isometry3d& X_WB, std::vector<Item>& out) {
  for (const Part& part : body.parts) {
    const TriangleMesh mesh = tessellate(part.geometry, 24);
    const Eigen::Isometry3d X = X_WB * part.pose;
    if (!std::holds_alternative<MeshShape>(part.geometry)) {
      Item item{{}, body.color, true};
      for (const auto& v : mesh.vertices)
        item.points.push_back(X * v);
      out.push_back(std::move(item));
      continue;
    }
    for (const auto& t : mesh.triangles) {
      out.push_back({{X * mesh.vertices[t[0]], X * mesh.vertices[t[1]], X * mesh.vertices[t[2]]},
                     body.color,
                     false});
    }
  }
}

/// Andrew's monotone chain.
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3)
    return p;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
      --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0)
      --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

std::string hex(const Color& c, double shade) {
  auto channel = [&](double v) {
    return static_cast<int>(std::clamp(v * shade, 0.0, 1.0) * 255.0 + 0.5);
  };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
  return buf;
}

/// One orthographic view: world axes (u, v) to the panel; the viewer looks along -depth_sign *
/// depth.
struct View {
  int u, v, depth;
  double depth_sign;
  const char* title;
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
  double scale = 1.0;
  double x0 = 0.0, y0 = 0.0;

  Eigen::Vector2d project(const Eigen::Vector3d& p) const {
    return {x0 + (p[u] - lo.x()) * scale, y0 + (hi.y() - p[v]) * scale};
  }
  /// Larger is nearer to the viewer.
  double nearness(const Item& item) const {
    double s = 0.0;
    for (const auto& p : item.points)
      s += p[depth];
    return depth_sign * s / static_cast<double>(item.points.size());
  }
};

/// Configurations evenly spaced along the path by length, start and goal included.
std::vector<Config> snapshots(const SE3Space& space, const Path& path, int between) {
  std::vector<Config> out{path.front()};
  const double total = path_length(space, path);
  double walked = 0.0;
  std::size_t seg = 0;
  for (int i = 1; i <= between && total > 0.0; ++i) {
    const double target = total * i / (between + 1);
    while (seg + 1 < path.size() && walked + space.distance(path[seg], path[seg + 1]) < target) {
      walked += space.distance(path[seg], path[seg + 1]);
      ++seg;
    }
    if (seg + 1 >= path.size())
      break;
    const double d = space.distance(path[seg], path[seg + 1]);
    out.push_back(space.interpolate(path[seg], path[seg + 1], d > 0 ? (target - walked) / d : 0.0));
  }
  out.push_back(path.back());
  return out;
}

std::vector<Item> obstacle_items(const Problem& problem, const SvgOptions& options) {
  std::vector<Item> obstacles;
  for (const Body& b : problem.scene.obstacles)
    add_body(b, Eigen::Isometry3d::Identity(), obstacles);
  if (obstacles.size() > options.max_triangles) {
    // Keep every k-th item: a large mesh stays recognisable and the file stays small.
    const std::size_t k = (obstacles.size() + options.max_triangles - 1) / options.max_triangles;
    std::vector<Item> thinned;
    for (std::size_t i = 0; i < obstacles.size(); i += k)
      thinned.push_back(obstacles[i]);
    obstacles.swap(thinned);
  }
  return obstacles;
}

/// The object at the start (green), along the path (orange) and at the goal (red).
std::vector<std::vector<Item>> object_items(const Problem& problem, const Path& path,
                                            const SvgOptions& options) {
  const std::vector<Config> poses =
      path.empty() ? std::vector<Config>{problem.start, problem.goal}
                   : snapshots(problem.space, path, std::max(0, options.object_snapshots));
  std::vector<std::vector<Item>> objects;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    Body body = problem.scene.object;
    body.color =
        i == 0 ? Color{0.1, 0.7, 0.2, 1}
               : (i + 1 == poses.size() ? Color{0.85, 0.1, 0.1, 1} : Color{0.95, 0.6, 0.1, 1});
    objects.emplace_back();
    add_body(body, poses[i].pose(), objects.back());
  }
  return objects;
}

/// The views, one under the other, fitted to the bounds, the obstacles and the object along the
/// path; returns the picture's height.
double layout_views(const Problem& problem, const std::vector<Item>& obstacles,
                    const std::vector<std::vector<Item>>& objects, double width,
                    std::vector<View>& views) {
  const Bounds& bounds = problem.space.bounds();
  Eigen::Vector3d lo = bounds.min, hi = bounds.max;
  auto extend = [&](const std::vector<Item>& items) {
    for (const auto& item : items) {
      for (const auto& p : item.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
  };
  extend(obstacles);
  for (const auto& o : objects)
    extend(o);
  views = {{0, 1, 2, 1.0, "top view (x right, y up)"}};
  if (!problem.space.planar())
    views.push_back({0, 2, 1, -1.0, "side view (x right, z up)"});
  double y = kMargin;
  for (View& view : views) {
    view.lo = {lo[view.u], lo[view.v]};
    view.hi = {hi[view.u], hi[view.v]};
    const Eigen::Vector2d size = (view.hi - view.lo).cwiseMax(1e-9);
    view.scale = width / size.x();
    view.x0 = kMargin;
    view.y0 = y + 20.0;
    y = view.y0 + size.y() * view.scale + kMargin;
  }
  return y;
}

/// Polygons far to near, shaded by their facing the light.
void draw_items(std::ostream& svg, const View& view, std::vector<Item> items, double opacity,
                double stroke_opacity) {
  const Eigen::Vector3d light = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  std::sort(items.begin(), items.end(),
            [&](const Item& a, const Item& b) { return view.nearness(a) < view.nearness(b); });
  for (const auto& item : items) {
    std::vector<Eigen::Vector2d> points;
    for (const auto& p : item.points)
      points.push_back(view.project(p));
    double shade = 1.0;
    if (item.convex) {
      points = convex_hull(points);
    } else {
      const Eigen::Vector3d n =
          (item.points[1] - item.points[0]).cross(item.points[2] - item.points[0]);
      if (n.norm() > 0)
        shade = 0.55 + 0.45 * std::abs(n.normalized().dot(light));
    }
    svg << "<polygon points=\"";
    for (const auto& s : points)
      svg << s.x() << ',' << s.y() << ' ';
    svg << "\" fill=\"" << hex(item.color, shade) << "\" fill-opacity=\"" << opacity << "\"";
    if (stroke_opacity > 0) {
      svg << " stroke=\"" << hex(item.color, 0.5) << "\" stroke-width=\"1\" stroke-opacity=\""
          << stroke_opacity << "\"";
    }
    svg << "/>\n";
  }
}

void draw_view(std::ostream& svg, const View& view, const Problem& problem, const Path& path,
               const std::vector<Item>& obstacles, const std::vector<std::vector<Item>>& objects) {
  const Bounds& bounds = problem.space.bounds();
  svg << "<text x=\"" << view.x0 << "\" y=\"" << view.y0 - 6 << "\">" << problem.name << " - "
      << view.title << "</text>\n";
  const Eigen::Vector2d a = view.project(bounds.min), b = view.project(bounds.max);
  svg << "<rect x=\"" << std::min(a.x(), b.x()) << "\" y=\"" << std::min(a.y(), b.y())
      << "\" width=\"" << std::abs(b.x() - a.x()) << "\" height=\"" << std::abs(b.y() - a.y())
      << "\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
  // Translucent obstacles with outlines, so that what is behind or inside them shows.
  draw_items(svg, view, obstacles, 0.3, 0.9);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const bool endpoint = i == 0 || i + 1 == objects.size();
    draw_items(svg, view, objects[i], endpoint ? 0.7 : 0.3, endpoint ? 0.9 : 0.5);
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

}  // namespace

std::string render_svg(const Problem& problem, const Path& path, const SvgOptions& options) {
  const std::vector<Item> obstacles = obstacle_items(problem, options);
  const std::vector<std::vector<Item>> objects = object_items(problem, path, options);
  const double width = options.panel_width;
  std::vector<View> views;
  const double height = layout_views(problem, obstacles, objects, width, views);
  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(1);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width + 2 * kMargin
      << "\" height=\"" << height << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
      << "<title>tandem: " << problem.name << "</title>\n";
  for (const View& view : views)
    draw_view(svg, view, problem, path, obstacles, objects);
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace tandem
