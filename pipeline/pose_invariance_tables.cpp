#include "pipeline/pose_invariance_tables.h"

#include <glog/logging.h>

#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "metrics/pose_invariance.h"
#include "pipeline/class_correspondence.h"
#include "pipeline/pose_pictures.h"
#include "render/write_png.h"

namespace unfold {

void write_pose_invariance_tables(const std::string& output_dir,
                                  const std::vector<std::string>& labels,
                                  const std::vector<PoseShape>& shapes) {
  std::map<std::string, std::vector<size_t>> members;  // class -> shapes, in input order
  for (size_t i = 0; i < shapes.size(); ++i) {
    if (shapes[i].forms.size() != labels.size() || labels.empty() || !shapes[i].forms.front())
      throw UsageError("write_pose_invariance_tables: shape " + shapes[i].name +
                       " needs its raw form and one entry per label");
    members[shapes[i].shape_class].push_back(i);
  }
  std::ostringstream pose, pairs;
  pose << "class,method,pose_distance,mean_ratio,max_ratio,pairs,correspondence\n";
  pairs << "class,method,shape_a,shape_b,raw_distance,pose_distance,ratio,correspondence\n";
  for (const auto& [c, class_shapes] : members) {
    if (class_shapes.size() < 2) continue;
    std::vector<std::string> paths;
    std::vector<int> counts;
    for (size_t i : class_shapes) {
      paths.push_back(shapes[i].mesh_path);
      counts.push_back(int(shapes[i].forms.front()->rows()));
    }
    const ClassCorrespondence correspondence = class_correspondence(c, paths, counts);
    const std::string basis = correspondence_name(correspondence.basis);
    if (correspondence.basis == CorrespondenceBasis::kNone) {
      LOG(WARNING) << "pose invariance: " << correspondence.problem;
      for (const auto& label : labels) pose << c << ',' << label << ",,,,0," << basis << '\n';
      continue;
    }
    // Row k of a pose's compared points: its vertex rows[k] (.vts) or k (vertex order).
    auto distance = [&](size_t a, size_t b, const Eigen::MatrixX3d& A, const Eigen::MatrixX3d& B) {
      const PoseShape &sa = shapes[class_shapes[a]], &sb = shapes[class_shapes[b]];
      if (correspondence.basis == CorrespondenceBasis::kVertexOrder)
        return pose_distance(A, B, sa.F);
      return pose_distance(A, sa.F, correspondence.rows[a], B, sb.F, correspondence.rows[b]);
    };
    for (size_t m = 0; m < labels.size(); ++m) {
      double sum = 0, ratio_sum = 0, ratio_max = 0;
      int count = 0;
      for (size_t a = 0; a < class_shapes.size(); ++a)
        for (size_t b = a + 1; b < class_shapes.size(); ++b) {
          const PoseShape &sa = shapes[class_shapes[a]], &sb = shapes[class_shapes[b]];
          if (!sa.forms[m] || !sb.forms[m]) continue;
          const double raw = distance(a, b, *sa.forms.front(), *sb.forms.front());
          const double d = distance(a, b, *sa.forms[m], *sb.forms[m]);
          const double ratio = raw > 0 ? d / raw : 1.0;
          pairs << c << ',' << labels[m] << ',' << sa.name << ',' << sb.name << ',' << raw << ','
                << d << ',' << ratio << ',' << basis << '\n';
          sum += d, ratio_sum += ratio, ratio_max = std::max(ratio_max, ratio);
          ++count;
        }
      if (count == 0) continue;
      pose << c << ',' << labels[m] << ',' << sum / count << ',' << ratio_sum / count << ','
           << ratio_max << ',' << count << ',' << basis << '\n';
      std::vector<PosePanel> panels;
      for (size_t a = 0; a < class_shapes.size(); ++a) {
        const PoseShape& s = shapes[class_shapes[a]];
        if (s.forms[m])
          panels.push_back({s.name, *s.forms[m], s.F,
                            correspondence.basis == CorrespondenceBasis::kVts
                                ? correspondence.rows[a]
                                : Eigen::VectorXi()});
      }
      write_png(output_dir + "/poses_" + c + "_" + labels[m] + ".png",
                render_poses(panels, labels[m]));
    }
  }
  write_file_atomically(output_dir + "/pose_invariance.csv",
                        [&](std::ostream& s) { s << pose.str(); });
  write_file_atomically(output_dir + "/pose_pairs.csv", [&](std::ostream& s) { s << pairs.str(); });
}

}  // namespace unfold
