#include "tandem/experiments/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "tandem/core/text.hpp"

namespace tandem {
namespace {

std::string number(double v, int significant = 3) {
  if (!std::isfinite(v))
    return "—";
  char buf[48];
  if (std::fabs(v) >= 1000.0) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
  } else {
    std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  }
  return buf;
}

std::string with_interval(const Interval& i, bool integer) {
  auto f = [&](double v) { return integer ? number(std::round(v), 6) : number(v); };
  std::string s = f(i.value);
  if (i.has_interval)
    s += " (" + f(i.low) + "–" + f(i.high) + ")";
  return s;
}

std::string file_safe(const std::string& s) {
  std::string r;
  for (char c : s)
    r += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return r;
}

struct Summary {
  std::size_t runs = 0;
  std::size_t solved = 0;
  std::size_t valid = 0;
  Interval success, time, nodes, edges, checks;
  Interval waited;  ///< seconds a simulated person waited for the roadmap (human time)
  double share[kNodeSources] = {};  ///< mean share of nodes by source
  bool time_censored = false;       ///< the median run did not solve: the median is the limit
};

Summary summarise(const std::vector<const RunRecord*>& runs) {
  Summary s;
  s.runs = runs.size();
  std::vector<double> time, nodes, edges, checks, waited;
  for (const RunRecord* r : runs) {
    waited.push_back(r->operator_wait_s);
    s.solved += r->solved ? 1 : 0;
    s.valid += r->path_valid ? 1 : 0;
    // A run that did not solve counts at the time limit (OMPL's convention).
    time.push_back(r->solved ? r->time_s : std::max(r->time_s, r->time_limit_s));
    nodes.push_back(static_cast<double>(r->nodes));
    edges.push_back(static_cast<double>(r->edges));
    checks.push_back(static_cast<double>(r->collision_checks));
    for (std::size_t k = 0; k < kNodeSources; ++k) {
      s.share[k] += r->nodes == 0
                        ? 0.0
                        : static_cast<double>(r->nodes_by_source[k]) /
                              static_cast<double>(r->nodes) / static_cast<double>(runs.size());
    }
  }
  s.success = success_interval(s.solved, s.runs);
  s.time = median_interval(time);
  s.nodes = median_interval(nodes);
  s.edges = median_interval(edges);
  s.checks = median_interval(checks);
  s.waited = median_interval(waited);
  s.time_censored = 2 * s.solved < s.runs;
  return s;
}

/// What the report needs to know about the experiment's layout.
struct Layout {
  std::vector<std::string> varying;  ///< parameters whose value differs between configurations
  std::string rows;                  ///< x axis ("" if none)
  std::string panels;                ///< "" if none
};

Layout layout_of(const Experiment& x) {
  Layout l;
  std::set<std::string> names;
  for (const RunConfig& c : x.configs) {
    for (const auto& [k, v] : c.values)
      names.insert(k);
  }
  for (const std::string& n : names) {
    std::set<std::string> values;
    for (const RunConfig& c : x.configs)
      values.insert(c.value_text(n));
    if (values.size() > 1)
      l.varying.push_back(n);
  }
  // The mode first, as the papers' tables read; then rows, series, panels.
  std::stable_sort(
      l.varying.begin(), l.varying.end(),
      [](const std::string& a, const std::string& b) { return a == "mode" && b != "mode"; });
  l.rows = !x.report.rows.empty() ? x.report.rows : (l.varying.empty() ? "" : l.varying.front());
  if (!x.report.panels.empty() &&
      std::find(l.varying.begin(), l.varying.end(), x.report.panels) != l.varying.end()) {
    l.panels = x.report.panels;
  }
  return l;
}

/// A plot series' name: the values of the varying parameters other than the x axis and the panel
/// ("interactive-contact, experienced"); the table beside the plot names the parameters.
std::string series_key(const RunConfig& c, const Layout& l) {
  std::string s;
  for (const std::string& n : l.varying) {
    if (n == l.rows || n == l.panels)
      continue;
    s += (s.empty() ? "" : ", ") + (c.value_text(n).empty() ? "—" : c.value_text(n));
  }
  return s.empty() ? "tandem" : s;
}

/// Text as SVG character data.
std::string xml(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '<')
      r += "&lt;";
    else if (c == '>')
      r += "&gt;";
    else if (c == '&')
      r += "&amp;";
    else if (c == '"')
      r += "&quot;";
    else
      r += c;
  }
  return r;
}

template <typename T>
void add_unique(std::vector<T>& v, const T& x) {
  if (std::find(v.begin(), v.end(), x) == v.end())
    v.push_back(x);
}

