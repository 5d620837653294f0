// ARAP with held vertices (the interior following the surface, domain: surface)
// and an anchor: rigid motions are followed exactly, other deformations lower
// the energy, held rows stay, a strong anchor keeps the start.
#include "solvers/arap_solve.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "geometry/best_rotation.h"
#include "mesh/best_rotations.h"
#include "mesh/edge_graph.h"
#include "test_meshes.h"

namespace unfold {
namespace {

// A 4 x 4 x 4 grid of tets with its boundary vertices first, as in a TetMesh.
struct BoundaryFirstGrid {
  TetMesh mesh;
  int num_boundary = 0;
  BoundaryFirstGrid() {
    const TetMesh grid = test::grid_tet_mesh(4, 4, 4);
    const int n = int(grid.V.rows());
    std::vector<int> order;
    std::vector<int> position(static_cast<size_t>(n));
    for (const bool boundary : {true, false})
      for (int i = 0; i < n; ++i) {
        const Eigen::RowVector3d p = grid.V.row(i);
        if (((p.array() == 0) || (p.array() == 4)).any() == boundary) order.push_back(i);
      }
    mesh.V.resize(n, 3);
    for (int k = 0; k < n; ++k) {
      mesh.V.row(k) = grid.V.row(order[size_t(k)]);
      position[size_t(order[size_t(k)])] = k;
    }
    mesh.T = grid.T.unaryExpr([&](int i) { return position[size_t(i)]; });
    num_boundary = n - 27;  // the 3 x 3 x 3 inner vertices come last
  }
};

ArapSolveOptions held(int num_fixed) {
  ArapSolveOptions options;
  options.num_fixed = num_fixed;
  return options;
}

double arap_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q) {
  Rotations R;
  best_rotations(graph, P, Q, &R);
  double e = 0;
  for (int i = 0; i < graph.num_vertices; ++i)
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      e += (Q.row(i) - Q.row(j) - (R[size_t(i)] * (P.row(i) - P.row(j)).transpose()).transpose())
               .squaredNorm();
    }
  return e;
}

// Bent about the y axis, growing with x, with local detail lost to noise.
Eigen::MatrixX3d bent_and_noisy(const Eigen::MatrixX3d& V) {
  Eigen::MatrixX3d bent = V;
  for (int i = 0; i < bent.rows(); ++i) {
    const double a = 0.2 * V(i, 0), x = V(i, 0), z = V(i, 2);
    bent(i, 0) = std::cos(a) * x - std::sin(a) * z;
    bent(i, 2) = std::sin(a) * x + std::cos(a) * z;
  }
  return bent + 0.05 * Eigen::MatrixX3d::Random(bent.rows(), 3);
}

TEST(ArapSolve, FollowsARigidMotionOfTheSurface) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::Matrix3d R = test::random_rotation(7);
  const Eigen::RowVector3d t(1.0, -2.0, 0.5);
  const Eigen::MatrixX3d moved = (g.mesh.V * R.transpose()).rowwise() + t;
  Eigen::MatrixX3d start = moved;
  start.bottomRows(27) = g.mesh.V.bottomRows(27);  // interior left behind, unrotated
  const Eigen::MatrixX3d Q = arap_solve(graph, g.mesh.V, start, held(g.num_boundary));
  EXPECT_LT((Q - moved).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ArapSolve, LowersTheArapEnergyAndKeepsTheFixedRows) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  // A twist about the z axis, growing with height.
  Eigen::MatrixX3d twisted = g.mesh.V;
  for (int i = 0; i < twisted.rows(); ++i) {
    const double a = 0.15 * g.mesh.V(i, 2), x = g.mesh.V(i, 0) - 2, y = g.mesh.V(i, 1) - 2;
    twisted(i, 0) = std::cos(a) * x - std::sin(a) * y;
    twisted(i, 1) = std::sin(a) * x + std::cos(a) * y;
  }
  Eigen::MatrixX3d start = twisted;
  start.bottomRows(27) = g.mesh.V.bottomRows(27);
  const Eigen::MatrixX3d Q = arap_solve(graph, g.mesh.V, start, held(g.num_boundary));
  EXPECT_EQ(Q.topRows(g.num_boundary), twisted.topRows(g.num_boundary));
  EXPECT_LT(arap_energy(graph, g.mesh.V, Q), 0.5 * arap_energy(graph, g.mesh.V, start));
  // The twist itself is nearly as rigid as the surface allows: placement stays close to it.
  EXPECT_LT((Q - twisted).rowwise().norm().maxCoeff(), 0.1);
}

