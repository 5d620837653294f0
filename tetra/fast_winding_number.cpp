#include "tetra/fast_winding_number.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "geometry/fast_atan2.h"

namespace unfold {
namespace {

// A triangle's corner relative to a query point q, and its distance from q.
template <typename Real>
struct Corner {
  Real x, y, z, length;
};

Corner<double> corner(const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = p - q;
  return {d.x(), d.y(), d.z(), d.norm()};
}

// The signed solid angle of triangle (a, b, c) seen from q, positive when q is
// behind the triangle's normal, is 2 atan2(numerator, denominator) of these
// (Van Oosterom and Strackee 1983). Written on scalars: the packet walk below
// takes it in lane loops GCC vectorizes.
template <typename Real>
struct HalfAngle {
  Real numerator, denominator;
};

template <typename Real>
inline HalfAngle<Real> half_solid_angle(const Corner<Real>& a, const Corner<Real>& b,
                                        const Corner<Real>& c) {
  return {
      a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) + a.z * (b.x * c.y - b.y * c.x),
      a.length * b.length * c.length + (a.x * b.x + a.y * b.y + a.z * b.z) * c.length +
          (b.x * c.x + b.y * c.y + b.z * c.z) * a.length +
          (c.x * a.x + c.y * a.y + c.z * a.z) * b.length};
}

double triangle_solid_angle(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int t,
                            const Eigen::Vector3d& q) {
  const HalfAngle<double> h = half_solid_angle(corner(V.row(F(t, 0)), q), corner(V.row(F(t, 1)), q),
                                               corner(V.row(F(t, 2)), q));
  return 2 * std::atan2(h.numerator, h.denominator);
}

constexpr int kLeafSize = 8;
constexpr int kMaxLeafPoints = 3 * kLeafSize;

// Fills node `index` with triangles order[first, first + count) and builds its subtree.
void build(FastWindingNumberTree& tree, const Eigen::MatrixX3d& centroids, int index, int first,
           int count) {
  FastWindingNumberTree::Node node;
  node.first = first;
  node.count = count;
  double area = 0;
  Eigen::AlignedBox3d box;
  for (int k = first; k < first + count; ++k) {
    const int t = tree.order[size_t(k)];
    const Eigen::Vector3d a = tree.V.row(tree.F(t, 0)), b = tree.V.row(tree.F(t, 1)),
                          c = tree.V.row(tree.F(t, 2));
    const Eigen::Vector3d n = 0.5 * (b - a).cross(c - a);
    node.area_normal += n;
    node.center += n.norm() * centroids.row(t).transpose();
    area += n.norm();
    box.extend(centroids.row(t).transpose());
  }
  node.center = area > 0 ? Eigen::Vector3d(node.center / area) : box.center();
  for (int k = first; k < first + count; ++k)
    for (int j = 0; j < 3; ++j)
      node.radius =
          std::max(node.radius,
                   (tree.V.row(tree.F(tree.order[size_t(k)], j)).transpose() - node.center).norm());
  if (count > kLeafSize) {
    int axis = 0;
    box.sizes().maxCoeff(&axis);
    const auto begin = tree.order.begin() + first, end = begin + count, middle = begin + count / 2;
    std::nth_element(begin, middle, end,
                     [&](int s, int t) { return centroids(s, axis) < centroids(t, axis); });
    // Children are stored next to each other so one index finds both.
    node.left = int(tree.nodes.size());
    tree.nodes.resize(tree.nodes.size() + 2);
    tree.nodes[size_t(index)] = node;
    build(tree, centroids, node.left, first, count / 2);
    build(tree, centroids, node.left + 1, first + count / 2, count - count / 2);
  } else {
    // The leaf's distinct corners (at most 3 kLeafSize, so a byte indexes them).
    node.first_point = int(tree.points.size());
    for (int k = first; k < first + count; ++k)
      for (int j = 0; j < 3; ++j) {
        const int v = tree.F(tree.order[size_t(k)], j);
        int local = 0;
        while (local < node.num_points &&
               tree.points[size_t(node.first_point + local)] != tree.V.row(v).transpose())
          ++local;
        if (local == node.num_points) {
          tree.points.push_back(tree.V.row(v).transpose());
          ++node.num_points;
        }
        tree.corners[size_t(3 * k + j)] = static_cast<unsigned char>(local);
      }
    tree.nodes[size_t(index)] = node;
  }
}

// Spreads the low 10 bits of v to every third bit (Morton code helper).
uint32_t spread_bits(uint32_t v) {
  v &= 0x3ff;
  v = (v | (v << 16)) & 0x030000ff;
  v = (v | (v << 8)) & 0x0300f00f;
  v = (v | (v << 4)) & 0x030c30c3;
  return (v | (v << 2)) & 0x09249249;
}

// The rows of Q along a Z-order curve: queries in this order walk the same
// part of the tree one after another (the tree's nodes stay in cache), which
// more than pays for the sort. Each query's value does not depend on it.
std::vector<int> spatial_order(const Eigen::MatrixX3d& Q) {
  std::vector<int> order(size_t(Q.rows()));
  for (int i = 0; i < int(Q.rows()); ++i) order[size_t(i)] = i;
  if (Q.rows() < 2 || !Q.allFinite()) return order;
  const Eigen::RowVector3d low = Q.colwise().minCoeff();
  const double extent = (Q.colwise().maxCoeff() - low).maxCoeff();
  if (!(extent > 0)) return order;
  std::vector<uint32_t> key(size_t(Q.rows()));
  for (int i = 0; i < int(Q.rows()); ++i) {
    uint32_t code = 0;
    for (int k = 0; k < 3; ++k)
      code |= spread_bits(uint32_t((Q(i, k) - low(k)) / extent * 1023.0)) << k;
    key[size_t(i)] = code;
  }
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return key[size_t(a)] < key[size_t(b)]; });
  return order;
}

}  // namespace

