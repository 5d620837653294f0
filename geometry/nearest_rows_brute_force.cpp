#include "geometry/nearest_rows_brute_force.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

constexpr int kRows = 32;   // database rows per register block (the database padded to it)
constexpr int kTile = 512;  // database rows per cache tile
constexpr int kBlock = 64;  // queries per thread's task

// The argument of every scan: for the queries [begin, end) (rows of q, k
// wide, each scaled by -2), the database rows [tile, tile_end) of dt (k x
// padded, dimension-major) with their squared norms norms: |d|^2 - 2 q.d, the
// same argmin as |q - d|^2. least and at hold, per query and per lane (row
// mod kRows), the least score so far and its row: the first of equal scores,
// as each lane sees its rows in order.
struct Scan {
  const float* q;
  int k, begin, end;
  const float* dt;
  const float* norms;
  long padded, tile, tile_end;
  float* least;
  int* at;
};

// Queries scored at once: their kQueries x kRows scores stay in registers
// (enough independent sums to hide the multiply-add latency).
template <int kQueries>
inline __attribute__((always_inline)) void scan_tile(const Scan& s) {
  for (int i = s.begin; i < s.end; i += kQueries) {
    const int count = std::min(kQueries, s.end - i);
    const float* query[kQueries];  // a query past the block's end repeats the last one
    float lane_least[kQueries][kRows];
    int lane_at[kQueries][kRows];
    for (int r = 0; r < kQueries; ++r) {
      const long row = i + std::min(r, count - 1);
      query[r] = s.q + row * s.k;
      for (int j = 0; j < kRows; ++j) {
        lane_least[r][j] = s.least[row * kRows + j];
        lane_at[r][j] = s.at[row * kRows + j];
      }
    }
    for (long j0 = s.tile; j0 < s.tile_end; j0 += kRows) {
      float score[kQueries][kRows];
      for (int r = 0; r < kQueries; ++r)
        for (int j = 0; j < kRows; ++j) score[r][j] = s.norms[j0 + j];
      for (int c = 0; c < s.k; ++c) {
        const float* d = s.dt + c * s.padded + j0;
        for (int r = 0; r < kQueries; ++r)
          for (int j = 0; j < kRows; ++j) score[r][j] += query[r][c] * d[j];
      }
      for (int r = 0; r < kQueries; ++r)
        for (int j = 0; j < kRows; ++j) {
          const bool less = score[r][j] < lane_least[r][j];
          lane_least[r][j] = less ? score[r][j] : lane_least[r][j];
          lane_at[r][j] = less ? int(j0) + j : lane_at[r][j];
        }
    }
    for (int r = 0; r < count; ++r)
      for (int j = 0; j < kRows; ++j) {
        s.least[long(i + r) * kRows + j] = lane_least[r][j];
        s.at[long(i + r) * kRows + j] = lane_at[r][j];
      }
  }
}

// One build runs anywhere: the scan compiled for each instruction set, the
// processor's chosen at run time (the query counts measured best for each).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define UNFOLD_VECTOR_DISPATCH 1
__attribute__((target("arch=x86-64-v4"))) void scan_avx512(const Scan& s) { scan_tile<8>(s); }
__attribute__((target("arch=x86-64-v3"))) void scan_avx2(const Scan& s) { scan_tile<6>(s); }
#endif
void scan_baseline(const Scan& s) { scan_tile<4>(s); }

using ScanFunction = void (*)(const Scan&);

ScanFunction scan_function(VectorInstructions instructions) {
  switch (instructions) {
#ifdef UNFOLD_VECTOR_DISPATCH
    case VectorInstructions::avx512:
      return scan_avx512;
    case VectorInstructions::avx2:
      return scan_avx2;
#endif
    default:
      return scan_baseline;
  }
}

VectorInstructions widest_instructions() {
  for (const VectorInstructions v : {VectorInstructions::avx512, VectorInstructions::avx2})
    if (supports(v)) return v;
  return VectorInstructions::baseline;
}

}  // namespace

bool supports(VectorInstructions instructions) {
#ifdef UNFOLD_VECTOR_DISPATCH
  __builtin_cpu_init();
  if (instructions == VectorInstructions::avx512) return __builtin_cpu_supports("x86-64-v4");
  if (instructions == VectorInstructions::avx2) return __builtin_cpu_supports("x86-64-v3");
#endif
  return instructions == VectorInstructions::baseline;
}

Eigen::VectorXi nearest_rows_brute_force(const Eigen::MatrixXf& queries,
                                         const Eigen::MatrixXf& database) {
  static const VectorInstructions widest = widest_instructions();
  return nearest_rows_brute_force(queries, database, widest);
}

Eigen::VectorXi nearest_rows_brute_force(const Eigen::MatrixXf& queries,
                                         const Eigen::MatrixXf& database,
                                         VectorInstructions instructions) {
  if (!supports(instructions))
    throw UsageError("nearest_rows_brute_force: this processor lacks the instructions asked for");
  const ScanFunction scan = scan_function(instructions);
  if (queries.cols() != database.cols() || database.rows() == 0)
    throw UsageError("nearest_rows_brute_force: need a non-empty database of the queries' width");
  const int k = int(database.cols());
  const long n = database.rows(), m = queries.rows();
  const long padded = (n + kRows - 1) / kRows * kRows;
  // Dimension-major, padded with rows of infinite norm that no query picks.
  std::vector<float> dt(size_t(k) * size_t(padded), 0.0f);
  std::vector<float> norms(size_t(padded), std::numeric_limits<float>::infinity());
  for (long j = 0; j < n; ++j) {
    for (int c = 0; c < k; ++c) dt[size_t(c * padded + j)] = database(j, c);
    norms[size_t(j)] = database.row(j).squaredNorm();
  }
  std::vector<float> q(size_t(m) * size_t(k));
  for (long i = 0; i < m; ++i)
    for (int c = 0; c < k; ++c) q[size_t(i * k + c)] = -2.0f * queries(i, c);
  std::vector<float> least(size_t(m) * kRows, std::numeric_limits<float>::infinity());
  std::vector<int> at(size_t(m) * kRows, 0);
  const long blocks = (m + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(dynamic)
  for (long b = 0; b < blocks; ++b) {
    Scan s{q.data(),
           k,
           int(b * kBlock),
           int(std::min(m, (b + 1) * kBlock)),
           dt.data(),
           norms.data(),
           padded,
           0,
           0,
           least.data(),
           at.data()};
    for (s.tile = 0; s.tile < padded; s.tile += kTile) {
      s.tile_end = std::min(padded, s.tile + kTile);
      scan(s);
    }
  }
  // Each query's least score over its lanes, the first row of equal ones.
  Eigen::VectorXi nearest(m);
  for (long i = 0; i < m; ++i) {
    const float* l = &least[size_t(i * kRows)];
    const int* a = &at[size_t(i * kRows)];
    int best = 0;
    for (int j = 1; j < kRows; ++j)
      if (l[j] < l[best] || (l[j] == l[best] && a[j] < a[best])) best = j;
    nearest(i) = a[best];
  }
  return nearest;
}

}  // namespace unfold