// The twisted grid with one vertex held: free, ARAP drifts back towards the
// rest shape (its minimum); anchored, the steps stay near the start, the
// stronger the anchor the nearer, and still lower the ARAP energy.
TEST(ArapSolve, AnAnchorKeepsTheStart) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  const auto moved = [&](double anchor) {
    ArapSolveOptions options = held(1);
    options.anchor = anchor;
    options.max_iterations = 30;
    options.tolerance = 0;
    return (arap_solve(graph, g.mesh.V, bent, options) - bent).rowwise().norm().mean();
  };
  const double free = moved(0), weak = moved(0.1), strong = moved(10);
  EXPECT_GT(free, weak);
  EXPECT_GT(weak, strong);
  EXPECT_LT(strong, 0.2 * free) << free << " " << weak << " " << strong;
  ArapSolveOptions options = held(1);
  options.anchor = 0.1;
  EXPECT_LT(arap_energy(graph, g.mesh.V, arap_solve(graph, g.mesh.V, bent, options)),
            0.5 * arap_energy(graph, g.mesh.V, bent));
}

// The energy arap_solve lowers: half arap_energy (each edge is seen from both
// ends there), plus the anchor.
double anchored_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q,
                       const Eigen::MatrixX3d& start, int num_fixed, double anchor) {
  const int m = int(Q.rows()) - num_fixed;
  return 0.5 * arap_energy(graph, P, Q) +
         anchor * (Q.bottomRows(m) - start.bottomRows(m)).squaredNorm();
}

// One vertex held, anchored with weight 0.1, steps until they move less than 1e-9.
ArapSolveOptions anchored_to_convergence() {
  ArapSolveOptions options = held(1);
  options.anchor = 0.1;
  options.max_iterations = 5000;
  options.tolerance = 1e-9;
  return options;
}

// Anderson acceleration and L-BFGS steps change how the steps get there, not
// where: from a bent, noisy grid, accelerated, L-BFGS and plain steps end at
// the same shape, none above the energy it started from; L-BFGS steps take
// far fewer than plain ones, and a cap on them is reported as such.
TEST(ArapSolve, AcceleratedAndLbfgsStepsEndWhereThePlainStepsDo) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  options.anderson = 0;
  ArapSolveReport plain_report, lbfgs_report;
  const Eigen::MatrixX3d plain = arap_solve(graph, g.mesh.V, bent, options, nullptr, &plain_report);
  options.anderson = 5;
  const Eigen::MatrixX3d accelerated = arap_solve(graph, g.mesh.V, bent, options);
  options.lbfgs = 5;
  const Eigen::MatrixX3d lbfgs = arap_solve(graph, g.mesh.V, bent, options, nullptr, &lbfgs_report);
  const double before = anchored_energy(graph, g.mesh.V, bent, bent, 1, 0.1);
  const double plain_energy = anchored_energy(graph, g.mesh.V, plain, bent, 1, 0.1);
  EXPECT_LT(plain_energy, 0.5 * before);
  for (const Eigen::MatrixX3d* other : {&accelerated, &lbfgs}) {
    EXPECT_LT((plain - *other).rowwise().norm().maxCoeff(), 1e-4);
    EXPECT_LT(anchored_energy(graph, g.mesh.V, *other, bent, 1, 0.1), plain_energy + 1e-9);
  }
  EXPECT_TRUE(plain_report.converged);
  EXPECT_TRUE(lbfgs_report.converged);
  EXPECT_LT(2 * lbfgs_report.steps, plain_report.steps);
  options.max_iterations = 3;
  arap_solve(graph, g.mesh.V, bent, options, nullptr, &lbfgs_report);
  EXPECT_EQ(lbfgs_report.steps, 3);
  EXPECT_FALSE(lbfgs_report.converged);
}

// The report counts the steps and says whether they converged, and asking
// for it changes nothing: capped at two steps, two and not converged; run to
// the tolerance, fewer steps than the cap and converged.
TEST(ArapSolve, ReportsItsStepsAndWhetherTheyConverged) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  ArapSolveReport report;
  const Eigen::MatrixX3d converged = arap_solve(graph, g.mesh.V, bent, options, nullptr, &report);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.steps, 2);
  EXPECT_LT(report.steps, options.max_iterations);
  EXPECT_EQ(converged, arap_solve(graph, g.mesh.V, bent, options));
  options.max_iterations = 2;
  const Eigen::MatrixX3d capped = arap_solve(graph, g.mesh.V, bent, options, nullptr, &report);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.steps, 2);
  EXPECT_EQ(capped, arap_solve(graph, g.mesh.V, bent, options));
  options.max_iterations = 0;
  arap_solve(graph, g.mesh.V, bent, options, nullptr, &report);
  EXPECT_EQ(report.steps, 0);
}

