#pragma once
// The report of an experiment: Markdown tables and SVG plots that mirror the papers' tables and
// figures, with medians over the seeds and their 95% confidence intervals.
//
// A table has one row per configuration: the parameters that vary across the experiment, the
// success rate (Wilson interval), the medians of time, nodes, edges and collision checks
// (order-statistic intervals; a run that did not solve counts at the time limit, as OMPL's
// tables do), the share of nodes by source, and the paper's figures when the experiment quotes
// them. The plots put report.rows on the x axis, one series per combination of the other varying
// parameters, one plot per value of report.panels.

#include <filesystem>
#include <string>
#include <vector>

#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/experiments/statistics.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct ReportFiles {
  std::filesystem::path markdown;
  std::vector<std::filesystem::path> plots;
};

/// Writes OUT/report.md and OUT/<name>-*.svg. `command` is how the data were produced (quoted in
/// the report).
ReportFiles write_report(const Experiment& experiment, const Problem& problem,
                         const std::vector<RunRecord>& records,
                         const std::filesystem::path& out_dir, const std::string& command);

/// The Markdown text alone (for tests); plot_files are linked from it.
std::string format_report(const Experiment& experiment, const Problem& problem,
                          const std::vector<RunRecord>& records, const std::string& command,
                          const std::vector<std::string>& plot_files);

/// One series of a plot: its name and, per x position, the median and its interval.
struct PlotSeries {
  std::string name;
  std::vector<Interval> points;  ///< one per x label; has_interval false and value <= 0: no point
};

/// A line plot with categorical x labels, a logarithmic y axis and interval whiskers.
std::string svg_plot(const std::string& title, const std::string& x_title,
                     const std::string& y_title, const std::vector<std::string>& x_labels,
                     const std::vector<PlotSeries>& series);

}  // namespace tandem