FastWindingNumberTree fast_winding_number_precomputation(const Eigen::MatrixX3d& V,
                                                         const Eigen::MatrixX3i& F,
                                                         double accuracy) {
  FastWindingNumberTree tree;
  tree.V = V;
  tree.F = F;
  tree.accuracy = accuracy;
  tree.order.resize(size_t(F.rows()));
  for (int t = 0; t < int(F.rows()); ++t) tree.order[size_t(t)] = t;
  if (F.rows() == 0) return tree;
  Eigen::MatrixX3d centroids(F.rows(), 3);
  for (int t = 0; t < int(F.rows()); ++t)
    centroids.row(t) = (V.row(F(t, 0)) + V.row(F(t, 1)) + V.row(F(t, 2))) / 3;
  tree.nodes.resize(1);
  tree.corners.resize(3 * size_t(F.rows()));
  build(tree, centroids, 0, 0, int(F.rows()));
  tree.float_origin = 0.5 * (V.colwise().minCoeff() + V.colwise().maxCoeff()).transpose();
  tree.float_nodes.reserve(tree.nodes.size());
  for (const FastWindingNumberTree::Node& node : tree.nodes)
    tree.float_nodes.push_back(
        {{float(node.center.x() - tree.float_origin.x()),
          float(node.center.y() - tree.float_origin.y()),
          float(node.center.z() - tree.float_origin.z())},
         {float(node.area_normal.x()), float(node.area_normal.y()), float(node.area_normal.z())},
         float(node.radius),
         node.left});
  return tree;
}

