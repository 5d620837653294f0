#include "core/output_transaction.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/errors.h"

namespace unfold {
namespace {

thread_local OutputTransaction* innermost = nullptr;

}  // namespace

OutputTransaction::OutputTransaction() : enclosing_(innermost) { innermost = this; }

OutputTransaction::~OutputTransaction() {
  for (const auto& [temp, path] : staged_) std::remove(temp.c_str());
  innermost = enclosing_;
}

OutputTransaction* OutputTransaction::current() { return innermost; }

void OutputTransaction::stage(const std::string& temp, const std::string& path) {
  staged_.emplace_back(temp, path);
}

void OutputTransaction::commit() {
  for (size_t k = 0; k < staged_.size(); ++k) {
    const auto& [temp, path] = staged_[k];
    if (std::rename(temp.c_str(), path.c_str()) == 0) continue;
    const std::string reason = std::strerror(errno);
    // All or nothing: what this commit already put in place goes too.
    for (size_t done = 0; done < k; ++done) std::remove(staged_[done].second.c_str());
    throw OutputError("cannot write '" + path + "': rename failed: " + reason);
  }
  staged_.clear();
}

}  // namespace unfold
