#include "shapes/implicit_surface_mesh.h"

// OpenMesh's property arrays value-initialise VectorT, which GCC flags as a
// maybe-uninitialized read inside the library's headers.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#pragma GCC diagnostic pop
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/errors.h"

namespace unfold {
namespace {

struct Triangles {
  std::vector<Eigen::Vector3d> V;
  std::vector<std::array<int, 3>> F;
};

// Marching tetrahedra over the Kuhn split of each grid cube (6 tets around the
// main diagonal). The split is translation invariant, so neighbouring cubes
// agree on face diagonals, and vertices on grid edges are shared through an
// edge key: the surface is the level set of a piecewise linear field on a
// simplicial complex, hence closed and manifold.
Triangles marching_tetrahedra(const ImplicitFunction& f, const Eigen::Vector3d& origin, double h,
                              const Eigen::Vector3i& cells) {
  const Eigen::Vector3i n = cells.array() + 1;
  const auto index = [&](int i, int j, int k) {
    return int64_t(i) + n.x() * (j + int64_t(n.y()) * k);
  };
  const auto point = [&](int64_t g) {
    const int64_t i = g % n.x(), j = (g / n.x()) % n.y(), k = g / (int64_t(n.x()) * n.y());
    return Eigen::Vector3d(origin + h * Eigen::Vector3d(double(i), double(j), double(k)));
  };
  std::vector<double> value(size_t(n.prod()));
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        const int64_t g = index(i, j, k);
        double v = f(point(g));
        // A zero at a grid point would put a surface vertex on it and create
        // degenerate triangles; nudging it outside keeps the topology valid.
        if (std::abs(v) < 1e-9 * h) v = 1e-9 * h;
        value[size_t(g)] = v;
      }

  Triangles out;
  std::unordered_map<uint64_t, int> edge_vertex;
  const auto vertex_on = [&](int64_t a, int64_t b) {
    if (a > b) std::swap(a, b);
    const uint64_t key = uint64_t(a) * uint64_t(n.prod()) + uint64_t(b);
    const auto it = edge_vertex.find(key);
    if (it != edge_vertex.end()) return it->second;
    const double va = value[size_t(a)], vb = value[size_t(b)];
    out.V.push_back(point(a) + (va / (va - vb)) * (point(b) - point(a)));
    edge_vertex.emplace(key, int(out.V.size()) - 1);
    return int(out.V.size()) - 1;
  };
  // Orientation from the grid corners alone (exact): det > 0 means the
  // triangle (b, c, d) faces away from a.
  const auto faces_away = [&](int64_t a, int64_t b, int64_t c, int64_t d) {
    const Eigen::Vector3d pa = point(a);
    Eigen::Matrix3d M;
    M << point(b) - pa, point(c) - pa, point(d) - pa;
    return M.determinant() > 0;
  };
  const auto emit = [&](int a, int b, int c, bool keep) {
    out.F.push_back(keep ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, b});
  };
  static const int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < cells.z(); ++k)
    for (int j = 0; j < cells.y(); ++j)
      for (int i = 0; i < cells.x(); ++i)
        for (const auto& perm : kPerm) {
          std::array<int64_t, 4> t;
          Eigen::Vector3i c(i, j, k);
          t[0] = index(c.x(), c.y(), c.z());
          for (int s = 0; s < 3; ++s) {
            ++c[perm[s]];
            t[size_t(s) + 1] = index(c.x(), c.y(), c.z());
          }
          std::vector<int64_t> in, outside;
          for (const int64_t g : t) (value[size_t(g)] < 0 ? in : outside).push_back(g);
          if (in.size() == 1) {
            const int64_t a = in[0];
            emit(vertex_on(a, outside[0]), vertex_on(a, outside[1]), vertex_on(a, outside[2]),
                 faces_away(a, outside[0], outside[1], outside[2]));
          } else if (in.size() == 3) {
            const int64_t o = outside[0];
            emit(vertex_on(o, in[0]), vertex_on(o, in[1]), vertex_on(o, in[2]),
                 !faces_away(o, in[0], in[1], in[2]));
          } else if (in.size() == 2) {
            // The level set in a tet is a planar convex quad; its orientation
            // equals that of the midpoint quad, (d - c) x (b - a) against c + d - a - b.
            const int64_t a = in[0], b = in[1], cc = outside[0], d = outside[1];
            const Eigen::Vector3d pa = point(a), pb = point(b), pc = point(cc), pd = point(d);
            const bool keep = (pd - pc).cross(pb - pa).dot(pc + pd - pa - pb) > 0;
            const int q0 = vertex_on(a, cc), q1 = vertex_on(a, d), q2 = vertex_on(b, d),
                      q3 = vertex_on(b, cc);
            emit(q0, q1, q2, keep);
            emit(q0, q2, q3, keep);
          }
        }
  return out;
}

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