namespace {

// Queries traversing the tree together: 16 (two AVX2 vectors in float, four
// in double). The walk is bound by loading nodes, and each node loaded serves
// the whole packet: 16 rather than 8 took the coarse pass 205 -> 178 ms and
// the accurate one 439 -> 350 ms on david0 (BM_WindingNumbers).
constexpr int kPacket = 16;

// Float's rounding of a near triangle's numerator can put a query within about
// 1e-6 of the triangle's size from its plane on the plane's other side, which
// moves w by 1 (and near its edges, where the numerator and the denominator
// both vanish, the angle is anything). A float walk flags a query that meets a
// triangle whose |numerator| and denominator are below this times the corners'
// length product; classify evaluates it again in double.
constexpr float kFloatDoubtful = 1e-4f;

// Winding numbers at q[0, count), count <= kPacket: clusters farther than
// accuracy * radius by their dipole, the near leaves' triangles summed with
// fast_atan2. The queries go down the tree together, a query leaving the walk
// where its cluster is far, and each node's far field and each leaf's
// triangles are computed for all of them at once: every loop over the
// packet's lanes is branch-free (inactive lanes computed, their terms not
// added), so GCC vectorizes it, two lanes per SSE2 instruction and four in
// the AVX2 clone, picked at load time where the CPU has it (david0's carve
// 1.11 -> 0.77 s, docs/history/performance.md). Each query meets the nodes it meets
// alone, in the same order, so its sum is the one-query walk's bit for bit.
// Real is double (the accurate values) or float (classify's coarse pass: twice
// the lanes per instruction). In float the corner offsets are taken in double
// and then rounded, so that their error is relative to the offset, not to the
// coordinates; doubtful[k] says whether query k met a triangle float cannot
// vouch for (kFloatDoubtful; always false in double).
template <typename Real>
__attribute__((target_clones("avx2", "default"))) void winding_numbers_at(
    const FastWindingNumberTree& tree, const Eigen::Vector3d* q, int count, double accuracy,
    double* w, bool* doubtful) {
  alignas(64) Real sum[kPacket] = {};
  alignas(64) Real flagged[kPacket] = {};
  // Lanes past count repeat the last query.
  alignas(64) double qx[kPacket], qy[kPacket], qz[kPacket];
  alignas(64) Real rx[kPacket], ry[kPacket], rz[kPacket];
  // The far field's query in the float nodes' frame (double's is the identity).
  const Eigen::Vector3d origin =
      std::is_same_v<Real, float> ? tree.float_origin : Eigen::Vector3d::Zero();
  for (int k = 0; k < kPacket; ++k) {
    const Eigen::Vector3d& p = q[std::min(k, count - 1)];
    qx[k] = p.x(), qy[k] = p.y(), qz[k] = p.z();
    rx[k] = Real(p.x() - origin.x()), ry[k] = Real(p.y() - origin.y()),
    rz[k] = Real(p.z() - origin.z());
  }
  struct Entry {
    int node;
    uint32_t active;  // bit k: query k goes on below this node
  };
  Entry stack[128];
  int size = 0;
  stack[size++] = {0, (1u << count) - 1};
  while (size > 0) {
    const Entry entry = stack[--size];
    Real cx, cy, cz, nx, ny, nz, reach;
    int left;
    if constexpr (std::is_same_v<Real, float>) {
      const FastWindingNumberTree::FloatNode& node = tree.float_nodes[size_t(entry.node)];
      cx = node.center[0], cy = node.center[1], cz = node.center[2];
      nx = node.area_normal[0], ny = node.area_normal[1], nz = node.area_normal[2];
      reach = float(accuracy) * node.radius;
      left = node.left;
    } else {
      const FastWindingNumberTree::Node& node = tree.nodes[size_t(entry.node)];
      cx = node.center.x(), cy = node.center.y(), cz = node.center.z();
      nx = node.area_normal.x(), ny = node.area_normal.y(), nz = node.area_normal.z();
      reach = accuracy * node.radius;
      left = node.left;
    }
    // Lane flags as Reals (1 or 0): SSE2 compares and selects those.
    alignas(64) Real active[kPacket], near[kPacket];
    for (int k = 0; k < kPacket; ++k) active[k] = Real(entry.active >> k & 1);
#pragma GCC unroll 1  // unrolled first, it would not be vectorized
    for (int k = 0; k < kPacket; ++k) {
      // Far: the cluster acts as a dipole of moment area_normal at center.
      const Real dx = cx - rx[k], dy = cy - ry[k], dz = cz - rz[k];
      const Real distance = std::sqrt(dx * dx + dy * dy + dz * dz);
      const Real term = (nx * dx + ny * dy + nz * dz) / (distance * distance * distance);
      const bool far = distance > reach;
      sum[k] += (active[k] > 0) & far ? term : Real(0);
      near[k] = (active[k] > 0) & !far ? Real(1) : Real(0);
    }
    uint32_t open = 0;
    for (int k = 0; k < kPacket; ++k) open |= uint32_t(near[k] > 0) << k;
    if (open == 0) continue;
    if (left >= 0) {
      stack[size++] = {left, open};
      stack[size++] = {left + 1, open};
      continue;
    }
    const FastWindingNumberTree::Node& node = tree.nodes[size_t(entry.node)];
    // The leaf's corners' offsets and lengths once per query, then its
    // triangles' solid angles.
    alignas(64) Real ox[kMaxLeafPoints][kPacket], oy[kMaxLeafPoints][kPacket],
        oz[kMaxLeafPoints][kPacket], length[kMaxLeafPoints][kPacket];
    for (int p = 0; p < node.num_points; ++p) {
      const Eigen::Vector3d& point = tree.points[size_t(node.first_point + p)];
      const double px = point.x(), py = point.y(), pz = point.z();
      for (int k = 0; k < kPacket; ++k) {
        ox[p][k] = Real(px - qx[k]), oy[p][k] = Real(py - qy[k]), oz[p][k] = Real(pz - qz[k]);
        length[p][k] = std::sqrt(ox[p][k] * ox[p][k] + oy[p][k] * oy[p][k] + oz[p][k] * oz[p][k]);
      }
    }
    for (int t = node.first; t < node.first + node.count; ++t) {
      const unsigned char* c = &tree.corners[size_t(3 * t)];
      for (int k = 0; k < kPacket; ++k) {
        const HalfAngle<Real> h =
            half_solid_angle<Real>({ox[c[0]][k], oy[c[0]][k], oz[c[0]][k], length[c[0]][k]},
                                   {ox[c[1]][k], oy[c[1]][k], oz[c[1]][k], length[c[1]][k]},
                                   {ox[c[2]][k], oy[c[2]][k], oz[c[2]][k], length[c[2]][k]});
        const Real angle = 2 * fast_atan2(h.numerator, h.denominator);
        sum[k] += near[k] > 0 ? angle : Real(0);  // x + 0 is x
        if constexpr (std::is_same_v<Real, float>) {
          const float scale = kFloatDoubtful * length[c[0]][k] * length[c[1]][k] * length[c[2]][k];
          flagged[k] += (near[k] > 0) & (std::abs(h.numerator) < scale) & (h.denominator < scale)
                            ? 1.0f
                            : 0.0f;
        }
      }
    }
  }
  for (int k = 0; k < count; ++k) {
    w[k] = double(sum[k]) / (4 * M_PI);
    doubtful[k] = flagged[k] > 0;
  }
}

// Fills w(i) for the rows i of Q listed in `rows`, a packet of consecutive rows
// at a time (in a Z-order they are close, and take nearly the same walk), by
// Real's walk; (*doubtful)[i], if given, whether float's w(i) is in doubt.
template <typename Real>
void solve_rows(const FastWindingNumberTree& tree, const Eigen::MatrixX3d& Q,
                const std::vector<int>& rows, double accuracy, Eigen::VectorXd* w,
                std::vector<char>* doubtful = nullptr) {
  if (tree.nodes.empty()) return;
  const Eigen::Index packets = (Eigen::Index(rows.size()) + kPacket - 1) / kPacket;
#pragma omp parallel for schedule(dynamic, 32)
  for (Eigen::Index p = 0; p < packets; ++p) {
    const size_t first = size_t(p) * kPacket;
    const int count = int(std::min(rows.size() - first, size_t(kPacket)));
    Eigen::Vector3d q[kPacket];
    double values[kPacket];
    bool flags[kPacket];
    for (int k = 0; k < count; ++k) q[k] = Q.row(rows[first + size_t(k)]);
    winding_numbers_at<Real>(tree, q, count, accuracy, values, flags);
    for (int k = 0; k < count; ++k) {
      (*w)(rows[first + size_t(k)]) = values[k];
      if (doubtful) (*doubtful)[size_t(rows[first + size_t(k)])] = flags[k];
    }
  }
}

}  // namespace

