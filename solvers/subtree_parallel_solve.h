// The two triangular solves of a simplicial sparse factor, P A P^T = L L^T or
// L D L^T, with the elimination tree's disjoint subtrees on separate threads
// (docs/performance.md, solves by subtrees). A column of L only updates its
// ancestors in the tree, so subtrees with no common node are independent in
// both sweeps: the forward sweep runs them in parallel (their updates of the
// nodes above them summed per group of subtrees) and then those nodes, the
// backward sweep those nodes first and then the subtrees in parallel. All
// three columns of the right side go through one sweep together (rows
// interleaved), so L is read once a sweep, where solving columns on separate
// threads reads it once a thread. The factor is read where it is, not copied.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace unfold {

class SubtreeParallelSolve {
 public:
  /// The factor's columns in compressed form. The arrays are referenced, not
  /// copied: they must outlive the object and keep their values.
  struct Factor {
    int n = 0;
    const int* column_start = nullptr;  ///< n + 1 offsets
    /// entries per column (a factor with room left between columns); null:
    /// column_start's differences
    const int* column_count = nullptr;
    const int* row = nullptr;          ///< per entry; each column's diagonal entry first
    const double* value = nullptr;     ///< per entry
    const int* permutation = nullptr;  ///< row k of P A P^T is row permutation[k] of A
    /// true: L L^T (the diagonal entry is L's); false: L D L^T, L unit lower and
    /// the diagonal entry D's
    bool cholesky = true;
  };

  /// Splits the elimination tree into `groups` groups of disjoint subtrees of
  /// about equal work, and the nodes above them.
  /// @param groups >= 1; the solves run them on as many threads as the OpenMP
  ///        runtime gives (up to one a group); the result depends on the
  ///        groups, not on the threads
  /// @throws UsageError if a column does not start with its diagonal entry or
  ///         has an entry above it
  SubtreeParallelSolve(const Factor& factor, int groups);

  /// x = A^{-1} b. Not safe to call concurrently on one object.
  /// @param b n x 3; x is resized to n x 3 (may not alias b)
  void solve(const Eigen::MatrixX3d& b, Eigen::MatrixX3d* x) const;

  /// The share of the sweeps' work (entries of L) in the nodes above the
  /// subtrees, which run on one thread: 1 when the tree did not split.
  double serial_share() const { return serial_share_; }

 private:
  Factor factor_;
  // Nodes of each group (ascending), and the nodes above every group (ascending).
  std::vector<std::vector<int>> groups_;
  std::vector<int> top_;
  std::vector<int> top_slot_;  // per node: its row in the groups' sums, -1 in a group
  double serial_share_ = 1;
  mutable std::vector<double> y_;     // the interleaved right side, n x 3 by rows
  mutable std::vector<double> sums_;  // per group, its updates of the top nodes (x 3)

  int count(int j) const;
};

}  // namespace unfold