/// The experiment's configurations grouped for the report: the panels, and in each panel the
/// configurations that have runs, with their summaries.
struct Grouped {
  Layout layout;
  std::vector<std::string> panels;
  std::map<std::string, std::vector<const RunRecord*>> by_config;

  Grouped(const Experiment& x, const std::vector<RunRecord>& records) : layout(layout_of(x)) {
    for (const RunRecord& r : records)
      by_config[r.config].push_back(&r);
    if (layout.panels.empty()) {
      panels.emplace_back();
    } else {
      for (const RunConfig& c : x.configs)
        add_unique(panels, c.value_text(layout.panels));
    }
  }

  std::vector<std::pair<const RunConfig*, Summary>> rows(const Experiment& x,
                                                         const std::string& panel) const {
    std::vector<std::pair<const RunConfig*, Summary>> out;
    for (const RunConfig& c : x.configs) {
      if (!layout.panels.empty() && c.value_text(layout.panels) != panel)
        continue;
      auto it = by_config.find(c.label());
      if (it != by_config.end())
        out.emplace_back(&c, summarise(it->second));
    }
    return out;
  }
};

/// A configuration's value of the x-axis parameter, as the plots label it.
std::string x_value(const RunConfig& c, const Layout& l) {
  if (l.rows.empty())
    return "all";
  const std::string v = c.value_text(l.rows);
  return v.empty() ? "—" : v;
}

/// Where a plot's parts go: the plot area within the picture, the y axis's decades (10^l0 to
/// 10^l1, logarithmic) and the x axis's evenly spaced labels.
struct PlotFrame {
  static constexpr double W = 780, H = 400, left = 70, right = 300, top = 40, bottom = 60;
  static constexpr double pw = W - left - right, ph = H - top - bottom;
  double l0 = 0.0, l1 = 1.0;
  std::size_t labels = 0;

  double y(double v) const {
    return top + ph * (1.0 - (std::log10(std::max(v, std::pow(10.0, l0))) - l0) / (l1 - l0));
  }
  double x(std::size_t i) const {
    return left +
           (labels <= 1 ? pw / 2 : pw * static_cast<double>(i) / static_cast<double>(labels - 1));
  }
};

/// The frame whose decades hold every positive value and interval of the series.
PlotFrame plot_frame(const std::vector<PlotSeries>& series, std::size_t labels) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series) {
    for (const auto& p : s.points) {
      if (p.value <= 0.0)
        continue;
      lo = std::min({lo, p.value, p.has_interval && p.low > 0 ? p.low : p.value});
      hi = std::max({hi, p.value, p.has_interval ? p.high : p.value});
    }
  }
  if (!std::isfinite(lo)) {
    lo = 1.0;
    hi = 10.0;
  }
  PlotFrame f;
  f.l0 = std::floor(std::log10(lo));
  f.l1 = std::ceil(std::log10(hi));
  if (f.l1 <= f.l0)
    f.l1 = f.l0 + 1;
  f.labels = labels;
  return f;
}

/// The picture's background, title, grid, axis labels and plot area.
void draw_axes(std::ostream& o, const PlotFrame& f, const std::string& title,
               const std::string& x_title, const std::string& y_title,
               const std::vector<std::string>& x_labels) {
  const double W = f.W, H = f.H, left = f.left, top = f.top, pw = f.pw, ph = f.ph;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>\n";
  o << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">" << xml(title)
    << "</text>\n";
  for (double e = f.l0; e <= f.l1 + 1e-9; e += 1.0) {
    const double v = std::pow(10.0, e);
    o << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << f.y(v) << "\" y2=\""
      << f.y(v) << "\" stroke=\"#ddd\"/>\n<text x=\"" << left - 6 << "\" y=\"" << f.y(v) + 4
      << "\" text-anchor=\"end\">" << number(v, 6) << "</text>\n";
  }
  for (std::size_t i = 0; i < x_labels.size(); ++i) {
    o << "<text x=\"" << f.x(i) << "\" y=\"" << top + ph + 18 << "\" text-anchor=\"middle\">"
      << xml(x_labels[i]) << "</text>\n";
  }
  o << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << H - 15 << "\" text-anchor=\"middle\">"
    << xml(x_title) << "</text>\n<text transform=\"translate(18 " << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << xml(y_title) << " (log scale)</text>\n";
}