Eigen::VectorXd fast_winding_number_solve(const FastWindingNumberTree& tree,
                                          const Eigen::MatrixX3d& Q) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(Q.rows());
  solve_rows<double>(tree, Q, spatial_order(Q), tree.accuracy, &w);
  return w;
}

Eigen::VectorXd fast_winding_number_classify(const FastWindingNumberTree& tree,
                                             const Eigen::MatrixX3d& Q,
                                             const ClassifyOptions& options) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(Q.rows());
  const std::vector<int> order = spatial_order(Q);
  std::vector<char> doubtful(size_t(Q.rows()), 0);
  solve_rows<float>(tree, Q, order, std::min(options.coarse_accuracy, tree.accuracy), &w,
                    &doubtful);
  std::vector<int> uncertain;
  for (int i : order)
    if (classify_refines(w(i), options) || doubtful[size_t(i)]) uncertain.push_back(i);
  solve_rows<double>(tree, Q, uncertain, tree.accuracy, &w);
  return w;
}

Eigen::VectorXd winding_number(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
                               const Eigen::MatrixX3d& Q) {
  Eigen::VectorXd w(Q.rows());
#pragma omp parallel for schedule(dynamic, 64)
  for (Eigen::Index i = 0; i < Q.rows(); ++i) {
    double sum = 0;
    for (int t = 0; t < int(F.rows()); ++t) sum += triangle_solid_angle(V, F, t, Q.row(i));
    w(i) = sum / (4 * M_PI);
  }
  return w;
}

}  // namespace unfold