// With inverse-length weights a rigid motion is still followed exactly.
TEST(ArapSolve, InverseLengthWeightsFollowARigidMotion) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::Matrix3d R = test::random_rotation(11);
  const Eigen::MatrixX3d moved = (g.mesh.V * R.transpose()).rowwise() + Eigen::RowVector3d(2, 0, 1);
  Eigen::MatrixX3d start = moved;
  start.bottomRows(27) = g.mesh.V.bottomRows(27);
  ArapSolveOptions options = held(g.num_boundary);
  options.inverse_length_weights = true;
  EXPECT_LT((arap_solve(graph, g.mesh.V, start, options) - moved).cwiseAbs().maxCoeff(), 1e-6);
}

// sum_i sum_j w_ij |q_i - q_j - R_i (p_i - p_j)|^2 at its best rotations,
// w_ij = 1 / |p_i - p_j| (the grid's edges: 1, sqrt 2, sqrt 3), plus the anchor.
double inverse_length_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                             const Eigen::MatrixX3d& Q, const Eigen::MatrixX3d& start,
                             double anchor) {
  double e = 0;
  for (int i = 0; i < graph.num_vertices; ++i) {
    Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const Eigen::Vector3d p = (P.row(i) - P.row(j)).transpose();
      s += p / p.norm() * (Q.row(i) - Q.row(j));
    }
    const Eigen::Matrix3d R = best_rotation(s);
    for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k) {
      const int j = graph.neighbors[size_t(k)];
      const Eigen::Vector3d p = (P.row(i) - P.row(j)).transpose();
      e += 0.5 / p.norm() * (Q.row(i) - Q.row(j) - (R * p).transpose()).squaredNorm();
    }
  }
  return e + anchor * (Q.bottomRows(Q.rows() - 1) - start.bottomRows(Q.rows() - 1)).squaredNorm();
}

// Converged, each weighting ends at the lower value of its own energy: the
// inverse-length steps minimise the weighted energy, not the uniform one.
TEST(ArapSolve, InverseLengthWeightsMinimiseTheirOwnEnergy) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  const Eigen::MatrixX3d uniform = arap_solve(graph, g.mesh.V, bent, options);
  options.inverse_length_weights = true;
  const Eigen::MatrixX3d weighted = arap_solve(graph, g.mesh.V, bent, options);
  EXPECT_GT((uniform - weighted).rowwise().norm().maxCoeff(), 1e-3) << "the weights matter";
  // arap_solve scales the weights to mean 1, which scales the ARAP part against the
  // anchor: compare at that scale.
  double mean = 0;
  for (int e = 0; e < graph.num_edges(); ++e)
    mean += 1 / (g.mesh.V.row(graph.edges(e, 0)) - g.mesh.V.row(graph.edges(e, 1))).norm();
  mean /= graph.num_edges();
  const auto weighted_energy = [&](const Eigen::MatrixX3d& Q) {
    return inverse_length_energy(graph, g.mesh.V, Q, bent, 0.1 * mean);
  };
  EXPECT_LT(weighted_energy(weighted), weighted_energy(uniform));
  EXPECT_LT(anchored_energy(graph, g.mesh.V, uniform, bent, 1, 0.1),
            anchored_energy(graph, g.mesh.V, weighted, bent, 1, 0.1));
}

// A factor made apart (arap_factorization, as the integration makes the
// anchored steps' beside its own) gives the steps arap_solve's own factor gives,
// bit for bit; one made for another anchor gives other steps.
TEST(ArapSolve, AFactorMadeApartGivesTheSameSteps) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  options.inverse_length_weights = true;
  const Eigen::MatrixX3d own = arap_solve(graph, g.mesh.V, bent, options);
  const auto factor = arap_factorization(graph, g.mesh.V, options);
  EXPECT_EQ(arap_solve(graph, g.mesh.V, bent, options, factor.get()), own);
  ArapSolveOptions stronger = options;
  stronger.anchor = 10 * options.anchor;
  const auto other = arap_factorization(graph, g.mesh.V, stronger);
  EXPECT_GT((arap_solve(graph, g.mesh.V, bent, options, other.get()) - own).norm(), 1e-6);
  EXPECT_THROW(arap_factorization(graph, g.mesh.V, held(int(g.mesh.V.rows()))), UsageError);
  EXPECT_THROW(arap_factorization(graph, g.mesh.V.topRows(10), options), UsageError);
}

