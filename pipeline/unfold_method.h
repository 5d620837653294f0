// A method is an ordered list of stages (pipeline/run_stages.h, the steps of
// pipeline/unfold_steps.h): the preparation's (prepare_mesh), then the
// unfolding's (unfold_prepared); unfold_surface runs them all. The config
// picks the list (choose_method).
#pragma once

#include <string>
#include <vector>

#include "config/options.h"
#include "pipeline/run_stages.h"

namespace unfold {

struct Method {
  std::string name;
  StageList stages;
};

/// The default: the surface solve's shape tetrahedralized, the rotation field
/// integrated on those tets (pipeline/method_default.cpp).
Method default_method(const Options& options);
/// The paper's: the cascade on the input's tets; also dpmu's and ceres'
/// (pipeline/method_paper.cpp).
Method paper_method(const Options& options);
/// domain surface on the input's tets (pipeline/method_surface.cpp).
Method surface_method(const Options& options);
/// tetrahedralize.shape contact: the default's tets where parts are in
/// contact, else the input's (pipeline/method_contact.cpp).
Method contact_method(const Options& options);
/// The baselines without a cascade (pipeline/method_baselines.cpp).
Method lsmds_method(const Options& options);
Method scf_method(const Options& options);

/// The method of validated options: by method, domain and tetrahedralize.shape.
Method choose_method(const Options& options);

/// The stages of the preparation (StagePart::prepare) or the rest.
StageList preparation(const StageList& stages);
StageList unfolding(const StageList& stages);

/// The stages' names, in order (whether their conditions would hold or not).
std::vector<std::string> stage_names(const StageList& stages);

/// Appends `more` to `stages`.
void append(StageList* stages, const StageList& more);

}  // namespace unfold
