// All outputs of one run committed together: a run either leaves every file it
// was asked for, complete, or none of them.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace unfold {

/// While one is open on this thread, write_file_atomically keeps each finished
/// file under its temporary name and hands it here; commit() renames them all
/// into place. Destroyed without a commit (an exception on the way), it
/// removes the temporaries. Transactions may nest; the innermost one collects.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// The innermost transaction open on this thread, or nullptr.
  static OutputTransaction* current();

  /// Takes over `temp`, a finished file to be renamed to `path` on commit().
  void stage(const std::string& temp, const std::string& path);

  /// Renames every staged file into place, in staging order.
  /// @throws OutputError naming the file if a rename fails; the files already
  ///         renamed by this commit and the remaining temporaries are removed
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  ///< (temporary, destination)
  OutputTransaction* enclosing_;
};

}  // namespace unfold
