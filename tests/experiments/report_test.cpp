// The report: a table per experiment, censored medians marked, plots as SVG.

#include "tandem/experiments/report.hpp"

#include <gtest/gtest.h>

#include "support/runs.hpp"

namespace tandem {
namespace {

using Fixture = test::ExperimentFixture;

TEST(Report, TablesHaveARowPerConfigurationAndMarkCensoredMedians) {
  Fixture f;
  std::vector<RunRecord> records;
  for (int i = 0; i < 3; ++i) {
    RunRecord r;
    r.config = "birrt";
    r.params = {{"mode", "birrt"}};
    r.seed = static_cast<std::uint64_t>(i + 1);
    r.time_limit_s = 30;
    r.status = "timeout";
    r.time_s = 30.001;
    r.nodes = 1000;
    records.push_back(r);
    r.config = "interactive-contact";
    r.params = {{"mode", "interactive-contact"}};
    r.status = "solved";
    r.solved = r.path_valid = true;
    r.time_s = 0.5 * (i + 1);
    r.nodes = 10;
    records.push_back(r);
  }
  f.experiment.report.paper = {{"birrt", "2h45m"}};
  const std::string md =
      format_report(f.experiment, f.problem, records, "tandem bench gap.toml", {"a.svg", "b.svg"});
  EXPECT_NE(md.find("| birrt | 0/3 (0–56%) | > 30 | 1000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| interactive-contact | 3/3 (44–100%) | 1 | 10 |"), std::string::npos) << md;
  EXPECT_NE(md.find("2h45m"), std::string::npos);
  EXPECT_NE(md.find("3 of 3 valid"), std::string::npos);
  EXPECT_NE(md.find("![time](a.svg)"), std::string::npos);

  const std::string svg = svg_plot("a <b> & c", "x", "y", {"1", "2"},
                                   {PlotSeries{"s", {Interval{1, 0.5, 2, true}, Interval{}}}});
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
}

}  // namespace
}  // namespace tandem
