#include "server/render_response.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace server {
namespace {

TEST(ServerTiming, ListsPassesThatRanThenTheTotals) {
  api::RenderStats stats;
  stats.passes = {{"shadow", true, true, "", {0.5, 0.5, 0.5}, {}},
                  {"rsm", false, false, "lpv disabled", {}, {}},
                  {"shade", true, true, "", {2.25, 2.0, 3.0}, {}},
                  {"propagate", true, false, "", {}, {}}};  // planned, not run (a dry run): no entry
  stats.gpu_ms = {2.75, 2.5, 3.5};
  stats.wall_ms = {3.0, 3.0, 3.0};
  EXPECT_EQ(server_timing_value(stats, 0.125, 1.0, 4.5),
            "shadow;dur=0.500;desc=\"pass\", shade;dur=2.250;desc=\"pass\", "
            "gpu;dur=2.750;desc=\"sum of passes\", wall;dur=3.000;desc=\"one frame\", "
            "queue;dur=0.125;desc=\"wait for a worker\", encode;dur=1.000;desc=\"image encoding\", "
            "total;dur=4.500;desc=\"arrival to response\"");
}

TEST(StatsHeader, SmallStatsGoWholeAndLargeOnesLoseTheLpvDetailFirst) {
  std::string omitted;
  const nlohmann::json small = {{"scene", "cornell-box"}, {"warnings", {"caf\xc3\xa9"}}};
  const std::string value = stats_header_value(small, omitted);
  EXPECT_EQ(value, R"({"scene":"cornell-box","warnings":["caf\u00e9"]})") << "headers must be ASCII";
  EXPECT_EQ(omitted, "");

  nlohmann::json large = {{"scene", "cornell-box"}};
  nlohmann::json flux = nlohmann::json::array();
  for (int i = 0; i < 1000; ++i) flux.push_back({0.123456, 0.123456, 0.123456});
  large["lpv"] = {{"vpl_count", 42}, {"cascades", {{{"cell_size", 0.1}, {"propagated_flux", flux}}}}};
  const auto shortened = nlohmann::json::parse(stats_header_value(large, omitted));
  EXPECT_EQ(omitted, "lpv.cascades[].propagated_flux");
  EXPECT_EQ(shortened["lpv"]["vpl_count"], 42);
  EXPECT_FALSE(shortened["lpv"]["cascades"][0].contains("propagated_flux"));
  EXPECT_LE(shortened.dump().size(), kMaxStatsHeaderBytes);
}

TEST(StatsHeader, ABudgetKeepsItsChoiceAndLosesItsCandidatesBeforeTheLpvStats) {
  nlohmann::json stats = {{"scene", "cornell-box"}, {"lpv", {{"vpl_count", 42}}}};
  const nlohmann::json candidate = {{"description", std::string(600, 'x')}, {"predicted_ms", 1.5}};
  stats["budget"] = {{"budget_ms", 50}, {"chosen", candidate}, {"candidates", std::vector<nlohmann::json>(13, candidate)}};
  std::string omitted;
  const auto shortened = nlohmann::json::parse(stats_header_value(stats, omitted));
  EXPECT_EQ(omitted, "budget.candidates");
  EXPECT_EQ(shortened["budget"]["chosen"], candidate);
  EXPECT_FALSE(shortened["budget"].contains("candidates"));
  EXPECT_EQ(shortened["lpv"]["vpl_count"], 42);

  stats["warnings"] = std::vector<std::string>(20, std::string(400, 'w'));  // too long even then
  const auto shortest = nlohmann::json::parse(stats_header_value(stats, omitted));
  EXPECT_EQ(omitted, "budget.candidates, lpv");
  EXPECT_FALSE(shortest.contains("lpv"));
}

}  // namespace
}  // namespace server
