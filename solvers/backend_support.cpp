#include "solvers/backend_support.h"

#include "energies/concave_term.h"
#include "energies/quadratic_term.h"

namespace unfold {

std::string why_backend_cannot_run(const std::string& method, const EnergyTerm& term) {
  // A concave term joins the global step by its tangent (energies/concave_term.h).
  if (method == "local_global" && !dynamic_cast<const QuadraticTerm*>(&term) &&
      !dynamic_cast<const ConcaveTerm*>(&term))
    return "the " + term.name() +
           " term is neither quadratic nor concave: the local_global method cannot minimise it "
           "(use method: ceres or dpmu)";
  return "";
}

std::string why_backend_cannot_run(const std::string& method, const EnergyTerms& terms) {
  for (const auto& term : terms) {
    std::string why = why_backend_cannot_run(method, *term);
    if (!why.empty()) return why;
  }
  return "";
}

}  // namespace unfold
