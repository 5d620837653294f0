#include "solvers/synchronize_rotations.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <set>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {
namespace {

constexpr double kDegrees = 180.0 / M_PI;
// A measurement this far (degrees) from the current solution weighs half; one
// turned round (180 degrees) weighs about 1 %.
constexpr double kRobustScaleDegrees = 20.0;

double angle_degrees(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const double c = std::clamp(((A.transpose() * B).trace() - 1) / 2, -1.0, 1.0);
  return std::acos(c) * kDegrees;
}

// The rotation nearest to M (Frobenius).
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& M) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(2) *= -1;
  return U * svd.matrixV().transpose();
}

// Members of each connected component, and each component's measurements.
struct Component {
  std::vector<int> members;
  std::vector<int> measurements;
};

std::vector<Component> components(int n, const std::vector<RelativeRotation>& measured) {
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const RelativeRotation& m : measured) parent[root(m.from)] = root(m.to);
  std::vector<int> index(n, -1);
  std::vector<Component> result;
  for (int a = 0; a < n; ++a) {
    int& c = index[root(a)];
    if (c < 0) {
      c = int(result.size());
      result.emplace_back();
    }
    result[c].members.push_back(a);
  }
  for (size_t e = 0; e < measured.size(); ++e)
    result[index[root(measured[e].from)]].measurements.push_back(int(e));
  return result;
}

// A tree: the measurements composed outward from its first member, exact.
void compose_tree(const Component& c, const std::vector<RelativeRotation>& measured,
                  std::vector<Eigen::Matrix3d>* global) {
  std::vector<std::vector<int>> incident((*global).size());
  for (int e : c.measurements) {
    incident[measured[e].from].push_back(e);
    incident[measured[e].to].push_back(e);
  }
  std::vector<char> placed(global->size(), 0);
  std::queue<int> queue;
  queue.push(c.members.front());
  placed[c.members.front()] = 1;
  while (!queue.empty()) {
    const int a = queue.front();
    queue.pop();
    for (int e : incident[a]) {
      const RelativeRotation& m = measured[e];
      const int b = m.from == a ? m.to : m.from;
      if (placed[b]) continue;
      // G_to R = G_from
      (*global)[b] = m.from == a ? Eigen::Matrix3d((*global)[a] * m.R.transpose())
                                 : Eigen::Matrix3d((*global)[a] * m.R);
      placed[b] = 1;
      queue.push(b);
    }
  }
}

// One spectral solve on a component with the given measurement weights: the
// blocks Y_a ~ G_a^T C of the three leading eigenvectors of
// I + D^-1/2 A D^-1/2 (A's block (to, from) is w R), scaled back by D^-1/2.
void spectral_solve(const Component& c, const std::vector<RelativeRotation>& measured,
                    const std::vector<double>& weight, std::vector<Eigen::Matrix3d>* global) {
  const int k = int(c.members.size());
  std::vector<int> local(global->size(), -1);
  for (int i = 0; i < k; ++i) local[c.members[i]] = i;
  Eigen::VectorXd degree = Eigen::VectorXd::Zero(k);
  for (int e : c.measurements) {
    degree(local[measured[e].from]) += weight[e];
    degree(local[measured[e].to]) += weight[e];
  }
  Eigen::MatrixXd N = Eigen::MatrixXd::Identity(3 * k, 3 * k);
  for (int e : c.measurements) {
    const int a = local[measured[e].from], b = local[measured[e].to];
    const Eigen::Matrix3d block = weight[e] / std::sqrt(degree(a) * degree(b)) * measured[e].R;
    N.block<3, 3>(3 * b, 3 * a) = block;
    N.block<3, 3>(3 * a, 3 * b) = block.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(N);
  if (eigen.info() != Eigen::Success)
    throw NumericalError("synchronize_rotations: the eigensolver failed");
  Eigen::MatrixXd Y = eigen.eigenvectors().rightCols(3);
  for (int i = 0; i < k; ++i) Y.middleRows(3 * i, 3) /= std::sqrt(degree(i));
  // The eigenvectors fix the common frame only up to a reflection: the one
  // that makes the blocks rotations.
  double determinants = 0;
  for (int i = 0; i < k; ++i) determinants += Eigen::Matrix3d(Y.middleRows(3 * i, 3)).determinant();
  if (determinants < 0) Y.col(2) *= -1;
  for (int i = 0; i < k; ++i)
    (*global)[c.members[i]] = nearest_rotation(Y.middleRows(3 * i, 3)).transpose();
}

}  // namespace

SynchronizedRotations synchronize_rotations(int n, const std::vector<RelativeRotation>& measured,
                                            int rounds) {
  if (n < 0 || rounds < 1) throw UsageError("synchronize_rotations: n >= 0 and rounds >= 1");
  std::set<std::pair<int, int>> seen;
  for (const RelativeRotation& m : measured) {
    if (m.from < 0 || m.from >= n || m.to < 0 || m.to >= n)
      throw UsageError("synchronize_rotations: a member out of range");
    if (m.from == m.to) throw UsageError("synchronize_rotations: a member paired with itself");
    if (!seen.insert(std::minmax(m.from, m.to)).second)
      throw UsageError("synchronize_rotations: a pair measured twice");
  }
  SynchronizedRotations result;
  result.global.assign(n, Eigen::Matrix3d::Identity());
  result.implied.resize(measured.size());
  result.disagreement_degrees.assign(measured.size(), 0);
  std::vector<double> weight(measured.size(), 1.0);
  for (const Component& c : components(n, measured)) {
    if (c.measurements.size() < c.members.size()) {  // connected without a cycle
      compose_tree(c, measured, &result.global);
    } else {
      for (int round = 0; round < rounds; ++round) {
        spectral_solve(c, measured, weight, &result.global);
        for (int e : c.measurements) {
          const RelativeRotation& m = measured[e];
          const double angle =
              angle_degrees(m.R, result.global[m.to].transpose() * result.global[m.from]);
          weight[e] = 1 / (1 + std::pow(angle / kRobustScaleDegrees, 2));
        }
      }
    }
    for (int e : c.measurements) {
      const RelativeRotation& m = measured[e];
      result.implied[e] = result.global[m.to].transpose() * result.global[m.from];
      result.disagreement_degrees[e] = angle_degrees(m.R, result.implied[e]);
    }
  }
  return result;
}

}  // namespace unfold
