// A built-in articulated test shape: a four-legged animal (body, neck, head,
// four two-segment legs, two-segment tail) posed by joint angles, so demos and
// tests need no downloaded data. All poses of one resolution share the same
// connectivity and vertex order: vertex i is the same body point in every pose.
// On request (ShapePose::mouth) the head has a mouth and a lower jaw instead:
// another surface, whose poses share their own connectivity.
#pragma once

#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace unfold {

/// Joint angles of one leg, in degrees.
struct LegPose {
  double hip_swing = 0;  ///< about the hip's left-right axis; > 0 moves the foot forward (+x)
  double hip_spread =
      0;            ///< about the hip's front-back axis; > 0 moves the foot away from the midline
  double knee = 0;  ///< about the knee's left-right axis; > 0 moves the foot backward (-x)
};

/// Degrees the mouth head's lower jaw is open at rest (jaw_pitch 0).
constexpr double kMouthOpenDegrees = 25;

/// Joint angles of the animal, in degrees. The animal faces +x, up is +z and
/// its left side is +y. All zeros is the rest pose: legs straight down, neck
/// and tail straight.
struct ShapePose {
  double neck_pitch = 0;    ///< > 0 raises the neck
  double neck_yaw = 0;      ///< > 0 turns the neck to the left
  double head_pitch = 0;    ///< > 0 raises the head
  double tail_pitch = 0;    ///< > 0 raises the tail
  double tail_yaw = 0;      ///< > 0 swings the tail to the left
  double tail_tip_yaw = 0;  ///< > 0 swings the tail's outer half to the left
  LegPose front_left, front_right, hind_left, hind_right;
  /// The head with a mouth: a slot between the upper and a lower jaw, open by
  /// kMouthOpenDegrees at rest, with a pocket behind the lips. Another surface
  /// (other vertices and faces) than without, so existing users see no change.
  bool mouth = false;
  /// > 0 raises the lower jaw about its hinge (closes the mouth); needs `mouth`.
  double jaw_pitch = 0;

  /// The canonical-looking pose: every angle zero.
  static ShapePose rest();
  /// Clearly different bent poses (30-70 degrees at hips and knees, bent neck
  /// and tail), free of self-intersections.
  /// @param k in [0, num_presets())
  /// @throws UsageError for k out of range
  static ShapePose preset(int k);
  /// Number of presets.
  static int num_presets();
  /// Poses where the body touches itself, as real scans do (docs/method.md,
  /// contact): 0, a hind paw pressed against the belly; 1, the front legs
  /// crossed through each other. Their surfaces intersect themselves.
  /// @param k in [0, num_contact_poses())
  /// @throws UsageError for k out of range
  static ShapePose contact(int k);
  /// Number of contact poses.
  static int num_contact_poses();
  /// The mouth head closed as real scans' mouths are (TOSCA's cats, people):
  /// the jaw raised until the lips touch, pressed slightly into each other
  /// along the front, a thin cavity left behind them; the body at rest. Its
  /// surface intersects itself at the lips; upper and lower lip are near in
  /// space but far apart along the surface.
  static ShapePose closed_mouth();
  /// The mouth head at rest: the mouth open by kMouthOpenDegrees.
  static ShapePose open_mouth();
  /// "rest", a preset index ("0", "1", ...), a contact pose ("contact0",
  /// ...), "mouth" (closed_mouth) or "mouth_open" (open_mouth), as command
  /// lines name poses.
  /// @throws UsageError for any other name
  static ShapePose named(const std::string& name);
};

/// Default `resolution` of make_articulated_shape: about 4000 vertices.
constexpr int kDefaultShapeResolution = 64;

/// The rest shape's surface, meshed from its implicit field (a smooth union
/// of tapered capsules): seconds of work at any resolution (the field is
/// sampled finer than the thinnest limb, then decimated), so make_articulated_shape
/// uses a stored copy where there is one (stored_rest_surfaces()).
/// With `mouth`, the rest surface of the head with a mouth (ShapePose::mouth).
/// @throws UsageError for a resolution out of [16, 128]
SurfaceMesh mesh_articulated_rest_surface(int resolution, bool mouth = false);

/// A rest surface make_articulated_shape does not mesh but reads, bit for bit
/// mesh_articulated_rest_surface(resolution, mouth), from
/// shapes/articulated_rest_surface_[mouth_]<resolution>.inc (checked against it
/// by tests/shape_test.cpp, which also regenerates the file).
struct StoredRestSurface {
  int resolution;
  bool mouth;
};

/// The stored rest surfaces: the default resolution's and those the tests use,
/// so that a test process does not spend seconds meshing.
std::vector<StoredRestSurface> stored_rest_surfaces();

/// The animal in `pose`: a closed, 2-manifold, single-component, outward
/// oriented triangle mesh. The rest shape is a smooth union of tapered capsules
/// meshed once per resolution (mesh_articulated_rest_surface; read where stored,
/// cached for others: later poses are cheap); poses are obtained by skinning
/// (each vertex is rotated about the joints of its skeleton chain by a fraction of each joint
/// angle, fractions blended smoothly across joints), so connectivity and vertex
/// order never depend on the pose. Self-intersection free for the rest pose and
/// presets; large angles may make limbs collide. Deterministic.
/// The mouth head (pose.mouth) is another rest surface, shared by its poses.
/// @param resolution target edge count along the body's length (about
///                   resolution^2 vertices), in [16, 128]
/// @throws UsageError for a resolution out of range, or a jaw_pitch without mouth
SurfaceMesh make_articulated_shape(const ShapePose& pose, int resolution = kDefaultShapeResolution);

}  // namespace unfold
