#include "tetra/run_tetgen.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

std::string tetgen_error_name(int code) {
  switch (code) {
    case 1:
      return "out of memory";
    case 2:
      return "internal error";
    case 3:
      return "the surface intersects itself";
    case 4:
      return "a feature is too small for the tolerance";
    case 5:
      return "two facets are too close to each other";
    case 10:
      return "duplicated input points";
    default:
      return "error code " + std::to_string(code);
  }
}

bool write_all(int fd, const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= size_t(n);
  }
  return true;
}

// The child: run TetGen, send [status, #points, #tets, points, tets], exit
// without running the parent's atexit handlers or destructors.
[[noreturn]] void child(int fd, const std::string& switches, tetgenio& in) {
  // glibc's report of TetGen's double free would reach the user's terminal.
  const int null_fd = ::open("/dev/null", O_WRONLY);
  if (null_fd >= 0) {
    ::dup2(null_fd, STDOUT_FILENO);
    ::dup2(null_fd, STDERR_FILENO);
  }
  // Nor should the parent's crash handlers (Python's faulthandler, in the
  // Python module) report TetGen's crash: it is the usual "no" (see below).
  for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
  int32_t status = 0;
  tetgenio out;
  try {
    tetgenbehavior behavior;
    std::string s = switches;
    if (!behavior.parse_commandline(s.data())) status = -1;
    if (status == 0) ::tetrahedralize(&behavior, &in, &out);
  } catch (int code) {
    status = code > 0 ? code : 2;
  } catch (...) {
    status = 2;
  }
  const int32_t counts[3] = {status, status ? 0 : out.numberofpoints,
                             status ? 0 : out.numberoftetrahedra};
  bool ok = write_all(fd, counts, sizeof counts);
  if (ok && status == 0) {
    ok = write_all(fd, out.pointlist, sizeof(REAL) * 3 * size_t(counts[1])) &&
         write_all(fd, out.tetrahedronlist, sizeof(int) * 4 * size_t(counts[2]));
  }
  ::_exit(ok ? 0 : 1);
}

}  // namespace

TetgenOutput run_tetgen(const std::string& switches, tetgenio& in, const std::string& what,
                        const std::function<bool()>& give_up) {
  static_assert(sizeof(REAL) == sizeof(double), "TetGen built with REAL = double");
  const std::string given_up = what + ": given up (its result would not be used)";
  if (give_up && give_up()) throw NumericalError(given_up);
  int fds[2];
  if (::pipe(fds) != 0) throw NumericalError(what + ": cannot create a pipe for TetGen");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw NumericalError(what + ": cannot start a process for TetGen");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], switches, in);
  }
  ::close(fds[1]);
  std::vector<char> data;
  char buffer[1 << 16];
  while (true) {
    if (give_up) {
      pollfd ready = {fds[0], POLLIN, 0};
      if (::poll(&ready, 1, 2) == 0) {
        if (!give_up()) continue;
        ::kill(pid, SIGKILL);
        ::close(fds[0]);
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        throw NumericalError(given_up);
      }
    }
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    data.insert(data.end(), buffer, buffer + n);
  }
  ::close(fds[0]);
  int wait_status = 0;
  while (::waitpid(pid, &wait_status, 0) < 0 && errno == EINTR) {
  }
  // TetGen's failures (self-intersections, tiny features, close facets) end in
  // the double free described in the header, so a signal is its usual "no".
  if (WIFSIGNALED(wait_status))
    throw NumericalError(what + ": TetGen gave up on this surface (it stopped with " +
                         strsignal(WTERMSIG(wait_status)) +
                         "; the usual cause is a self-intersecting surface)");

  int32_t counts[3] = {2, 0, 0};
  if (data.size() >= sizeof counts) std::memcpy(counts, data.data(), sizeof counts);
  if (counts[0] == -1) throw UsageError(what + ": bad TetGen switches '" + switches + "'");
  if (counts[0] != 0)
    throw NumericalError(what + ": TetGen failed: " + tetgen_error_name(counts[0]));
  const size_t point_bytes = sizeof(double) * 3 * size_t(counts[1]);
  const size_t tet_bytes = sizeof(int) * 4 * size_t(counts[2]);
  if (data.size() != sizeof counts + point_bytes + tet_bytes)
    throw NumericalError(what + ": TetGen's process ended before sending its result");
  // TetGen's arrays are row-major. They sit at 4-byte offsets in the message,
  // so they are copied out rather than read in place (doubles need 8).
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> points(counts[1], 3);
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> tets(counts[2], 4);
  std::memcpy(points.data(), data.data() + sizeof counts, point_bytes);
  std::memcpy(tets.data(), data.data() + sizeof counts + point_bytes, tet_bytes);
  TetgenOutput result;
  result.points = points;
  result.tets = tets;
  return result;
}

}  // namespace unfold