/// Series number s of `count`: its points, whiskers, line and legend entry, nudged sideways so
/// that series at the same x stay apart.
void draw_series(std::ostream& o, const PlotFrame& f, const PlotSeries& series, std::size_t s,
                 std::size_t count) {
  static const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                   "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  const char* colour = kColours[s % std::size(kColours)];
  std::string poly;
  for (std::size_t i = 0; i < series.points.size() && i < f.labels; ++i) {
    const Interval& p = series.points[i];
    if (p.value <= 0.0)
      continue;
    const double dx = (static_cast<double>(s) - static_cast<double>(count - 1) / 2.0) * 4.0;
    if (p.has_interval) {
      o << "<line x1=\"" << f.x(i) + dx << "\" x2=\"" << f.x(i) + dx << "\" y1=\"" << f.y(p.low)
        << "\" y2=\"" << f.y(p.high) << "\" stroke=\"" << colour << "\"/>\n";
    }
    o << "<circle cx=\"" << f.x(i) + dx << "\" cy=\"" << f.y(p.value) << "\" r=\"3\" fill=\""
      << colour << "\"/>\n";
    std::ostringstream pt;
    pt.setf(std::ios::fixed);
    pt.precision(1);
    pt << f.x(i) + dx << ',' << f.y(p.value) << ' ';
    poly += pt.str();
  }
  const double legend_x = f.left + f.pw, row = 18.0 * static_cast<double>(s);
  o << "<polyline points=\"" << poly << "\" fill=\"none\" stroke=\"" << colour << "\"/>\n";
  o << "<rect x=\"" << legend_x + 12 << "\" y=\"" << f.top + row
    << "\" width=\"10\" height=\"10\" fill=\"" << colour << "\"/>\n<text x=\"" << legend_x + 26
    << "\" y=\"" << f.top + 9 + row << "\">" << xml(series.name) << "</text>\n";
}

/// The report's opening: what was run, how much, and how to read the tables.
void write_introduction(std::ostream& o, const Experiment& x, const Problem& problem,
                        const std::vector<RunRecord>& records, const std::string& command) {
  std::size_t solved = 0, valid = 0;
  std::set<std::uint64_t> seeds;
  for (const RunRecord& r : records) {
    solved += r.solved ? 1 : 0;
    valid += r.path_valid ? 1 : 0;
    seeds.insert(r.seed);
  }
  o << "# " << x.report.title << "\n\n";
  if (!x.description.empty())
    o << x.description << "\n\n";
  o << "Problem **" << problem.name << "** (" << problem.source << "); " << x.configs.size()
    << " configurations; " << records.size() << " runs";
  if (!seeds.empty())
    o << " (seeds " << *seeds.begin() << "–" << *seeds.rbegin() << ")";
  o << "; time limit " << number(x.time_limit) << " s per run. Produced by `" << command
    << "`.\n\n";
  if (x.clock == "wall") {
    o << "In human time: the operator is a simulated person with human limits (a 6D mouse as a "
         "rate device, a reaction delay, smooth steering) on its own thread, the planner on "
         "another, one run at a time; times are the person's wall-clock seconds. A planner "
         "alone had the same two cores. Person waited: seconds the person spent going back to "
         "the roadmap.\n\n";
  }
  o << "Medians over the seeds, with 95% confidence intervals in brackets (order statistics; "
       "none for fewer than 6 runs). A run that did not solve counts at the time limit, and a "
       "median time marked > is such a run. Solved: share of runs, with its 95% Wilson interval. "
       "Every solution was checked state by state and motion by motion (check-path): "
    << valid << " of " << solved << " valid.\n\n";
}

/// A table's heading and alignment lines.
void write_table_head(std::ostream& o, const Layout& l, bool quote_paper, bool human_time) {
  o << '|';
  for (const std::string& n : l.varying) {
    if (n != l.panels)
      o << ' ' << n << " |";
  }
  o << " solved | time s | nodes | edges | collision checks | nodes random / operator / contact "
       "|";
  if (human_time)
    o << " person waited s |";
  if (quote_paper)
    o << " paper |";
  o << "\n|";
  for (const std::string& n : l.varying) {
    if (n != l.panels)
      o << " --- |";
  }
  o << " ---: | ---: | ---: | ---: | ---: | ---: |" << (human_time ? " ---: |" : "")
    << (quote_paper ? " --- |" : "") << '\n';
}

