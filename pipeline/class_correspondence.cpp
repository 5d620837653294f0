#include "pipeline/class_correspondence.h"

#include <algorithm>
#include <filesystem>

#include "core/errors.h"
#include "mesh/read_vts.h"

namespace unfold {

const char* correspondence_name(CorrespondenceBasis basis) {
  switch (basis) {
    case CorrespondenceBasis::kVertexOrder:
      return "vertex_order";
    case CorrespondenceBasis::kVts:
      return "vts";
    case CorrespondenceBasis::kNone:
      break;
  }
  return "none";
}

ClassCorrespondence class_correspondence(const std::string& class_name,
                                         const std::vector<std::string>& mesh_paths,
                                         const std::vector<int>& vertex_counts) {
  ClassCorrespondence c;
  const std::string where = "class " + class_name + ": ";
  std::error_code ec;
  const auto without_vts = std::find_if(mesh_paths.begin(), mesh_paths.end(), [&](auto& path) {
    return !std::filesystem::exists(vts_path(path), ec);
  });
  if (!mesh_paths.empty() && without_vts == mesh_paths.end()) {
    try {
      for (size_t i = 0; i < mesh_paths.size(); ++i)
        c.rows.push_back(read_vts(vts_path(mesh_paths[i]), vertex_counts[i],
                                  c.rows.empty() ? -1 : int(c.rows.front().size())));
      c.basis = CorrespondenceBasis::kVts;
    } catch (const InputError& e) {
      c.rows.clear();
      c.problem = where + e.what() + "; no pose distance for this class";
    }
    return c;
  }
  const auto [low, high] = std::minmax_element(vertex_counts.begin(), vertex_counts.end());
  if (low == vertex_counts.end() || *low == *high) {
    c.basis = CorrespondenceBasis::kVertexOrder;
    return c;
  }
  c.problem = where + "the meshes differ in vertex count (" + std::to_string(*low) + " to " +
              std::to_string(*high) + ") and " + vts_path(*without_vts) +
              " is missing (one-based vertex ids, one per common point); no pose distance for "
              "this class";
  return c;
}

}  // namespace unfold