Eigen::Vector3d gradient(const ImplicitFunction& f, const Eigen::Vector3d& x, double step) {
  Eigen::Vector3d g;
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    d[a] = step;
    g[a] = (f(x + d) - f(x - d)) / (2 * step);
  }
  return g;
}

Eigen::Vector3d to_eigen(const OMesh::Point& p) { return {p[0], p[1], p[2]}; }
OMesh::Point to_om(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

// Newton steps onto f = 0 along the gradient.
Eigen::Vector3d project(const ImplicitFunction& f, Eigen::Vector3d x, double step) {
  for (int newton = 0; newton < 3; ++newton) {
    const Eigen::Vector3d g = gradient(f, x, step);
    x -= f(x) / g.squaredNorm() * g;
  }
  return x;
}

// Quadric edge collapses (topology-preserving: OpenMesh checks the link
// condition) down to `target` vertices; the aspect-ratio and normal-flip
// modules veto collapses that would create needles or fold the surface.
void decimate(size_t target, OMesh* mesh) {
  OpenMesh::Decimater::DecimaterT<OMesh> decimater(*mesh);
  OpenMesh::Decimater::ModQuadricT<OMesh>::Handle quadric;
  OpenMesh::Decimater::ModAspectRatioT<OMesh>::Handle aspect;
  OpenMesh::Decimater::ModNormalFlippingT<OMesh>::Handle flipping;
  decimater.add(quadric);
  decimater.add(aspect);
  decimater.add(flipping);
  decimater.module(quadric).unset_max_err();
  decimater.module(aspect).set_aspect_ratio(10.0f);
  decimater.module(flipping).set_max_normal_deviation(45.0);
  decimater.initialize();
  decimater.decimate_to(target);
  mesh->garbage_collection();
}

// True if moving vertex v to p keeps every face around v (except those in
// `skip`) facing within 60 degrees of its current normal.
bool move_keeps_normals(const OMesh& mesh, OMesh::VertexHandle v, const OMesh::Point& p,
                        OMesh::FaceHandle skip0, OMesh::FaceHandle skip1) {
  for (const auto fh : mesh.vf_range(v)) {
    if (fh == skip0 || fh == skip1) continue;
    std::array<OMesh::Point, 3> before, after;
    int a = 0;
    for (const auto w : mesh.fv_range(fh)) {
      before[size_t(a)] = mesh.point(w);
      after[size_t(a++)] = w == v ? p : mesh.point(w);
    }
    const OMesh::Point n0 = (before[1] - before[0]) % (before[2] - before[0]);
    const OMesh::Point n1 = (after[1] - after[0]) % (after[2] - after[0]);
    if ((n0 | n1) <= 0.5 * n0.norm() * n1.norm()) return false;
  }
  return true;
}

// Isotropic remeshing (Botsch & Kobbelt 2004) towards edge length e: split
// long edges, collapse short ones, flip towards valence 6, then smooth
// tangentially and project onto f = 0. Evens out the long thin triangles
// quadric decimation leaves along tubes.
void remesh(const ImplicitFunction& f, double e, int iterations, OMesh* mesh) {
  const double lo = 0.8 * e, hi = 4.0 / 3.0 * e, step = 1e-4 * e;
  for (int it = 0; it < iterations; ++it) {
    // Passes over the edges present at the start of each pass; a long edge
    // halves per pass, so a handful of passes suffice (capped for safety).
    for (int pass = 0, splits = 1; pass < 20 && splits > 0; ++pass) {
      const int num_edges = int(mesh->n_edges());
      splits = 0;
      for (int k = 0; k < num_edges; ++k) {
        const OMesh::EdgeHandle eh(k);
        if (mesh->calc_edge_length(eh) <= hi) continue;
        const auto h = mesh->halfedge_handle(eh, 0);
        const Eigen::Vector3d mid = 0.5 * (to_eigen(mesh->point(mesh->from_vertex_handle(h))) +
                                           to_eigen(mesh->point(mesh->to_vertex_handle(h))));
        mesh->split(eh, to_om(project(f, mid, step)));
        ++splits;
      }
    }
    for (int k = 0; k < int(mesh->n_edges()); ++k) {
      const OMesh::EdgeHandle eh(k);
      if (mesh->status(eh).deleted() || mesh->calc_edge_length(eh) >= lo) continue;
      const auto h = mesh->halfedge_handle(eh, 0);
      const auto v0 = mesh->from_vertex_handle(h), v1 = mesh->to_vertex_handle(h);
      const OMesh::Point p1 = mesh->point(v1);
      bool ok = mesh->is_collapse_ok(h);
      for (const auto w : mesh->vv_range(v0)) ok = ok && (mesh->point(w) - p1).norm() <= hi;
      if (ok && move_keeps_normals(*mesh, v0, p1, mesh->face_handle(h),
                                   mesh->face_handle(mesh->opposite_halfedge_handle(h))))
        mesh->collapse(h);
    }
    mesh->garbage_collection();
    for (const auto eh : mesh->edges()) {
      const auto h0 = mesh->halfedge_handle(eh, 0), h1 = mesh->halfedge_handle(eh, 1);
      const auto a = mesh->to_vertex_handle(h0), b = mesh->to_vertex_handle(h1);
      const auto c = mesh->to_vertex_handle(mesh->next_halfedge_handle(h0));
      const auto d = mesh->to_vertex_handle(mesh->next_halfedge_handle(h1));
      const auto deviation = [&](int da, int db, int dc, int dd) {
        const auto sq = [&](OMesh::VertexHandle v, int delta) {
          const int x = int(mesh->valence(v)) + delta - 6;
          return x * x;
        };
        return sq(a, da) + sq(b, db) + sq(c, dc) + sq(d, dd);
      };
      if (deviation(-1, -1, 1, 1) >= deviation(0, 0, 0, 0) || !mesh->is_flip_ok(eh)) continue;
      // The new edge c-d must not fold the surface: both new triangles keep
      // facing the way the old pair did.
      const OMesh::Point pa = mesh->point(a), pb = mesh->point(b), pc = mesh->point(c),
                         pd = mesh->point(d);
      const OMesh::Point n = (pb - pa) % (pc - pa) + (pa - pb) % (pd - pb);
      const OMesh::Point n1 = (pd - pc) % (pa - pc), n2 = (pc - pd) % (pb - pd);
      if ((n | n1) <= 0.5 * n.norm() * n1.norm() || (n | n2) <= 0.5 * n.norm() * n2.norm())
        continue;
      mesh->flip(eh);
    }
    std::vector<OMesh::Point> next(mesh->n_vertices());
#pragma omp parallel for schedule(static)
    for (int i = 0; i < int(mesh->n_vertices()); ++i) {
      const OMesh::VertexHandle v(i);
      const Eigen::Vector3d x = to_eigen(mesh->point(v));
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (const auto w : mesh->vv_range(v)) mean += to_eigen(mesh->point(w));
      mean /= double(mesh->valence(v));
      const Eigen::Vector3d normal = gradient(f, x, step).normalized();
      const Eigen::Vector3d d = mean - x;
      next[size_t(i)] = to_om(project(f, x + 0.5 * (d - d.dot(normal) * normal), step));
    }
    for (const auto v : mesh->vertices()) mesh->set_point(v, next[size_t(v.idx())]);
  }
}

}  // namespace