/// A configuration's row of a table.
void write_table_row(std::ostream& o, const Experiment& x, const Layout& l, const RunConfig& c,
                     const Summary& s) {
  o << '|';
  for (const std::string& n : l.varying) {
    if (n != l.panels)
      o << ' ' << (c.value_text(n).empty() ? "—" : c.value_text(n)) << " |";
  }
  char share[64];
  std::snprintf(share, sizeof share, "%.0f%% / %.0f%% / %.0f%%",
                100 * s.share[static_cast<std::size_t>(NodeSource::random)],
                100 * s.share[static_cast<std::size_t>(NodeSource::operator_)],
                100 * s.share[static_cast<std::size_t>(NodeSource::contact)]);
  char solved_text[96];
  std::snprintf(solved_text, sizeof solved_text, "%zu/%zu (%.0f–%.0f%%)", s.solved, s.runs,
                100 * s.success.low, 100 * s.success.high);
  o << ' ' << solved_text << " | " << (s.time_censored ? "> " : "") << with_interval(s.time, false)
    << " | " << with_interval(s.nodes, true) << " | " << number(std::round(s.edges.value), 6)
    << " | " << number(std::round(s.checks.value), 6) << " | " << share << " |";
  if (x.clock == "wall")
    o << ' ' << with_interval(s.waited, false) << " |";
  if (!x.report.paper.empty()) {
    auto p = x.report.paper.find(l.rows.empty() ? "" : c.value_text(l.rows));
    o << ' ' << (p == x.report.paper.end() ? "" : p->second) << " |";
  }
  o << '\n';
}

}  // namespace

std::string svg_plot(const std::string& title, const std::string& x_title,
                     const std::string& y_title, const std::vector<std::string>& x_labels,
                     const std::vector<PlotSeries>& series) {
  const PlotFrame f = plot_frame(series, x_labels.size());
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(1);
  draw_axes(o, f, title, x_title, y_title, x_labels);
  for (std::size_t s = 0; s < series.size(); ++s)
    draw_series(o, f, series[s], s, series.size());
  o << "</svg>\n";
  return o.str();
}

std::string format_report(const Experiment& x, const Problem& problem,
                          const std::vector<RunRecord>& records, const std::string& command,
                          const std::vector<std::string>& plot_files) {
  const Grouped g(x, records);
  const Layout& l = g.layout;
  std::ostringstream o;
  write_introduction(o, x, problem, records, command);
  std::size_t plot = 0;
  for (const std::string& panel : g.panels) {
    if (!l.panels.empty())
      o << "## " << l.panels << " = " << panel << "\n\n";
    write_table_head(o, l, !x.report.paper.empty(), x.clock == "wall");
    for (const auto& [config, s] : g.rows(x, panel))
      write_table_row(o, x, l, *config, s);
    o << '\n';
    for (int k = 0; k < 2 && plot < plot_files.size(); ++k, ++plot)
      o << "![" << (k == 0 ? "time" : "nodes") << "](" << plot_files[plot] << ") ";
    o << "\n\n";
  }
  return o.str();
}

ReportFiles write_report(const Experiment& x, const Problem& problem,
                         const std::vector<RunRecord>& records,
                         const std::filesystem::path& out_dir, const std::string& command) {
  const Grouped g(x, records);
  const Layout& l = g.layout;
  ReportFiles files;
  std::vector<std::string> names;
  for (const std::string& panel : g.panels) {
    const auto rows = g.rows(x, panel);
    std::vector<std::string> xs, keys;
    for (const auto& [c, s] : rows) {
      add_unique(xs, x_value(*c, l));
      add_unique(keys, series_key(*c, l));
    }
    std::vector<PlotSeries> time(keys.size()), nodes(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
      time[k] = {keys[k], std::vector<Interval>(xs.size())};
      nodes[k] = {keys[k], std::vector<Interval>(xs.size())};
    }
    for (const auto& [c, s] : rows) {
      const auto xi =
          static_cast<std::size_t>(std::find(xs.begin(), xs.end(), x_value(*c, l)) - xs.begin());
      const auto ki = static_cast<std::size_t>(
          std::find(keys.begin(), keys.end(), series_key(*c, l)) - keys.begin());
      time[ki].points[xi] = s.time;
      nodes[ki].points[xi] = s.nodes;
    }
    const std::string suffix = l.panels.empty() ? "" : "-" + file_safe(l.panels + "=" + panel);
    const std::string heading =
        x.report.title + (l.panels.empty() ? "" : " (" + l.panels + " = " + panel + ")");
    const std::string x_title = l.rows.empty() ? "" : l.rows;
    for (int k = 0; k < 2; ++k) {
      const std::string name = file_safe(x.name) + suffix + (k == 0 ? "-time.svg" : "-nodes.svg");
      write_file_atomically(
          out_dir / name, svg_plot(heading, x_title, k == 0 ? "median time, s" : "median nodes", xs,
                                   k == 0 ? time : nodes));
      files.plots.push_back(out_dir / name);
      names.push_back(name);
    }
  }
  files.markdown = out_dir / "report.md";
  write_file_atomically(files.markdown, format_report(x, problem, records, command, names));
  return files;
}

}  // namespace tandem
