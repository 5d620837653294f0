// All outputs of a run committed together (core/output_transaction.h).
#include "core/output_transaction.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "test_files.h"

namespace unfold {
namespace {

using test::TempDir;

void write_text(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

TEST(OutputTransaction, FilesAppearOnlyOnCommitAndAllTogether) {
  const TempDir dir;
  OutputTransaction outputs;
  write_text(dir.file("a.txt"), "a");
  write_text(dir.file("b.txt"), "b");
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.txt")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("b.txt")));
  EXPECT_EQ(dir.count(), 2);  // the two temporaries
  outputs.commit();
  EXPECT_EQ(test::read_text(dir.file("a.txt")), "a");
  EXPECT_EQ(test::read_text(dir.file("b.txt")), "b");
  EXPECT_EQ(dir.count(), 2);
}

TEST(OutputTransaction, AFailureBeforeCommitLeavesNothingAndKeepsOldFiles) {
  const TempDir dir;
  write_text(dir.file("old.txt"), "old");
  try {
    OutputTransaction outputs;
    write_text(dir.file("old.txt"), "new");
    write_text(dir.file("a.txt"), "a");
    write_file_atomically(dir.file("b.txt"), [](std::ostream&) { throw InputError("late"); });
    outputs.commit();
    ADD_FAILURE() << "the writer's error did not propagate";
  } catch (const InputError&) {
  }
  EXPECT_EQ(dir.count(), 1);
  EXPECT_EQ(test::read_text(dir.file("old.txt")), "old");
  // Without a transaction open, writes are immediate again.
  write_text(dir.file("c.txt"), "c");
  EXPECT_EQ(test::read_text(dir.file("c.txt")), "c");
}

TEST(OutputTransaction, AFailedRenameTakesBackWhatTheCommitPutInPlace) {
  const TempDir dir;
  OutputTransaction outputs;
  write_text(dir.file("a.txt"), "a");
  outputs.stage(dir.file("vanished.tmp"), dir.file("b.txt"));  // a temporary that is gone
  write_text(dir.file("c.txt"), "c");
  EXPECT_THROW(outputs.commit(), OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.txt")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("b.txt")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("c.txt")));
  EXPECT_EQ(dir.count(), 1);  // c's temporary, until the transaction ends
}

TEST(OutputTransaction, NestedTransactionsCollectInTheInnermost) {
  const TempDir dir;
  OutputTransaction outer;
  {
    OutputTransaction inner;
    EXPECT_EQ(OutputTransaction::current(), &inner);
    write_text(dir.file("inner.txt"), "i");
    inner.commit();
  }
  EXPECT_EQ(OutputTransaction::current(), &outer);
  EXPECT_TRUE(std::filesystem::exists(dir.file("inner.txt")));
  write_text(dir.file("outer.txt"), "o");
  EXPECT_FALSE(std::filesystem::exists(dir.file("outer.txt")));
}

}  // namespace
}  // namespace unfold