// Edge factors scale each edge's weight: factors of 1 are no factors, bit for
// bit; weaker edges on one side of the grid let that side follow the bend less
// stiffly (its ARAP part against the anchor), and the steps minimise the
// energy with those weights, not without them.
TEST(ArapSolve, EdgeFactorsWeighTheirEdges) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  options.inverse_length_weights = true;
  const Eigen::MatrixX3d plain = arap_solve(graph, g.mesh.V, bent, options);
  ArapSolveOptions ones = options;
  ones.edge_factors.assign(size_t(graph.num_edges()), 1.0);
  EXPECT_EQ(arap_solve(graph, g.mesh.V, bent, ones), plain);
  ArapSolveOptions weak = options;
  weak.edge_factors.assign(size_t(graph.num_edges()), 1.0);
  for (int e = 0; e < graph.num_edges(); ++e)
    if (g.mesh.V(graph.edges(e, 0), 0) < 2 && g.mesh.V(graph.edges(e, 1), 0) < 2)
      weak.edge_factors[size_t(e)] = 0.01;
  const Eigen::MatrixX3d weakened = arap_solve(graph, g.mesh.V, bent, weak);
  // Where the edges are weak the anchor wins: the result stays nearer the start there.
  double near_plain = 0, near_weak = 0;
  for (int i = 1; i < int(g.mesh.V.rows()); ++i)
    if (g.mesh.V(i, 0) < 1) {
      near_plain += (plain.row(i) - bent.row(i)).norm();
      near_weak += (weakened.row(i) - bent.row(i)).norm();
    }
  EXPECT_LT(near_weak, 0.5 * near_plain);
  ArapSolveOptions wrong = options;
  wrong.edge_factors.assign(3, 1.0);
  EXPECT_THROW(arap_solve(graph, g.mesh.V, bent, wrong), UsageError);
  wrong.edge_factors.assign(size_t(graph.num_edges()), 1.0);
  wrong.edge_factors[0] = 0;
  EXPECT_THROW(arap_solve(graph, g.mesh.V, bent, wrong), UsageError);
  EXPECT_THROW(arap_factorization(graph, g.mesh.V, wrong), UsageError);
}

// Shared by stiffness, each free vertex's anchor is the anchor times its
// sum_j w_ij |p_i - p_j|^2 over the mean: the free vertices' weights average the
// anchor, the grid's inner vertices (alike) get one weight, above the boundary's.
TEST(ArapSolve, AnAnchorSharedByStiffnessFollowsEachVertexsStiffness) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  ArapSolveOptions options = anchored_to_convergence();
  options.inverse_length_weights = true;
  EXPECT_EQ(arap_anchor_weights(graph, g.mesh.V, options),
            Eigen::VectorXd::Constant(graph.num_vertices - 1, options.anchor));
  options.anchor_by_stiffness = true;
  const Eigen::VectorXd a = arap_anchor_weights(graph, g.mesh.V, options);
  ASSERT_EQ(a.size(), graph.num_vertices - 1);
  EXPECT_NEAR(a.mean(), options.anchor, 1e-12);
  const Eigen::VectorXd inner = a.tail(27);
  EXPECT_LT(inner.maxCoeff() - inner.minCoeff(), 1e-12);
  EXPECT_GT(inner.minCoeff(), a.head(g.num_boundary - 1).maxCoeff());
  EXPECT_THROW(arap_anchor_weights(graph, g.mesh.V.topRows(10), options), UsageError);
}

// The anchored energy with each vertex's own anchor weight (arap_anchor_weights).
double shared_anchor_energy(const EdgeGraph& graph, const Eigen::MatrixX3d& P,
                            const Eigen::MatrixX3d& Q, const Eigen::MatrixX3d& start,
                            const Eigen::VectorXd& a) {
  const int m = int(a.size());
  return 0.5 * arap_energy(graph, P, Q) +
         a.dot((Q.bottomRows(m) - start.bottomRows(m)).rowwise().squaredNorm());
}

