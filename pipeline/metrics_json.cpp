#include "pipeline/metrics_json.h"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "core/atomic_file.h"

namespace unfold {
namespace {

std::string quoted(const std::string& s) {
  std::ostringstream out;
  out << '"';
  for (char c : s) {
    if (c == '"' || c == '\\')
      out << '\\' << c;
    else if (static_cast<unsigned char>(c) < 0x20)
      out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
    else
      out << c;
  }
  out << '"';
  return out.str();
}

std::string number(double x) {
  if (!std::isfinite(x)) return "null";  // JSON has no NaN or Inf
  std::ostringstream out;
  out << std::setprecision(10) << x;
  return out.str();
}

std::string boolean(bool b) { return b ? "true" : "false"; }

}  // namespace

void write_metrics_json(const std::string& path, const UnfoldResult& r, const Options& options) {
  write_file_atomically(path, [&](std::ostream& out) {
    const UnfoldMetrics& m = r.metrics;
    const CascadeResult& c = r.cascade;
    out << "{\n"
        << "  \"E_rig\": " << number(m.E_rig) << ",\n"
        << "  \"E_str\": " << number(m.E_str) << ",\n"
        << "  \"E_str_exact\": " << boolean(m.E_str_exact) << ",\n"
        << "  \"E_geo\": " << number(m.E_geo) << ",\n"
        << "  \"E_geo_exact\": " << boolean(m.E_geo_exact) << ",\n"
        << "  \"edge_ratio\": " << number(c.edge_ratio) << ",\n"
        << "  \"inverted_tets\": " << m.inverted_tets << ",\n"
        << "  \"final_energy\": " << number(c.final_energy) << ",\n"
        << "  \"reached_band\": " << boolean(c.reached_band) << ",\n"
        << "  \"bounded\": " << boolean(c.bounded) << ",\n"
        << "  \"iterations\": " << c.iterations << ",\n"
        << "  \"cascades\": " << c.cascades << ",\n"
        << "  \"beta\": " << number(c.final_beta) << ",\n"
        << "  \"beta_start\": " << number(r.beta_start) << ",\n"
        << "  \"beta_requested\": " << number(r.beta_requested) << ",\n"
        << "  \"beta_raised\": " << boolean(r.beta_raised) << ",\n"
        << "  \"lambda2\": " << number(r.lambda2) << ",\n"
        << "  \"surface_vertices\": " << r.surface.V.rows() << ",\n"
        << "  \"surface_faces\": " << r.surface.faces.size() << ",\n"
        << "  \"tet_vertices\": " << r.tets.V.rows() << ",\n"
        << "  \"tets\": " << r.tets.T.rows() << ",\n"
        << "  \"edges\": " << r.num_edges << ",\n"
        << "  \"linear_solver\": {\"method\": " << quoted(r.linear_solver)
        << ", \"amg_levels\": " << r.amg_levels << ", \"cg_solves\": " << r.cg.solves
        << ", \"cg_iterations\": " << r.cg.iterations
        << ", \"cg_unconverged_solves\": " << r.cg.unconverged_solves
        << ", \"cg_worst_relative_residual\": " << number(r.cg.worst_relative_residual)
        << ", \"seconds_amg\": " << number(r.seconds_amg) << "},\n"
        << "  \"tetrahedralization\": {\"route\": " << quoted(r.tet_report.route)
        << ", \"tets\": " << r.tet_report.num_tets
        << ", \"interior_points\": " << r.tet_report.num_interior_points
        << ", \"removed_tets\": " << r.tet_report.num_removed_tets
        << ", \"rescued_tets\": " << r.tet_report.num_rescued_tets
        << ", \"intersecting_faces\": " << r.tet_report.num_intersecting_faces
        << ", \"fallback\": " << quoted(r.tet_report.fallback)
        << ", \"seconds\": " << number(r.tet_report.seconds) << "},\n"
        << "  \"seconds_tetrahedralize\": " << number(r.tet_report.seconds) << ",\n"
        << "  \"seconds_unfold\": " << number(r.seconds_unfold) << ",\n"
        << "  \"seconds_metrics\": " << number(m.seconds) << ",\n"
        << "  \"method\": " << quoted(options.method) << ",\n"
        << "  \"warnings\": [";
    for (size_t k = 0; k < r.warnings.size(); ++k) out << (k ? ", " : "") << quoted(r.warnings[k]);
    out << "],\n  \"history\": [\n";
    for (size_t k = 0; k < c.history.size(); ++k) {
      const IterationRecord& h = c.history[k];
      out << "    {\"iteration\": " << h.iteration << ", \"cascade\": " << h.cascade
          << ", \"beta\": " << number(h.beta) << ", \"energy\": " << number(h.energy)
          << ", \"edge_ratio\": " << number(h.edge_ratio) << "}"
          << (k + 1 < c.history.size() ? ",\n" : "\n");
    }
    out << "  ]\n}\n";
  });
}

}  // namespace unfold
