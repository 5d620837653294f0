#include "solvers/quadratic_part.h"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "energies/quadratic_term.h"
#include "energies/rotation_term.h"
#include "solvers/sparse_ldlt.h"
#include "solvers/woodbury_update.h"

namespace unfold {
namespace {

// A_fixed and A_beta: the triplets are gathered once into one reserved buffer:
// at 10^5 vertices they are ~10^7, and growing such vectors by reallocation
// cost more than the assembly itself.
void assemble_matrices(const UnfoldProblem& problem, QuadraticPart* part) {
  const int n = problem.num_vertices();
  std::vector<Eigen::Triplet<double>> all;
  all.reserve(size_t(n) + 6 * size_t(problem.graph->num_edges()));
  std::vector<std::pair<size_t, bool>> term_ends;  // end of each term's triplets, scaled?
  for (const auto& term : problem.terms) {
    term->add_growth_hessian(term->weight(1.0), &all);
    term_ends.emplace_back(all.size(), term->scales_with_beta());
  }
  std::vector<Eigen::Triplet<double>> scaled_part(all.size());
  for (const bool scaled : {false, true}) {
    size_t k = 0;
    for (const auto& [end, term_scaled] : term_ends)
      for (; k < end; ++k)
        scaled_part[k] = Eigen::Triplet<double>(all[k].row(), all[k].col(),
                                                term_scaled == scaled ? all[k].value() : 0.0);
    Eigen::SparseMatrix<double>& A = scaled ? part->A_beta : part->A_fixed;
    A.resize(n, n);
    A.setFromTriplets(scaled_part.begin(), scaled_part.end());
  }
}

}  // namespace

QuadraticPart assemble_quadratic_part(const UnfoldProblem& problem) {
  QuadraticPart part;
  assemble_matrices(problem, &part);
  const int n = problem.num_vertices();
  part.B_fixed.setZero(n, 3);
  part.B_beta.setZero(n, 3);
  part.U_fixed.resize(n, 0);
  part.U_regions.resize(n, 0);
  const Rotations identity(size_t(n), Eigen::Matrix3d::Identity());  // unused: no R dependence
  for (const auto& term : problem.terms) {
    const auto* quadratic = dynamic_cast<const QuadraticTerm*>(term.get());
    if (!quadratic) continue;
    const Eigen::VectorXd u = quadratic->rank_one_hessian();
    if (u.size() > 0) {
      if (term->scales_with_beta())
        throw UsageError("term '" + term->name() +
                         "' scales with beta and has a rank-one Hessian part: not supported");
      part.U_fixed.conservativeResize(n, part.U_fixed.cols() + 1);
      part.U_fixed.rightCols<1>() = std::sqrt(term->weight(1.0)) * u;
    }
    const Eigen::MatrixXd U = quadratic->region_hessian();
    if (U.cols() > 0) {
      if (term->scales_with_beta())
        throw UsageError("term '" + term->name() +
                         "' scales with beta and has a low-rank Hessian part: not supported");
      for (Eigen::MatrixXd* all : {&part.U_regions, &part.U_fixed}) {
        all->conservativeResize(n, all->cols() + U.cols());
        all->rightCols(U.cols()) = std::sqrt(term->weight(1.0)) * U;
      }
    }
    if (dynamic_cast<const RotationTerm*>(term.get())) continue;
    const bool scaled = term->scales_with_beta();
    quadratic->add_linear(identity, term->weight(1.0), scaled ? &part.B_beta : &part.B_fixed);
    (scaled ? part.c_beta : part.c_fixed) += term->weight(1.0) * quadratic->constant(identity);
  }
  return part;
}

bool quadratic_part_bounded(const UnfoldProblem& problem, double beta) {
  const QuadraticPart part = assemble_quadratic_part(problem);
  const Eigen::SparseMatrix<double> A = part.A_fixed + beta * part.A_beta;
  SparseLdlt ldlt;
  ldlt.analyze(A);
  try {
    ldlt.factorize(A);
  } catch (const NumericalError& e) {
    std::ostringstream what;
    what << "factorizing the global matrix failed at beta = " << beta << ": " << e.what();
    throw NumericalError(what.str());
  }
  WoodburyUpdate regions;
  woodbury_precomputation(ldlt, part.U_regions, &regions);
  return ldlt.negative_pivots() - regions.negative_eigenvalues <= 1;
}

}  // namespace unfold