// Converged, each sharing of the anchor ends at the lower value of its own
// energy: the steps minimise the energy with every vertex's own anchor weight.
// The edge factors weigh edges, not the mesh: they leave the weights alone.
TEST(ArapSolve, AnAnchorSharedByStiffnessIsTheEnergyMinimised) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const Eigen::MatrixX3d bent = bent_and_noisy(g.mesh.V);
  ArapSolveOptions options = anchored_to_convergence();
  const Eigen::MatrixX3d alike = arap_solve(graph, g.mesh.V, bent, options);
  const Eigen::VectorXd a_alike = arap_anchor_weights(graph, g.mesh.V, options);
  options.anchor_by_stiffness = true;
  const Eigen::MatrixX3d shared = arap_solve(graph, g.mesh.V, bent, options);
  const Eigen::VectorXd a_shared = arap_anchor_weights(graph, g.mesh.V, options);
  EXPECT_GT((alike - shared).rowwise().norm().maxCoeff(), 1e-3) << "the sharing matters";
  EXPECT_LT(shared_anchor_energy(graph, g.mesh.V, shared, bent, a_shared),
            shared_anchor_energy(graph, g.mesh.V, alike, bent, a_shared));
  EXPECT_LT(shared_anchor_energy(graph, g.mesh.V, alike, bent, a_alike),
            shared_anchor_energy(graph, g.mesh.V, shared, bent, a_alike));
  options.edge_factors.assign(size_t(graph.num_edges()), 0.5);
  EXPECT_EQ(arap_anchor_weights(graph, g.mesh.V, options), a_shared);
}

// The global matrix is the free rows' block of sum_e w_e (u_a - u_b)(u_a - u_b)^T
// (w_e: 1 / rest length scaled to mean 1, times the edge's factor) plus the
// anchor's diagonal, one entry per free-free edge and per diagonal; with uniform
// weights and no anchor, exactly the graph Laplacian's block.
TEST(ArapSolve, TheGlobalMatrixIsTheWeightedLaplaciansFreeBlockPlusTheAnchor) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  const int n = graph.num_vertices, num_fixed = g.num_boundary, m = n - num_fixed;
  ArapSolveOptions uniform = held(num_fixed);
  const Eigen::SparseMatrix<double> L = graph_laplacian(graph);
  EXPECT_EQ(Eigen::MatrixXd(arap_global_matrix(graph, g.mesh.V, uniform)),
            Eigen::MatrixXd(L).bottomRightCorner(m, m));

  ArapSolveOptions options = held(num_fixed);
  options.inverse_length_weights = true;
  options.anchor = 0.3;
  options.anchor_by_stiffness = true;
  options.edge_factors.resize(size_t(graph.num_edges()));
  std::vector<double> w(size_t(graph.num_edges()));
  double sum = 0;
  for (int e = 0; e < graph.num_edges(); ++e) {
    w[size_t(e)] = 1 / (g.mesh.V.row(graph.edges(e, 0)) - g.mesh.V.row(graph.edges(e, 1))).norm();
    sum += w[size_t(e)];
    options.edge_factors[size_t(e)] = 1 + 0.5 * std::sin(double(e));
  }
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
  int free_edges = 0;
  for (int e = 0; e < graph.num_edges(); ++e) {
    const int a = graph.edges(e, 0), b = graph.edges(e, 1);
    const double we = w[size_t(e)] * graph.num_edges() / sum * options.edge_factors[size_t(e)];
    expected(a, a) += we;
    expected(b, b) += we;
    expected(a, b) -= we;
    expected(b, a) -= we;
    free_edges += a >= num_fixed && b >= num_fixed;
  }
  Eigen::MatrixXd block = expected.bottomRightCorner(m, m);
  block.diagonal() += arap_anchor_weights(graph, g.mesh.V, options);
  const Eigen::SparseMatrix<double> M = arap_global_matrix(graph, g.mesh.V, options);
  EXPECT_EQ(M.nonZeros(), m + 2 * free_edges);
  EXPECT_LT((Eigen::MatrixXd(M) - block).cwiseAbs().maxCoeff(),
            1e-12 * block.cwiseAbs().maxCoeff());
}

TEST(ArapSolve, RefusesMismatchedSizesAndNothingFixed) {
  const BoundaryFirstGrid g;
  const EdgeGraph graph = build_edge_graph(int(g.mesh.V.rows()), g.mesh.T);
  EXPECT_THROW(arap_solve(graph, g.mesh.V, g.mesh.V, held(0)), UsageError);
  ArapSolveOptions negative = held(1);
  negative.anchor = -1;
  EXPECT_THROW(arap_solve(graph, g.mesh.V, g.mesh.V, negative), UsageError);
  ArapSolveOptions no_window = held(1);
  no_window.anderson = -1;
  EXPECT_THROW(arap_solve(graph, g.mesh.V, g.mesh.V, no_window), UsageError);
  EXPECT_THROW(arap_solve(graph, g.mesh.V, g.mesh.V.topRows(10), held(5)), UsageError);
  EXPECT_EQ(arap_solve(graph, g.mesh.V, g.mesh.V, held(int(g.mesh.V.rows()))), g.mesh.V);
}

}  // namespace
}  // namespace unfold
