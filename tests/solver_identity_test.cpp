// The optimised solver path (Newton polar rotations, CHOLMOD LDL^T, split
// right-hand side) against a straightforward reference kept here: Jacobi SVD
// rotations, Eigen's SimplicialLDLT and the right-hand side as in the paper,
// replayed on the beta schedule the cascade reports. Same output within 1e-9.
#include <gtest/gtest.h>
#include <omp.h>

#include <Eigen/SVD>
#include <Eigen/SparseCholesky>

#include "mesh/edge_graph.h"
#include "mesh/read_surface_mesh.h"
#include "shapes/articulated_shape.h"
#include "solvers/cascade.h"
#include "solvers/fiedler_value.h"
#include "solvers/local_global.h"
#include "test_meshes.h"
#include "test_problem.h"
#include "tetra/tetrahedralize.h"

namespace unfold {
namespace {

Eigen::Matrix3d reference_rotation(const Eigen::Matrix3d& cov) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU();
  if ((svd.matrixV() * U.transpose()).determinant() < 0) U.col(2) *= -1;
  return svd.matrixV() * U.transpose();
}

// Local and global steps exactly as in the paper, serial, one beta per record.
Eigen::MatrixX3d reference_iterations(const EdgeGraph& g, const Eigen::MatrixX3d& P,
                                      const std::vector<IterationRecord>& history) {
  const int n = g.num_vertices;
  const Eigen::SparseMatrix<double> L = graph_laplacian(g);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  Eigen::MatrixX3d Q = P;
  double beta = -1;
  for (const IterationRecord& record : history) {
    if (record.beta != beta) {
      beta = record.beta;
      Eigen::SparseMatrix<double> A = (beta + 1.0) * L;
      A.diagonal().array() -= double(n);
      ldlt.compute(A);
    }
    std::vector<Eigen::Matrix3d> R(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
        const int j = g.neighbors[size_t(k)];
        cov += (P.row(i) - P.row(j)).transpose() * (Q.row(i) - Q.row(j));
      }
      R[size_t(i)] = reference_rotation(cov);
    }
    Eigen::MatrixX3d b(n, 3);
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d bi = Eigen::Vector3d::Zero();
      for (int k = g.offsets[size_t(i)]; k < g.offsets[size_t(i) + 1]; ++k) {
        const int j = g.neighbors[size_t(k)];
        bi += (R[size_t(i)] + R[size_t(j)]) * (P.row(i) - P.row(j)).transpose();
      }
      b.row(i) = 0.5 * beta * bi.transpose();
    }
    Q = ldlt.solve(b);
    Q.rowwise() -= Q.colwise().mean();
  }
  return Q;
}

void expect_same_as_reference(const SurfaceMesh& surface) {
  const test::ProblemFixture f(tetrahedralize(surface, TetOptions{}));
  const EdgeGraph& g = *f.graph;
  const TetMesh& tets = f.mesh;
  CascadeOptions options;
  options.beta = 1.5 * g.num_vertices / fiedler_value(graph_laplacian(g));
  options.anderson = 0;  // plain iterations: the reference replays them one by one
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  LocalGlobalBackend backend(f.problem);
  const CascadeResult result = run_cascade(f.problem, backend, options);
  omp_set_num_threads(threads);
  ASSERT_GT(result.iterations, 1);
  const Eigen::MatrixX3d Q = reference_iterations(g, tets.V, result.history);
  const double scale = Q.cwiseAbs().maxCoeff();
  std::printf("IDENTITY DIFF %.3e\n", (result.positions - Q).cwiseAbs().maxCoeff() / scale);
  EXPECT_LT((result.positions - Q).cwiseAbs().maxCoeff(), 1e-9 * scale)
      << "after " << result.iterations << " iterations on " << g.num_vertices << " vertices";
}

TEST(SolverIdentity, DemoShapeMatchesReferenceImplementation) {
  expect_same_as_reference(make_articulated_shape(ShapePose::preset(0), 32));
}

TEST(SolverIdentity, Wolf0MatchesReferenceImplementation) {
  const std::string path = test::shared_data("tosca/wolf0.off");
  if (path.empty()) GTEST_SKIP() << "shared data absent: tosca/wolf0.off";
  expect_same_as_reference(read_surface_mesh(path));
}

}  // namespace
}  // namespace unfold
