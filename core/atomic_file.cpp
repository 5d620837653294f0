#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/errors.h"
#include "core/output_transaction.h"

namespace unfold {
namespace {

std::string system_reason() { return std::strerror(errno); }

// Creates a fresh, uniquely named file next to `path` (O_EXCL so that two
// concurrent writers never share one) and returns its name.
std::string create_temp_file(const std::string& path) {
  for (int attempt = 0;; ++attempt) {
    const std::string name =
        path + ".tmp" + std::to_string(getpid()) + "_" + std::to_string(attempt);
    // 0666 lets the umask decide permissions, as for any ordinary output file.
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      return name;
    }
    if (errno != EEXIST || attempt >= 100)
      throw OutputError("cannot write '" + path + "': " + system_reason());
  }
}

}  // namespace

void check_writable_destination(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "."
                          : slash == 0               ? "/"
                                                     : path.substr(0, slash);
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw OutputError("cannot write '" + path + "': directory '" + dir + "': " + system_reason());
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  const std::string temp = create_temp_file(path);
  try {
    std::ofstream out(temp, binary ? std::ios::out | std::ios::binary : std::ios::out);
    if (!out) throw OutputError("cannot write '" + path + "': cannot open " + temp);
    write(out);
    out.close();
    if (out.fail()) throw OutputError("cannot write '" + path + "': stream error (disk full?)");
    if (OutputTransaction* transaction = OutputTransaction::current())
      return transaction->stage(temp, path);
    if (std::rename(temp.c_str(), path.c_str()) != 0)
      throw OutputError("cannot write '" + path + "': rename failed: " + system_reason());
  } catch (const Error&) {
    std::remove(temp.c_str());
    throw;
  } catch (const std::exception& e) {
    std::remove(temp.c_str());
    throw OutputError("cannot write '" + path + "': " + e.what());
  } catch (...) {
    std::remove(temp.c_str());
    throw OutputError("cannot write '" + path + "': unknown exception while writing");
  }
}

}  // namespace unfold
