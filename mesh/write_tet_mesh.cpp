#include "mesh/write_tet_mesh.h"

#include <iomanip>
#include <ostream>

#include "core/atomic_file.h"
#include "core/ends_with.h"
#include "core/errors.h"

namespace unfold {
namespace {

void write_fields(std::ostream& out, const char* tag,
                  const std::vector<std::pair<std::string, Eigen::VectorXd>>& fields,
                  const std::vector<std::pair<std::string, Eigen::MatrixX3d>>& vectors = {}) {
  if (fields.empty() && vectors.empty()) return;
  out << '<' << tag;
  if (!fields.empty()) out << " Scalars=\"" << fields.front().first << '"';
  if (!vectors.empty()) out << " Vectors=\"" << vectors.front().first << '"';
  out << ">\n";
  for (const auto& [name, values] : fields) {
    out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (Eigen::Index i = 0; i < values.size(); ++i) out << values[i] << '\n';
    out << "</DataArray>\n";
  }
  for (const auto& [name, X] : vectors) {
    out << "<DataArray type=\"Float64\" Name=\"" << name
        << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (Eigen::Index i = 0; i < X.rows(); ++i)
      out << X(i, 0) << ' ' << X(i, 1) << ' ' << X(i, 2) << '\n';
    out << "</DataArray>\n";
  }
  out << "</" << tag << ">\n";
}

void write_vtu(std::ostream& out, const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T,
               const TetMeshFields& fields) {
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << V.rows() << "\" NumberOfCells=\""
      << T.rows() << "\">\n";
  write_fields(out, "PointData", fields.per_vertex, fields.per_vertex_vectors);
  write_fields(out, "CellData", fields.per_tet);
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
      << "format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    out << V(i, 0) << ' ' << V(i, 1) << ' ' << V(i, 2) << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    out << T(t, 0) << ' ' << T(t, 1) << ' ' << T(t, 2) << ' ' << T(t, 3) << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (Eigen::Index t = 0; t < T.rows(); ++t) out << 4 * (t + 1) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (Eigen::Index t = 0; t < T.rows(); ++t) out << "10\n";  // VTK_TETRA
  out << "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void check_tet_mesh_format(const std::string& path) {
  if (!path.empty() && !ends_with(path, ".vtu") && !ends_with(path, ".node"))
    throw OutputError("unsupported tet mesh format '" + path + "' (use .vtu or .node)");
}

void write_tet_mesh(const std::string& path, const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& T,
                    const TetMeshFields& fields) {
  check_tet_mesh_format(path);
  for (const auto& [name, values] : fields.per_vertex)
    if (values.size() != V.rows())
      throw UsageError("write_tet_mesh: vertex field '" + name + "' has " +
                       std::to_string(values.size()) + " values for " + std::to_string(V.rows()) +
                       " vertices");
  for (const auto& [name, values] : fields.per_tet)
    if (values.size() != T.rows())
      throw UsageError("write_tet_mesh: tet field '" + name + "' has " +
                       std::to_string(values.size()) + " values for " + std::to_string(T.rows()) +
                       " tets");
  for (const auto& [name, X] : fields.per_vertex_vectors)
    if (X.rows() != V.rows())
      throw UsageError("write_tet_mesh: vertex vector field '" + name + "' has " +
                       std::to_string(X.rows()) + " rows for " + std::to_string(V.rows()) +
                       " vertices");
  if (ends_with(path, ".vtu")) {
    write_file_atomically(path, [&](std::ostream& out) { write_vtu(out, V, T, fields); });
    return;
  }
  // TetGen's own format, 0-based as TetGen's -z writes it.
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17) << V.rows() << " 3 0 0\n";
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      out << i << ' ' << V(i, 0) << ' ' << V(i, 1) << ' ' << V(i, 2) << '\n';
  });
  const std::string ele = path.substr(0, path.size() - 5) + ".ele";
  write_file_atomically(ele, [&](std::ostream& out) {
    out << T.rows() << " 4 0\n";
    for (Eigen::Index t = 0; t < T.rows(); ++t)
      out << t << ' ' << T(t, 0) << ' ' << T(t, 1) << ' ' << T(t, 2) << ' ' << T(t, 3) << '\n';
  });
}

}  // namespace unfold
