#include "solvers/align_canonical_forms.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "core/errors.h"
#include "geometry/point_tree.h"
#include "mesh/lumped_masses.h"
#include "metrics/rigid_alignment.h"

namespace unfold {
namespace {

// Every `n / count`-th row (all rows when count >= n).
Eigen::MatrixX3d sample_rows(const Eigen::MatrixX3d& P, int count) {
  const Eigen::Index n = P.rows();
  if (count >= n) return P;
  Eigen::MatrixX3d S(count, 3);
  for (int k = 0; k < count; ++k) S.row(k) = P.row(Eigen::Index(double(k) * n / count));
  return S;
}

struct IcpResult {
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  double residual;
};

// ICP of S (already reflected if need be) onto T from (R, t), nearest points
// both ways (a target point's nearest in the moved source is its nearest in S
// moved back: the trees are built once); the residual of the last placement.
IcpResult icp(const Eigen::MatrixX3d& S, const PointTree& source_tree, const Eigen::MatrixX3d& T,
              const PointTree& target_tree, Eigen::Matrix3d R, Eigen::Vector3d t, int iterations) {
  IcpResult result{R, t, std::numeric_limits<double>::infinity()};
  const Eigen::Index ns = S.rows(), nt = T.rows();
  Eigen::MatrixX3d from(ns + nt, 3), to(ns + nt, 3);
  for (int it = 0; it <= iterations; ++it) {
    const Eigen::MatrixX3d Y = (S * R.transpose()).rowwise() + t.transpose();
    const Eigen::MatrixX3d T_back = (T.rowwise() - t.transpose()) * R;
    Eigen::VectorXd d_forward, d_backward;
    const Eigen::VectorXi forward = target_tree.nearest_rows(Y, &d_forward);
    const Eigen::VectorXi backward = source_tree.nearest_rows(T_back, &d_backward);
    const double residual = 0.5 * (d_forward.cwiseSqrt().mean() + d_backward.cwiseSqrt().mean());
    const double previous_best = result.residual;
    if (residual < result.residual) result = {R, t, residual};
    // Stop when an iteration no longer improves the placement noticeably.
    if (it == iterations || residual > (1 - 1e-4) * previous_best) break;
    for (Eigen::Index i = 0; i < ns; ++i) {
      from.row(i) = S.row(i);
      to.row(i) = T.row(forward(i));
    }
    for (Eigen::Index j = 0; j < nt; ++j) {
      from.row(ns + j) = S.row(backward(j));
      to.row(ns + j) = T.row(j);
    }
    const RigidAlignment step = align_rigidly(to, from);
    R = step.R;
    t = step.t;
  }
  return result;
}

// Principal axes (columns, by decreasing variance) of a centred point set.
Eigen::Matrix3d principal_axes(const Eigen::MatrixX3d& P, const Eigen::VectorXd& masses) {
  const Eigen::Matrix3d covariance = P.transpose() * masses.asDiagonal() * P;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  return eigen.eigenvectors().rowwise().reverse();
}

double triangle_area(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  double area = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    area += 0.5 * (V.row(F(f, 1)) - V.row(F(f, 0))).cross(V.row(F(f, 2)) - V.row(F(f, 0))).norm();
  return area;
}

}  // namespace

Eigen::MatrixX3d unit_area_form(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  const double area = triangle_area(V, F);
  if (!(area > 0) || !std::isfinite(area)) throw InputError("a canonical form has no area");
  const Eigen::VectorXd masses = lumped_masses(V, F);
  const Eigen::RowVector3d centroid = (masses.transpose() * V) / masses.sum();
  return (V.rowwise() - centroid) / std::sqrt(area);
}

FormAlignments align_canonical_forms(const Eigen::MatrixX3d& source_V,
                                     const Eigen::MatrixX3i& source_F,
                                     const Eigen::MatrixX3d& target_V,
                                     const Eigen::MatrixX3i& target_F,
                                     const FormAlignmentOptions& options,
                                     const Eigen::Matrix3d* rotation_seed) {
  if (options.coarse_points < 4 || options.points < 4 || options.coarse_iterations < 1 ||
      options.iterations < 1 || options.keep < 1 || !(options.keep_ratio >= 1))
    throw UsageError(
        "align_canonical_forms: coarse_points and points must be >= 4, the iterations and keep >= "
        "1, "
        "keep_ratio >= 1");
  FormAlignments result;
  result.source = unit_area_form(source_V, source_F);
  result.target = unit_area_form(target_V, target_F);
  const Eigen::MatrixX3d& S = result.source;
  const Eigen::MatrixX3d& T = result.target;
  const Eigen::Matrix3d Es = principal_axes(S, lumped_masses(source_V, source_F));
  const Eigen::Matrix3d Et = principal_axes(T, lumped_masses(target_V, target_F));
  // A fixed reflection: a mirrored placement is a rotation of S X^T.
  const Eigen::Matrix3d X = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  const Eigen::MatrixX3d S_coarse = sample_rows(S, options.coarse_points);
  const Eigen::MatrixX3d T_coarse = sample_rows(T, options.coarse_points);
  const Eigen::MatrixX3d S_coarse_mirrored = S_coarse * X;
  const PointTree coarse_tree(T_coarse), source_coarse_tree(S_coarse),
      source_coarse_mirrored_tree(S_coarse_mirrored);

  // Every signed permutation D: the source's axis k goes to the target's axis
  // perm[k] with sign s_k, linear = Et D Es^T.
  struct Candidate {
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    double residual;
    bool mirrored;
  };
  std::vector<Candidate> candidates;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 3; ++k) D(perm[k], k) = (signs >> k & 1) ? -1.0 : 1.0;
      const Eigen::Matrix3d linear = Et * D * Es.transpose();
      const bool mirrored = linear.determinant() < 0;
      const Eigen::Matrix3d R0 = mirrored ? Eigen::Matrix3d(linear * X) : linear;
      candidates.push_back({R0, Eigen::Vector3d::Zero(), 0, mirrored});
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
#pragma omp parallel for schedule(dynamic)
  for (size_t k = 0; k < candidates.size(); ++k) {
    Candidate& c = candidates[k];
    const IcpResult r = c.mirrored ? icp(S_coarse_mirrored, source_coarse_mirrored_tree, T_coarse,
                                         coarse_tree, c.R, c.t, options.coarse_iterations)
                                   : icp(S_coarse, source_coarse_tree, T_coarse, coarse_tree, c.R,
                                         c.t, options.coarse_iterations);
    c.R = r.R;
    c.t = r.t;
    c.residual = r.residual;
  }

