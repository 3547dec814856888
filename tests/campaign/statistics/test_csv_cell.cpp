#include "frictionlab/campaign/csv_cell.hpp"

#include <gtest/gtest.h>

namespace frictionlab {
namespace {

TEST(CsvCell, ATextCellNeedsNoQuotingRules) {
    EXPECT_EQ(csv_cell("plain text"), "plain text");
    EXPECT_EQ(csv_cell("run failed: block 3, step 12, value \"nan\"\nat t = 0.1"),
              "run failed: block 3; step 12; value 'nan' at t = 0.1");
}

}  // namespace
}  // namespace frictionlab
