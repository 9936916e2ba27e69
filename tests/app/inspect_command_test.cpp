// The inspector's table and JSON (app/inspect_command.h) on an inspection whose values include
// NaN and the infinities (tests/support/odd_inspection.h): both list the rows in
// renderer::ranks_before's order, largest first, NaN last, ties in record order, where the old
// comparators were not strict weak orders (undefined behaviour in std::sort).
#include <cstddef>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/inspect_command.h"
#include "tests/support/odd_inspection.h"

namespace {

TEST(InspectCommand, TableListsNanLastAndTiesInRecordOrder) {
  const std::vector<std::size_t> expected = levrt_test::odd_expected_order();
  const std::string table =
      app::inspection_table(levrt_test::odd_inspection(), static_cast<int>(expected.size()));
  // Each row ("tested" or "culled") names its light's position "(X, 0, 0)": X is its place in
  // the record.
  std::vector<std::size_t> listed;
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t open = line.find("point (");
    if (line.rfind("tested ", 0) != 0 && line.rfind("culled ", 0) != 0) continue;
    unsigned place = 0;
    ASSERT_NE(open, std::string::npos) << line;
    ASSERT_EQ(std::sscanf(line.c_str() + open, "point (%u, 0, 0)", &place), 1) << line;
    listed.push_back(place);
  }
  ASSERT_EQ(listed.size(), expected.size()) << table;
  for (std::size_t i = 0; i < listed.size(); ++i) EXPECT_EQ(listed[i], expected[i]) << table;
}

TEST(InspectCommand, JsonListsTheCulledNanLastAndTiesInRecordOrder) {
  const renderer::PixelInspection inspection = levrt_test::odd_inspection();
  const nlohmann::ordered_json json = app::inspection_json(inspection);
  const std::size_t first_culled = inspection.hits[0].record.shaded.size();
  std::vector<std::size_t> expected;
  for (const std::size_t place : levrt_test::odd_expected_order()) {
    if (place >= first_culled) expected.push_back(place);
  }
  const nlohmann::ordered_json& culled = json["hits"][0]["culled"];
  ASSERT_EQ(culled.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(culled[i]["position"][0].get<double>(), static_cast<double>(expected[i]));
  // Every shaded term is listed, the NaN ones too.
  EXPECT_EQ(json["hits"][0]["shaded"].size(), first_culled);
}

}  // namespace
