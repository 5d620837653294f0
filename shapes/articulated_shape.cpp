#include "shapes/articulated_shape.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "mesh/edge_graph.h"
#include "shapes/implicit_surface_mesh.h"

namespace unfold {
namespace {

using Eigen::Vector3d;

// Skeleton, parents before children (posing relies on this order). A bone
// rotates about its joint, a rest-pose point inside the parent near where the
// bone leaves it.
enum Bone {
  kBody,
  kNeck,
  kHead,
  kTail,
  kTailTip,
  kFrontLeftUpper,
  kFrontLeftLower,
  kFrontRightUpper,
  kFrontRightLower,
  kHindLeftUpper,
  kHindLeftLower,
  kHindRightUpper,
  kHindRightLower,
  kJaw,  // the mouth head's lower jaw; last, so the plain animal's bones keep their order
  kNumBones
};
const std::array<int, kNumBones> kParent = {-1,
                                            kBody,
                                            kNeck,
                                            kBody,
                                            kTail,
                                            kBody,
                                            kFrontLeftUpper,
                                            kBody,
                                            kFrontRightUpper,
                                            kBody,
                                            kHindLeftUpper,
                                            kBody,
                                            kHindRightUpper,
                                            kHead};

constexpr double kLegX = 0.6, kLegY = 0.25, kHipZ = -0.25, kKneeZ = -0.85, kFootZ = -1.4;

// The mouth head's jaw hinge (an axis along y): both faces of the mouth slot
// are planes through it, the upper one horizontal, so raising the jaw by
// kMouthOpenDegrees lays the lower face onto the upper one.
const Vector3d kHinge(1.5, 0, 0.72);
// ShapePose::closed_mouth's jaw_pitch (degrees).
constexpr double kClosedJawPitch = 30;

Vector3d joint(int bone) {
  switch (bone) {
    case kNeck:
      return {1.0, 0, 0.3};
    case kHead:
      return {1.3, 0, 0.75};
    case kTail:
      return {-1.1, 0, 0.2};
    case kTailTip:
      return {-1.5, 0, 0.4};
    case kJaw:
      return kHinge;
    default:
      break;
  }
  const int leg = (bone - kFrontLeftUpper) / 2;  // 0 FL, 1 FR, 2 HL, 3 HR
  const bool lower = (bone - kFrontLeftUpper) % 2 == 1;
  return {leg < 2 ? kLegX : -kLegX, leg % 2 == 0 ? kLegY : -kLegY, lower ? kKneeZ : kHipZ};
}

// A tapered capsule: radius varies linearly from ra at a to rb at b.
struct Capsule {
  int bone;
  Vector3d a, b;
  double ra, rb;
};

Eigen::Matrix3d rot(double degrees, const Vector3d& axis) {
  return Eigen::AngleAxisd(degrees * M_PI / 180, axis).toRotationMatrix();
}

// The lower jaw's rest position: its closed position turned down about the hinge.
Vector3d open_jaw(const Vector3d& closed) {
  return kHinge + rot(kMouthOpenDegrees, Vector3d::UnitY()) * (closed - kHinge);
}

// The plain animal's parts, or with `mouth` the head with a mouth: cranium,
// upper jaw and lower jaw (open) instead of head and snout. The jaws' cross
// sections on the mouth plane nearly match, so the lips meet all round.
std::vector<Capsule> capsules(bool mouth) {
  std::vector<Capsule> c = {
      {kBody, {-0.8, 0, 0}, {0.8, 0, 0}, 0.4, 0.4},
      {kNeck, joint(kNeck), joint(kHead), 0.18, 0.15},
  };
  if (mouth) {
    c.push_back({kHead, {1.42, 0, 0.82}, {1.42, 0, 0.82}, 0.24, 0.24});
    c.push_back({kHead, {1.48, 0, 0.77}, {1.86, 0, 0.755}, 0.14, 0.1});
    c.push_back({kJaw, open_jaw({1.48, 0, 0.7}), open_jaw({1.84, 0, 0.7}), 0.11, 0.085});
  } else {
    c.push_back({kHead, {1.42, 0, 0.82}, {1.42, 0, 0.82}, 0.24, 0.24});
    c.push_back({kHead, {1.42, 0, 0.82}, {1.8, 0, 0.72}, 0.16, 0.11});
  }
  const std::vector<Capsule> tail = {
      {kTail, joint(kTail), joint(kTailTip), 0.1, 0.085},
      {kTailTip, joint(kTailTip), {-1.9, 0, 0.5}, 0.085, 0.07},
  };
  c.insert(c.end(), tail.begin(), tail.end());
  for (int upper = kFrontLeftUpper; upper <= kHindRightUpper; upper += 2) {
    const Vector3d foot(joint(upper).x(), joint(upper).y(), kFootZ);
    c.push_back({upper, joint(upper), joint(upper + 1), 0.14, 0.12});
    c.push_back({upper + 1, joint(upper + 1), foot, 0.12, 0.1});
  }
  return c;
}

double capsule_distance(const Capsule& c, const Vector3d& x) {
  const Vector3d ab = c.b - c.a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((x - c.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - c.a - t * ab).norm() - (c.ra + t * (c.rb - c.ra));
}

// Polynomial smooth minimum: fillets of width about k where parts meet.
double smooth_min(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k / 4;
}

double smooth_max(double a, double b, double k) { return -smooth_min(-a, -b, k); }

// Signed distance to the mouth slot, in its rest (open) position: a wedge of
// angle kMouthOpenDegrees between two planes through the hinge, infinite
// along y and forward, its back rounded to a radius of kSlotRadius so the slot
// never gets thinner than the marching grid resolves (a thinner slit would
// break up into bubbles).
double mouth_slot_distance(const Vector3d& x) {
  constexpr double kSlotRadius = 0.035;
  const double half = kMouthOpenDegrees / 2 * M_PI / 180;
  // In the x-z plane: u along the bisector (forward, down), v across it.
  const Eigen::Vector2d b(std::cos(half), -std::sin(half)), n(std::sin(half), std::cos(half));
  // The sharp wedge whose offset by kSlotRadius has its faces through the hinge.
  const Eigen::Vector2d p(x.x() - kHinge.x(), x.z() - kHinge.z());
  const double u = p.dot(b) - kSlotRadius / std::sin(half), v = std::abs(p.dot(n));
  const double along_face = u * std::cos(half) + v * std::sin(half);
  const double d = along_face < 0 ? std::hypot(u, v) : v * std::cos(half) - u * std::sin(half);
  return d - kSlotRadius;
}

// Signed distance (approximate) to the pocket carved behind the lips: a
// flattened ellipsoid on the slot's bisector, deeper than the slot, so that
// with the jaw closed a thin cavity remains inside the ring where the lips touch.
double mouth_pocket_distance(const Vector3d& x) {
  const double half = kMouthOpenDegrees / 2 * M_PI / 180;
  const Vector3d b(std::cos(half), 0, -std::sin(half)), n(std::sin(half), 0, std::cos(half));
  const Vector3d p = x - (kHinge + 0.22 * b);
  const Vector3d radii(0.11, 0.055, 0.075);
  const Vector3d q(p.dot(b) / radii.x(), p.y() / radii.y(), p.dot(n) / radii.z());
  return (q.norm() - 1) * radii.minCoeff();
}

struct RestShape {
  SurfaceMesh mesh;
  // alpha(i, b): fraction of bone b's joint rotation applied to vertex i.
  Eigen::MatrixXd alpha;
};

void check_resolution(int resolution) {
  if (resolution < 16 || resolution > 128)
    throw UsageError("make_articulated_shape: resolution " + std::to_string(resolution) +
                     " is not in [16, 128]");
}

// The field's box and the target edge length of a resolution.
struct RestGrid {
  Eigen::AlignedBox3d box;
  double edge;
};

RestGrid rest_grid(const std::vector<Capsule>& parts, int resolution) {
  RestGrid grid;
  for (const Capsule& c : parts) {
    const Vector3d r = Vector3d::Constant(std::max(c.ra, c.rb));
    grid.box.extend(Vector3d(c.a - r)).extend(Vector3d(c.a + r));
    grid.box.extend(Vector3d(c.b - r)).extend(Vector3d(c.b + r));
  }
  grid.edge = grid.box.sizes().x() / resolution;
  grid.box.min().array() -= 2 * grid.edge;
  grid.box.max().array() += 2 * grid.edge;
  return grid;
}

// A rest surface stored in shapes/articulated_rest_surface_*.inc: each
// coordinate's bits, then the triangles.
template <size_t NumCoordinates, size_t NumCorners>
SurfaceMesh stored_surface(const uint64_t (&vertex_bits)[NumCoordinates],
                           const int (&triangles)[NumCorners]) {
  SurfaceMesh mesh;
  mesh.V.resize(Eigen::Index(NumCoordinates / 3), 3);
  for (size_t k = 0; k < NumCoordinates; ++k) {
    double x;
    std::memcpy(&x, &vertex_bits[k], sizeof x);
    mesh.V(Eigen::Index(k / 3), Eigen::Index(k % 3)) = x;
  }
  for (size_t k = 0; k < NumCorners; k += 3)
    mesh.faces.push_back({triangles[k], triangles[k + 1], triangles[k + 2]});
  return mesh;
}

// One function a file: each file's arrays have the same names.
SurfaceMesh stored_16() {
#include "shapes/articulated_rest_surface_16.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_20() {
#include "shapes/articulated_rest_surface_20.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_24() {
#include "shapes/articulated_rest_surface_24.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_32() {
#include "shapes/articulated_rest_surface_32.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_40() {
#include "shapes/articulated_rest_surface_40.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_64() {
  static_assert(kDefaultShapeResolution == 64, "the default's rest surface is stored");
#include "shapes/articulated_rest_surface_64.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}
SurfaceMesh stored_mouth_48() {
#include "shapes/articulated_rest_surface_mouth_48.inc"
  return stored_surface(kRestVertexBits, kRestTriangles);
}

struct StoredSurface {
  StoredRestSurface key;
  SurfaceMesh (*mesh)();
};
const StoredSurface kStoredSurfaces[] = {
    {{16, false}, stored_16},      {{20, false}, stored_20}, {{24, false}, stored_24},
    {{32, false}, stored_32},      {{40, false}, stored_40}, {{64, false}, stored_64},
    {{48, true}, stored_mouth_48},
};

RestShape build_rest_shape(int resolution, bool mouth) {
  const std::vector<Capsule> parts = capsules(mouth);
  const double edge = rest_grid(parts, resolution).edge;
  RestShape rest;
  const auto stored = std::find_if(
      std::begin(kStoredSurfaces), std::end(kStoredSurfaces),
      [&](const auto& s) { return s.key.resolution == resolution && s.key.mouth == mouth; });
  rest.mesh = stored != std::end(kStoredSurfaces)
                  ? stored->mesh()
                  : mesh_articulated_rest_surface(resolution, mouth);
  const int n = int(rest.mesh.V.rows());

  // Skinning weights: each vertex starts fully on the bone of its nearest
  // part; diffusing these labels over the mesh blends them across joints over
  // about kBlend, so bent joints stay smooth instead of creasing.
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, kNumBones);
  for (int i = 0; i < n; ++i) {
    const Vector3d x = rest.mesh.V.row(i).transpose();
    size_t best = 0;
    for (size_t k = 1; k < parts.size(); ++k)
      if (capsule_distance(parts[k], x) < capsule_distance(parts[best], x)) best = k;
    w(i, parts[best].bone) = 1;
  }
  const Eigen::MatrixX3i F = triangulate_faces(rest.mesh);
  const EdgeGraph graph = build_edge_graph(n, F);
  constexpr double kBlend = 0.25;
  const int steps = int(std::lround(std::pow(kBlend / edge, 2)));
  for (int s = 0; s < steps; ++s) {
    Eigen::MatrixXd next = w;
    for (int i = 0; i < n; ++i) {
      for (int k = graph.offsets[size_t(i)]; k < graph.offsets[size_t(i) + 1]; ++k)
        next.row(i) += w.row(graph.neighbors[size_t(k)]);
      next.row(i) /= double(graph.degree(i) + 1);
    }
    w = next;
  }
  // A joint moves everything below it: its fraction is the weight of its subtree.
  rest.alpha = w;
  for (int b = kNumBones - 1; b > 0; --b) rest.alpha.col(kParent[size_t(b)]) += rest.alpha.col(b);
  return rest;
}

// The rotation of each bone about its joint, relative to its parent.
std::array<Eigen::AngleAxisd, kNumBones> joint_rotations(const ShapePose& p) {
  const Vector3d X = Vector3d::UnitX(), Y = Vector3d::UnitY(), Z = Vector3d::UnitZ();
  std::array<Eigen::Matrix3d, kNumBones> R;
  R[kBody] = Eigen::Matrix3d::Identity();
  R[kNeck] = rot(p.neck_yaw, Z) * rot(p.neck_pitch, -Y);
  R[kHead] = rot(p.head_pitch, -Y);
  R[kTail] = rot(p.tail_yaw, -Z) * rot(p.tail_pitch, Y);
  R[kTailTip] = rot(p.tail_tip_yaw, -Z);
  R[kJaw] = rot(p.jaw_pitch, -Y);
  const std::array<const LegPose*, 4> legs = {&p.front_left, &p.front_right, &p.hind_left,
                                              &p.hind_right};
  for (int leg = 0; leg < 4; ++leg) {
    const Vector3d outward = leg % 2 == 0 ? X : Vector3d(-X);
    const int upper = kFrontLeftUpper + 2 * leg;
    R[size_t(upper)] =
        rot(legs[size_t(leg)]->hip_swing, -Y) * rot(legs[size_t(leg)]->hip_spread, outward);
    R[size_t(upper) + 1] = rot(legs[size_t(leg)]->knee, Y);
  }
  std::array<Eigen::AngleAxisd, kNumBones> result;
  for (size_t b = 0; b < R.size(); ++b) result[b] = Eigen::AngleAxisd(R[b]);
  return result;
}

}  // namespace

SurfaceMesh mesh_articulated_rest_surface(int resolution, bool mouth) {
  check_resolution(resolution);
  const std::vector<Capsule> parts = capsules(mouth);
  const ImplicitFunction field = [&parts, mouth](const Vector3d& x) {
    double d = std::numeric_limits<double>::infinity();
    for (const Capsule& c : parts) d = smooth_min(d, capsule_distance(c, x), 0.06);
    if (mouth) {
      // Carved out: the slot between the jaws and the pocket behind the lips.
      constexpr double kFillet = 0.03;
      d = smooth_max(d, -mouth_slot_distance(x), kFillet);
      d = smooth_max(d, -mouth_pocket_distance(x), kFillet);
    }
    return d;
  };
  const RestGrid grid = rest_grid(parts, resolution);
  // The thinnest part (tail tip, radius 0.07) needs a few grid cells across.
  const double spacing = std::min(grid.edge / 2.5, 0.028);
  return mesh_implicit_surface(field, grid.box, grid.edge, spacing);
}

std::vector<StoredRestSurface> stored_rest_surfaces() {
  std::vector<StoredRestSurface> keys;
  for (const StoredSurface& s : kStoredSurfaces) keys.push_back(s.key);
  return keys;
}

ShapePose ShapePose::rest() { return ShapePose(); }

int ShapePose::num_presets() { return 3; }

ShapePose ShapePose::named(const std::string& name) {
  if (name == "rest") return rest();
  if (name == "mouth") return closed_mouth();
  if (name == "mouth_open") return open_mouth();
  for (int k = 0; k < num_presets(); ++k)
    if (name == std::to_string(k)) return preset(k);
  for (int k = 0; k < num_contact_poses(); ++k)
    if (name == "contact" + std::to_string(k)) return contact(k);
  throw UsageError("unknown pose '" + name + "' (use rest, a preset index 0.." +
                   std::to_string(num_presets() - 1) + ", contact0..contact" +
                   std::to_string(num_contact_poses() - 1) + ", mouth or mouth_open)");
}

int ShapePose::num_contact_poses() { return 2; }

ShapePose ShapePose::closed_mouth() {
  ShapePose p;
  p.mouth = true;
  // More than kMouthOpenDegrees: the skinning weights blend the jaw into the
  // head near the hinge, and the lips are to press slightly into each other.
  p.jaw_pitch = kClosedJawPitch;
  return p;
}

ShapePose ShapePose::open_mouth() {
  ShapePose p;
  p.mouth = true;
  return p;
}

ShapePose ShapePose::contact(int k) {
  ShapePose p;
  switch (k) {
    case 0:  // lying down: left hind leg brought forward, its paw pressed against the belly
      p.neck_pitch = 10, p.head_pitch = -15, p.tail_pitch = -15, p.tail_yaw = 20;
      p.hind_left = {60, 0, -48};
      p.front_left = {20, 0, 30};
      break;
    case 1:  // front legs crossed through each other, head turned
      p.neck_yaw = -25, p.head_pitch = 10, p.tail_yaw = -30, p.tail_tip_yaw = 30;
      p.front_left = {0, -25, 10};
      p.front_right = {10, -25, 0};
      p.hind_left = {-15, 5, -20};
      break;
    default:
      throw UsageError("ShapePose::contact: k = " + std::to_string(k) + " is not in [0, " +
                       std::to_string(num_contact_poses()) + ")");
  }
  return p;
}

ShapePose ShapePose::preset(int k) {
  ShapePose p;
  switch (k) {
    case 0:  // walking: left legs forward, right legs back, head down
      p.neck_pitch = -15, p.neck_yaw = 20, p.head_pitch = -20;
      p.tail_pitch = 30, p.tail_yaw = 25, p.tail_tip_yaw = 35;
      p.front_left = {35, 0, 50};
      p.front_right = {-30, 5, -35};
      p.hind_left = {30, 5, 45};
      p.hind_right = {-35, 0, -50};
      break;
    case 1:  // crouching: front legs reaching forward, hind legs back, head up
      p.neck_pitch = 25, p.neck_yaw = -30, p.head_pitch = 25;
      p.tail_pitch = -20, p.tail_yaw = -40, p.tail_tip_yaw = -45;
      p.front_left = {45, 10, 65};
      p.front_right = {40, 15, 60};
      p.hind_left = {-30, 10, -60};
      p.hind_right = {-35, 15, -55};
      break;
    case 2:  // galloping: legs stretched fore and aft, tail curled up
      p.neck_pitch = 10, p.neck_yaw = 35, p.head_pitch = -10;
      p.tail_pitch = 40, p.tail_yaw = -20, p.tail_tip_yaw = 50;
      p.front_left = {40, 5, 30};
      p.front_right = {40, 10, 60};
      p.hind_left = {-40, 10, -30};
      p.hind_right = {-30, 5, -65};
      break;
    default:
      throw UsageError("ShapePose::preset: k = " + std::to_string(k) + " is not in [0, " +
                       std::to_string(num_presets()) + ")");
  }
  return p;
}

SurfaceMesh make_articulated_shape(const ShapePose& pose, int resolution) {
  check_resolution(resolution);
  if (pose.jaw_pitch != 0 && !pose.mouth)
    throw UsageError("make_articulated_shape: jaw_pitch needs the head with a mouth (mouth)");
  // Meshing the rest shape dominates the cost; poses of one resolution share it.
  static std::mutex mutex;
  static std::map<std::pair<int, bool>, std::shared_ptr<const RestShape>> cache;
  std::shared_ptr<const RestShape> cached;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    auto& slot = cache[{resolution, pose.mouth}];
    if (!slot) slot = std::make_shared<const RestShape>(build_rest_shape(resolution, pose.mouth));
    cached = slot;
  }
  const RestShape& rest = *cached;
  const std::array<Eigen::AngleAxisd, kNumBones> R = joint_rotations(pose);
  SurfaceMesh posed = rest.mesh;
  for (Eigen::Index i = 0; i < posed.V.rows(); ++i) {
    Vector3d x = posed.V.row(i).transpose();
    // Children first: a knee turns the lower leg about the rest knee, then the
    // hip turns the result about the hip (forward kinematics, blended).
    for (int b = kNumBones - 1; b > 0; --b) {
      const double a = rest.alpha(i, b);
      if (a == 0) continue;
      const Vector3d J = joint(b);
      x = J + Eigen::AngleAxisd(a * R[size_t(b)].angle(), R[size_t(b)].axis()) * (x - J);
    }
    posed.V.row(i) = x.transpose();
  }
  return posed;
}

}  // namespace unfold
