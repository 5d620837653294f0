// unfold_compare over a pairwise design of input class, config list, fixed
// beta and CSV output: exit 0 with a complete table, or the documented code,
// one error line and no CSV; never a signal.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "matrix_inputs.h"
#include "output_checks.h"
#include "pairwise_design.h"
#include "run_app.h"
#include "test_files.h"

namespace unfold {
// Named, not anonymous: the unity build compiles this file with
// cli_matrix_test.cpp, whose Factor and kLevels differ.
namespace compare_matrix {

enum Factor { kInput, kConfigs, kFixedBeta, kCsv };
const std::vector<int> kLevels = {test::kNumInputs, 3, 2, 2};
// Config lists (test::kMatrixConfigs indices): the paper's method with Ceres,
// the two baselines, all four.
const std::vector<std::vector<int>> kConfigLists = {{0, 1}, {2, 3}, {0, 1, 2, 3}};

TEST(CompareMatrix, EveryCombinationSucceedsCompletelyOrFailsCleanly) {
  const std::vector<test::DesignRow> design = test::pairwise_design(kLevels);
  EXPECT_TRUE(test::uncovered_pairs(kLevels, design).empty());
  int failures = 0;
  for (size_t k = 0; k < design.size(); ++k) {
    const test::DesignRow& row = design[k];
    const test::TempDir dir;
    std::string configs;
    for (int c : kConfigLists[size_t(row[kConfigs])])
      configs += (configs.empty() ? "" : ",") + test::quick_config(test::kMatrixConfigs[c]);
    const std::string csv = dir.file("table.csv");
    const std::string args = "--input " + test::matrix_input(row[kInput]) + " --configs " +
                             configs + (row[kFixedBeta] ? " --fixed_beta 1.5" : "") +
                             (row[kCsv] ? " --csv " + csv : "");
    const test::AppRun r = test::run_app("unfold_compare", args);
    std::printf("compare matrix %2zu: %-18s configs %d%s%s: exit %d\n", k + 1,
                test::input_name(row[kInput]), row[kConfigs], row[kFixedBeta] ? " fixed_beta" : "",
                row[kCsv] ? " csv" : "", r.exit_code);
    SCOPED_TRACE("unfold_compare " + args);
    ASSERT_NE(r.exit_code, -1) << "killed by a signal\n" << r.err;
    const int expected =
        row[kInput] == test::kTwoComponents || row[kInput] == test::kOpenSurface ? 3 : 0;
    ASSERT_EQ(r.exit_code, expected) << r.err;
    failures += expected != 0;
    if (expected != 0) {
      EXPECT_NE(r.err.find("unfold_compare: error: "), std::string::npos) << r.err;
      EXPECT_EQ(dir.count(), 0);
    } else if (row[kCsv]) {
      EXPECT_TRUE(test::IsCsv(csv, 1, int(kConfigLists[size_t(row[kConfigs])].size())));
    }
  }
  std::printf("compare matrix: %zu combinations, %d failed as documented\n", design.size(),
              failures);
}

}  // namespace compare_matrix
}  // namespace unfold
