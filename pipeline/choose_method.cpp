// choose_method, and what every method list uses (pipeline/unfold_method.h).
#include <algorithm>
#include <iterator>

#include "pipeline/unfold_method.h"

namespace unfold {

Method choose_method(const Options& options) {
  if (options.method == "lsmds") return lsmds_method(options);
  if (options.method == "scf") return scf_method(options);
  if (options.domain != "surface") return paper_method(options);
  if (tets_from_unfolded(options)) return default_method(options);
  if (tets_from_unfolded_on_contact(options)) return contact_method(options);
  return surface_method(options);
}

StageList preparation(const StageList& stages) {
  StageList out;
  std::copy_if(stages.begin(), stages.end(), std::back_inserter(out),
               [](const Stage& s) { return s.part == StagePart::prepare; });
  return out;
}

StageList unfolding(const StageList& stages) {
  StageList out;
  std::copy_if(stages.begin(), stages.end(), std::back_inserter(out),
               [](const Stage& s) { return s.part != StagePart::prepare; });
  return out;
}

std::vector<std::string> stage_names(const StageList& stages) {
  std::vector<std::string> names;
  for (const Stage& s : stages) names.push_back(s.name);
  return names;
}

void append(StageList* stages, const StageList& more) {
  stages->insert(stages->end(), more.begin(), more.end());
}

}  // namespace unfold
