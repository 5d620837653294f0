// The solvers know the energy terms only through their capability interfaces
// (docs/method.md, "Pluggable energy terms"): no file under solvers/ includes a
// particular term's header. A method's particular problem is built in stages/,
// or given to the solvers as a term's capability.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "test_files.h"

namespace unfold {
namespace {

// The headers of energies/ that name no particular term: the interfaces, the
// residual evaluator and the set of terms a config makes.
const std::set<std::string> kGenericEnergyHeaders = {
    "energy_term.h",   "energy_terms.h", "quadratic_term.h",
    "rotation_term.h", "concave_term.h", "residual_sum.h",
};

TEST(Layering, SolversIncludeNoParticularTerm) {
  const std::regex include("#include \"energies/([^\"]+)\"");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(UNFOLD_SOURCE_DIR "/solvers")) {
    const std::string extension = entry.path().extension();
    if (extension != ".h" && extension != ".cpp") continue;
    ++files;
    const std::string text = test::read_text(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), include);
         it != std::sregex_iterator(); ++it)
      EXPECT_TRUE(kGenericEnergyHeaders.count((*it)[1]))
          << "solvers/" << entry.path().filename().string() << " includes energies/" << (*it)[1]
          << ": a particular term (build the problem in stages/, or give the "
          << "term a capability interface)";
  }
  EXPECT_GT(files, 10);  // the directory was read
}

}  // namespace
}  // namespace unfold