SurfaceMesh mesh_implicit_surface(const ImplicitFunction& f, const Eigen::AlignedBox3d& box,
                                  double edge_length, double grid_spacing) {
  if (!(grid_spacing > 0) || !(grid_spacing <= edge_length))
    throw UsageError("mesh_implicit_surface: need 0 < grid_spacing <= edge_length");
  const Eigen::Array3d extent = (box.diagonal() / grid_spacing).array().ceil().max(1.0);
  if (!((extent + 1).prod() <= 1e8))
    throw UsageError("mesh_implicit_surface: grid_spacing too small for the box");
  // The grid may be finer than the target edge so thin tubes keep their
  // topology; decimation then brings the vertex count down.
  const double h = grid_spacing;
  const Eigen::Vector3i cells = extent.cast<int>();
  const Triangles tri = marching_tetrahedra(f, box.min(), h, cells);
  if (tri.F.empty()) throw UsageError("mesh_implicit_surface: the level set is empty in the box");
  double area = 0;
  for (const auto& t : tri.F)
    area += 0.5 * (tri.V[size_t(t[1])] - tri.V[size_t(t[0])])
                      .cross(tri.V[size_t(t[2])] - tri.V[size_t(t[0])])
                      .norm();
  // An equilateral closed mesh with edge e has about 2A / (sqrt(3) e^2) vertices.
  const size_t target =
      size_t(std::lround(2 * area / (std::sqrt(3.0) * edge_length * edge_length)));
  OMesh mesh;
  std::vector<OMesh::VertexHandle> vh;
  vh.reserve(tri.V.size());
  for (const auto& p : tri.V) vh.push_back(mesh.add_vertex(to_om(p)));
  for (const auto& t : tri.F) mesh.add_face(vh[size_t(t[0])], vh[size_t(t[1])], vh[size_t(t[2])]);
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  mesh.request_face_normals();
  mesh.update_face_normals();
  decimate(target, &mesh);
  remesh(f, edge_length, 8, &mesh);

  SurfaceMesh result;
  result.V.resize(Eigen::Index(mesh.n_vertices()), 3);
  for (const auto v : mesh.vertices()) result.V.row(v.idx()) = to_eigen(mesh.point(v)).transpose();
  result.faces.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces()) {
    std::vector<int> face;
    for (const auto v : mesh.fv_range(fh)) face.push_back(v.idx());
    result.faces.push_back(face);
  }
  return result;
}

}  // namespace unfold
