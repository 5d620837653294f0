#include "mesh/write_polyline.h"

#include <iomanip>
#include <limits>
#include <ostream>

#include "core/atomic_file.h"
#include "core/ends_with.h"
#include "core/errors.h"

namespace unfold {
namespace {

void write_points(std::ostream& out, const Eigen::MatrixX3d& nodes) {
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (int i = 0; i < nodes.rows(); ++i)
    out << nodes(i, 0) << ' ' << nodes(i, 1) << ' ' << nodes(i, 2) << '\n';
}

}  // namespace

void check_polyline_format(const std::string& path) {
  if (!ends_with(path, ".vtk") && !ends_with(path, ".ply"))
    throw OutputError("cannot write '" + path + "': a skeleton is written as .vtk or .ply");
}

void write_polyline(const std::string& path, const Eigen::MatrixX3d& nodes,
                    const Eigen::MatrixX2i& edges) {
  check_polyline_format(path);
  if (edges.size() > 0 && (edges.minCoeff() < 0 || edges.maxCoeff() >= nodes.rows()))
    throw OutputError("cannot write '" + path + "': a segment names a missing node");
  const int n = int(nodes.rows()), m = int(edges.rows());
  write_file_atomically(path, [&](std::ostream& out) {
    if (ends_with(path, ".vtk")) {
      out << "# vtk DataFile Version 3.0\nunfold curve skeleton\nASCII\nDATASET POLYDATA\n"
          << "POINTS " << n << " double\n";
      write_points(out, nodes);
      out << "LINES " << m << ' ' << 3 * m << '\n';
      for (int e = 0; e < m; ++e) out << "2 " << edges(e, 0) << ' ' << edges(e, 1) << '\n';
    } else {
      out << "ply\nformat ascii 1.0\ncomment unfold curve skeleton\nelement vertex " << n
          << "\nproperty double x\nproperty double y\nproperty double z\nelement edge " << m
          << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
      write_points(out, nodes);
      for (int e = 0; e < m; ++e) out << edges(e, 0) << ' ' << edges(e, 1) << '\n';
    }
  });
}

}  // namespace unfold
