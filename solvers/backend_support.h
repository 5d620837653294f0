// Which solver backend can minimise which energy term: decided here alone,
// from the terms' capability interfaces (energies/energy_term.h), for the
// config check and the backends alike.
//  - local_global: every term quadratic (QuadraticTerm); rotations only through
//    rotation terms (RotationTerm), which the local step fits.
//  - ceres, dpmu: any term (values and gradients; rotations fitted as above).
#pragma once

#include <string>

#include "energies/energy_terms.h"

namespace unfold {

/// Why `method` (local_global, ceres, dpmu) cannot minimise `term`, in one line
/// naming the term; empty if it can.
std::string why_backend_cannot_run(const std::string& method, const EnergyTerm& term);

/// The first such reason over all terms; empty if the method runs them all.
std::string why_backend_cannot_run(const std::string& method, const EnergyTerms& terms);

}  // namespace unfold
