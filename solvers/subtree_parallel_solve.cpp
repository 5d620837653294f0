#include "solvers/subtree_parallel_solve.h"

#include <omp.h>

#include <algorithm>
#include <functional>
#include <queue>
#include <string>
#include <utility>

#include "core/errors.h"

namespace unfold {
namespace {

// The split of the tree: per node its group, or -1 for the nodes above the groups.
struct Split {
  std::vector<int> group;
  double top_work = 0, total_work = 0;
};

// Nodes above the subtrees are taken largest subtree first (a subtree's root
// goes up, its children join the others) for as long as that shortens the
// estimated sweep, the work above plus the larger of the largest subtree and
// an even share; the subtrees then go to the least loaded group, largest first.
Split split_tree(const std::vector<int>& parent, const std::vector<double>& work, int groups) {
  const int n = int(parent.size());
  Split split;
  split.group.assign(size_t(n), 0);
  std::vector<double> subtree(work);
  std::vector<int> child_start(size_t(n) + 1, 0);
  std::vector<int> children(static_cast<size_t>(n));
  std::vector<int> roots;
  for (int j = 0; j < n; ++j) {  // a parent comes after its children
    split.total_work += work[size_t(j)];
    if (parent[size_t(j)] < 0) {
      roots.push_back(j);
      continue;
    }
    subtree[size_t(parent[size_t(j)])] += subtree[size_t(j)];
    ++child_start[size_t(parent[size_t(j)]) + 1];
  }
  if (groups < 2) return split;
  for (int j = 0; j < n; ++j) child_start[size_t(j) + 1] += child_start[size_t(j)];
  std::vector<int> next(child_start.begin(), child_start.end() - 1);
  for (int j = 0; j < n; ++j)
    if (parent[size_t(j)] >= 0) children[size_t(next[size_t(parent[size_t(j)])]++)] = j;

  // Nodes taken one by one, each time the root of the largest subtree; the
  // best prefix of them is the top.
  using Entry = std::pair<double, int>;  // (subtree work, root): ties by index
  std::priority_queue<Entry> frontier;
  double total = 0, top = 0;  // the frontier's work, the taken nodes'
  for (const int r : roots) {
    frontier.emplace(subtree[size_t(r)], r);
    total += subtree[size_t(r)];
  }
  std::vector<int> taken;
  double best = total;  // nothing taken: one group holds all, as if serial
  size_t best_taken = 0;
  while (!frontier.empty()) {
    const double cost = top + std::max(frontier.top().first, total / groups);
    if (cost < best) best = cost, best_taken = taken.size();
    if (top >= best) break;  // taking more only adds to the top
    const int r = frontier.top().second;
    frontier.pop();
    top += work[size_t(r)];
    total -= work[size_t(r)];
    taken.push_back(r);
    for (int c = child_start[size_t(r)]; c < child_start[size_t(r) + 1]; ++c)
      frontier.emplace(subtree[size_t(children[size_t(c)])], children[size_t(c)]);
  }
  taken.resize(best_taken);
  for (const int r : taken) {
    split.group[size_t(r)] = -1;
    split.top_work += work[size_t(r)];
  }
  // The subtrees below the top: roots and the top's children not taken.
  std::vector<Entry> subtrees;
  for (int j = 0; j < n; ++j)
    if (split.group[size_t(j)] != -1 &&
        (parent[size_t(j)] < 0 || split.group[size_t(parent[size_t(j)])] == -1))
      subtrees.emplace_back(subtree[size_t(j)], j);
  std::sort(subtrees.begin(), subtrees.end(), std::greater<Entry>());
  std::vector<double> load(size_t(groups), 0.0);
  std::vector<int> root_group(size_t(n), -2);
  for (const auto& [w, r] : subtrees) {  // largest first, to the least loaded group
    const int g = int(std::min_element(load.begin(), load.end()) - load.begin());
    load[size_t(g)] += w;
    root_group[size_t(r)] = g;
  }
  for (int j = n - 1; j >= 0; --j) {
    if (split.group[size_t(j)] == -1) continue;
    split.group[size_t(j)] =
        root_group[size_t(j)] >= 0 ? root_group[size_t(j)] : split.group[size_t(parent[size_t(j)])];
  }
  return split;
}

}  // namespace

int SubtreeParallelSolve::count(int j) const {
  return factor_.column_count ? factor_.column_count[j]
                              : factor_.column_start[j + 1] - factor_.column_start[j];
}

SubtreeParallelSolve::SubtreeParallelSolve(const Factor& factor, int groups) : factor_(factor) {
  const int n = factor.n;
  std::vector<int> parent(size_t(n), -1);
  std::vector<double> work(size_t(n), 1.0);
  for (int j = 0; j < n; ++j) {
    const int first = factor.column_start[j], last = first + count(j);
    if (last <= first || factor.row[first] != j)
      throw UsageError("SubtreeParallelSolve: column " + std::to_string(j) +
                       " does not start with its diagonal entry");
    for (int p = first + 1; p < last; ++p) {
      const int i = factor.row[p];
      if (i <= j || i >= n)
        throw UsageError("SubtreeParallelSolve: an entry of column " + std::to_string(j) +
                         " is not below the diagonal");
      // The parent in the elimination tree: the column's first row below the diagonal.
      if (parent[size_t(j)] < 0 || i < parent[size_t(j)]) parent[size_t(j)] = i;
    }
    work[size_t(j)] += 2 * (last - first - 1);  // each entry once in either sweep
  }
  const int num_groups = std::max(1, groups);
  const Split split = split_tree(parent, work, num_groups);
  groups_.assign(size_t(num_groups), {});
  top_slot_.assign(size_t(n), -1);
  for (int j = 0; j < n; ++j) {
    if (split.group[size_t(j)] < 0) {
      top_slot_[size_t(j)] = int(top_.size());
      top_.push_back(j);
    } else {
      groups_[size_t(split.group[size_t(j)])].push_back(j);
    }
  }
  serial_share_ = num_groups < 2 || split.total_work == 0 ? 1 : split.top_work / split.total_work;
  y_.resize(3 * size_t(n));
  sums_.assign(3 * top_.size() * size_t(num_groups), 0.0);
}

void SubtreeParallelSolve::solve(const Eigen::MatrixX3d& b, Eigen::MatrixX3d* x) const {
  const int n = factor_.n;
  if (b.rows() != n) throw UsageError("SubtreeParallelSolve: right-hand side has the wrong size");
  const int* perm = factor_.permutation;
  const int* start = factor_.column_start;
  const int* row = factor_.row;
  const double* value = factor_.value;
  const bool cholesky = factor_.cholesky;
  double* y = y_.data();
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) y[3 * k + c] = b(perm[k], c);
  const size_t num_top = top_.size();
  // Column j of L y = P b, y_j final: its updates of j's ancestors, those in
  // its group directly, the top nodes' into `sums` (null: directly too).
  const auto forward = [&](int j, double* sums) {
    double* yj = y + 3 * j;
    const int first = start[j], last = first + count(j);
    if (cholesky) {
      const double d = value[first];
      yj[0] /= d, yj[1] /= d, yj[2] /= d;
    }
    const double s0 = yj[0], s1 = yj[1], s2 = yj[2];
    for (int p = first + 1; p < last; ++p) {
      const double l = value[p];  // read once: to the compiler the stores may alias it
      const int i = row[p], slot = sums ? top_slot_[size_t(i)] : -1;
      double* target = slot < 0 ? y + 3 * i : sums + 3 * slot;
      target[0] -= l * s0;
      target[1] -= l * s1;
      target[2] -= l * s2;
    }
  };
  // Column j of L^T x = y (L D L^T: D^-1 y): its entries' rows are j's ancestors.
  const auto backward = [&](int j) {
    const int first = start[j], last = first + count(j);
    const double d = value[first];
    double s0 = y[3 * j], s1 = y[3 * j + 1], s2 = y[3 * j + 2];
    if (!cholesky) s0 /= d, s1 /= d, s2 /= d;
    for (int p = first + 1; p < last; ++p) {
      const double l = value[p];
      const double* xi = y + 3 * row[p];
      s0 -= l * xi[0];
      s1 -= l * xi[1];
      s2 -= l * xi[2];
    }
    if (cholesky) s0 /= d, s1 /= d, s2 /= d;
    y[3 * j] = s0, y[3 * j + 1] = s1, y[3 * j + 2] = s2;
  };
  const int num_groups = int(groups_.size());
  const int threads = std::min(num_groups, omp_get_max_threads());
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    for (int g = omp_get_thread_num(); g < num_groups; g += omp_get_num_threads()) {
      double* sums = sums_.data() + 3 * num_top * size_t(g);
      for (const int j : groups_[size_t(g)]) forward(j, sums);
    }
  }
  // The groups' sums in group order (the same whatever the threads), cleared
  // for the next solve.
  for (int g = 0; g < num_groups; ++g) {
    double* sums = sums_.data() + 3 * num_top * size_t(g);
    for (size_t t = 0; t < num_top; ++t)
      for (int c = 0; c < 3; ++c) {
        y[3 * top_[t] + c] += sums[3 * t + c];
        sums[3 * t + c] = 0;
      }
  }
  for (const int j : top_) forward(j, nullptr);
  for (auto j = top_.rbegin(); j != top_.rend(); ++j) backward(*j);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    for (int g = omp_get_thread_num(); g < num_groups; g += omp_get_num_threads())
      for (auto j = groups_[size_t(g)].rbegin(); j != groups_[size_t(g)].rend(); ++j) backward(*j);
  }
  x->resize(n, 3);
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < 3; ++c) (*x)(perm[k], c) = y[3 * k + c];
}

}  // namespace unfold
