#include "pipeline/cmbof_features.h"

#include "metrics/view_sphere.h"
#include "render/depth_image.h"

namespace unfold {

CmbofFeatures cmbof_features(const Eigen::MatrixX3d& normalised, const Eigen::MatrixX3i& F,
                             const CmbofOptions& options) {
  // Into the unit ball, as the views need.
  const Eigen::MatrixX3d V = normalised / normalised.rowwise().norm().maxCoeff();
  const Eigen::MatrixX3d directions = view_sphere_directions(options.view_subdivisions);
  std::vector<SiftDescriptors> per_view;
  CmbofFeatures features;
  features.view_start.push_back(0);
  for (Eigen::Index v = 0; v < directions.rows(); ++v) {
    per_view.push_back(
        sift_descriptors(depth_image(V, F, directions.row(v).transpose(), options.image_size),
                         options.features_per_view));
    features.view_start.push_back(features.view_start.back() + int(per_view.back().rows()));
  }
  features.descriptors.resize(features.view_start.back(), 128);
  for (size_t v = 0; v < per_view.size(); ++v)
    features.descriptors.middleRows(features.view_start[v], per_view[v].rows()) = per_view[v];
  return features;
}

void write_cmbof_features(std::ostream& s, const CmbofFeatures& features) {
  s << features.views() << ' ' << features.descriptors.rows() << '\n';
  for (int start : features.view_start) s << start << ' ';
  s << '\n';
  s.write(reinterpret_cast<const char*>(features.descriptors.data()),
          std::streamsize(features.descriptors.size()));
}

bool read_cmbof_features(std::istream& s, CmbofFeatures* features) {
  int views = -1;
  Eigen::Index rows = -1;
  if (!(s >> views >> rows) || views < 1 || views > 100000 || rows < 0 || rows > 100000000)
    return false;
  features->view_start.resize(size_t(views) + 1);
  for (int& start : features->view_start)
    if (!(s >> start)) return false;
  if (features->view_start.front() != 0 || features->view_start.back() != rows) return false;
  for (int v = 0; v < views; ++v)
    if (features->view_start[size_t(v)] > features->view_start[size_t(v) + 1]) return false;
  if (s.get() != ' ' || s.get() != '\n') return false;
  features->descriptors.resize(rows, 128);
  s.read(reinterpret_cast<char*>(features->descriptors.data()),
         std::streamsize(features->descriptors.size()));
  return s.gcount() == std::streamsize(features->descriptors.size());
}

}  // namespace unfold