  // The kept candidates are refined on `points` samples of each form.
  const Eigen::MatrixX3d S_fine = sample_rows(S, options.points);
  const Eigen::MatrixX3d T_fine = sample_rows(T, options.points);
  const Eigen::MatrixX3d S_fine_mirrored = S_fine * X;
  const PointTree tree(T_fine), source_tree(S_fine), source_mirrored_tree(S_fine_mirrored);
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.residual < b.residual; });
  // Placements refined from coarse ones, in parallel.
  const auto refine = [&](const std::vector<Candidate>& starts) {
    std::vector<FormAlignment> refined(starts.size());
#pragma omp parallel for schedule(dynamic)
    for (size_t k = 0; k < starts.size(); ++k) {
      const Candidate& c = starts[k];
      const IcpResult r =
          c.mirrored ? icp(S_fine_mirrored, source_mirrored_tree, T_fine, tree, c.R, c.t,
                           options.iterations)
                     : icp(S_fine, source_tree, T_fine, tree, c.R, c.t, options.iterations);
      FormAlignment& out = refined[k];
      out.linear = c.mirrored ? Eigen::Matrix3d(r.R * X) : r.R;
      out.translation = r.t;
      out.residual = r.residual;
      out.mirrored = c.mirrored;
      out.moved = (S * out.linear.transpose()).rowwise() + out.translation.transpose();
    }
    return refined;
  };
  // Two starts that ICP took to one placement count once.
  const auto is_new = [&](const FormAlignment& a) {
    for (const FormAlignment& b : result.candidates)
      if ((a.linear - b.linear).norm() <= 0.2 && (a.translation - b.translation).norm() <= 0.05)
        return false;
    return true;
  };
  std::vector<Candidate> kept;  // of each orientation, the rotations first
  size_t rotations = 0;
  for (const bool mirrored : {false, true}) {
    const size_t first = kept.size();
    for (const Candidate& c : candidates) {
      if (c.mirrored != mirrored || kept.size() - first >= size_t(options.keep)) continue;
      if (kept.size() > first && c.residual > options.keep_ratio * kept[first].residual) break;
      bool distinct = true;
      for (size_t k = first; k < kept.size(); ++k)
        distinct = distinct && ((kept[k].R - c.R).norm() > 0.2 || (kept[k].t - c.t).norm() > 0.05);
      if (distinct) kept.push_back(c);
    }
    if (!mirrored) rotations = kept.size();
  }
  std::vector<FormAlignment> refined = refine(kept);
  for (size_t k = 0; k < rotations; ++k) result.candidates.push_back(std::move(refined[k]));
  if (options.turns) {
    const FormAlignment& best = result.candidates.front();
    std::vector<Candidate> turns;
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d e = Et.col(axis);
      const Eigen::Matrix3d half_turn = 2 * e * e.transpose() - Eigen::Matrix3d::Identity();
      turns.push_back({half_turn * best.linear, half_turn * best.translation, 0, false});
    }
    for (FormAlignment& turned : refine(turns))
      if (is_new(turned)) result.candidates.push_back(std::move(turned));
    std::stable_sort(
        result.candidates.begin(), result.candidates.end(),
        [](const FormAlignment& a, const FormAlignment& b) { return a.residual < b.residual; });
  }
  for (size_t k = rotations; k < refined.size(); ++k)
    result.candidates.push_back(std::move(refined[k]));
  if (rotation_seed) add_seeded_alignment(*rotation_seed, options, &result);
  return result;
}

void add_seeded_alignment(const Eigen::Matrix3d& rotation_seed, const FormAlignmentOptions& options,
                          FormAlignments* aligned) {
  if (options.iterations < 1) throw UsageError("add_seeded_alignment: iterations must be >= 1");
  if (aligned->source.rows() == 0 || aligned->target.rows() == 0)
    throw UsageError("add_seeded_alignment: the alignments hold no forms");
  const Eigen::MatrixX3d& S = aligned->source;
  const Eigen::MatrixX3d S_fine = sample_rows(S, options.points);
  const Eigen::MatrixX3d T_fine = sample_rows(aligned->target, options.points);
  const IcpResult r = icp(S_fine, PointTree(S_fine), T_fine, PointTree(T_fine), rotation_seed,
                          Eigen::Vector3d::Zero(), options.iterations);
  FormAlignment out;
  out.linear = r.R;
  out.translation = r.t;
  out.residual = r.residual;
  out.seeded = true;
  out.moved = (S * out.linear.transpose()).rowwise() + out.translation.transpose();
  aligned->candidates.push_back(std::move(out));
}

}  // namespace unfold
