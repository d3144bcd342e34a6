// Run records: one JSON line per run.

#include "tandem/runs/run_record.hpp"

#include <gtest/gtest.h>

namespace tandem {
namespace {

TEST(RunRecords, RoundTripThroughAJsonLineAndRejectATornOne) {
  RunRecord r;
  r.problem = "p";
  r.config = "interactive alpha=0.5";
  r.params = {{"mode", "interactive"}, {"alpha", "0.5"}};
  r.seed = 9;
  r.time_limit_s = 30;
  r.status = "solved";
  r.solved = r.path_valid = true;
  r.time_s = 1.25;
  r.nodes = 100;
  r.edges = 98;
  r.nodes_by_source = {2, 50, 48, 0};
  r.tree_digest = "00ff";
  r.threads = 4;
  const std::string line = format_record(r);
  const auto back = parse_record(line);
  ASSERT_TRUE(back);
  EXPECT_EQ(format_record(*back), line);
  EXPECT_EQ(back->key(), "interactive alpha=0.5 #9");
  EXPECT_FALSE(parse_record(line.substr(0, line.size() / 2)));
  EXPECT_FALSE(parse_record("{}"));
}

TEST(RunRecords, ARecordFromBeforeHumanTimeReadsAsVirtualTimeWithoutWaiting) {
  RunRecord r;
  r.clock = "wall";
  r.operator_wait_s = 2.5;
  const auto both = parse_record(format_record(r));
  ASSERT_TRUE(both);
  EXPECT_EQ(both->clock, "wall");
  EXPECT_EQ(both->operator_wait_s, 2.5);
  nlohmann::json j = record_json(r);
  j.erase("clock");
  j.erase("operator_wait_s");
  const auto back = parse_record(j.dump());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->clock, "virtual");
  EXPECT_EQ(back->operator_wait_s, 0.0);
}

TEST(RunRecords, ARecordFromBeforeThreadsReadsAsOneThread) {
  RunRecord r;
  r.threads = 3;
  nlohmann::json j = record_json(r);
  j.erase("threads");
  const auto back = parse_record(j.dump());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->threads, 1u);
}

}  // namespace
}  // namespace tandem
