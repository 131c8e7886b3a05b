// The benchmark's workloads: shape pools (sphere hulls, boxes, a 32-sided
// cylinder) and the pose sets every row of a cell runs on, in the same order.
//
// Pose sets:
//   overlapping  B's centre uniform in the ball of radius 1 around A's
//   separated    B's centre 1 to 2.5 from A's
//   moving       trajectories approaching from a separated pose (32 frames)
//   resting      B resting on A (penetration 0.5% of the extent) with solver
//                noise: independent jitter of 2e-4 rad and 2e-4 units a step
//   sliding      B sliding over A's surface, 0.004 units a step
//   rolling      B rolling over A, 0.01 rad a step about an axis in the
//                contact plane, its centre following 0.01 units a step
//   hovering     B separated from A by a SAT gap of 10% of the extent (beyond
//                the 2% margin), turning 0.01 rad a step about an axis in the
//                plane facing A and drifting 0.004 units a step: pairs a
//                broadphase hands over that stay apart
// The coherent sets (resting, sliding, rolling, hovering) are 120-step
// trajectories whose offset along the contact direction is re-solved at
// every step, so the pair stays in contact (at its gap, hovering).
//
// Every pair has B's pose relative to A (`rel`, double) and world poses of
// both shapes (A at a random world pose, B at world_a * rel).  Pre-posed rows
// get B's vertices posed by `rel` once in double and rounded to float (A stays
// local); posed rows get the world poses rounded to float, one per query.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <sepax/convex_polyhedron.hpp>
#include <sepax/gauss_map_walk.hpp>
#include <sepax/transform.hpp>

#include "random_poses.hpp"

#if __has_include(<sepax/prepared_shape.hpp>)
#include <sepax/prepared_shape.hpp>
#define SEPAX_BENCH_PREPARED 1
#endif

namespace bench {

using sepax::ConvexPolyhedron;

struct WorkloadSpec {
  std::string name;  // "sphere16", "box", "cylinder32", "moving16"
  std::string kind;  // "sphere", "box", "cylinder"
  int n = 0;         // points of a sphere hull; 0 otherwise
};

/// The workloads of a run (N <= 64 only with quick).
std::vector<WorkloadSpec> workloads(bool quick);
/// The pose sets a workload runs: overlapping and separated; moving for the
/// moving workloads; resting, sliding and rolling for sphere hulls of N >= 16
/// and boxes.
std::vector<std::string> pose_sets(const WorkloadSpec& w);

struct Shape {
  ConvexPolyhedron<float> f;
  std::vector<std::vector<int>> faces;
  V3d half_extents = V3d::Zero();  // boxes: the box's half extents
  double extent = 0;               // the largest side of its bounding box
};

struct Pool {
  std::string kind;
  std::vector<Shape> shapes;
  std::vector<ConvexPolyhedron<double>> d;
  std::vector<sepax::GaussMapWalk> walk;  // topology only: serves posed copies too
#if SEPAX_BENCH_PREPARED
  std::vector<std::unique_ptr<sepax::PreparedShape<float>>> prepared;
#endif
};

/// A pool of `count` shapes of one kind, drawn from rng.
void build_pool(Pool& pool, const WorkloadSpec& spec, Rng& rng, int count);

struct PairData {
  int a = 0;  // indices into the pool
  int b = 0;
  Pose rel;                                     // B in A's frame (double)
  Pose world_a;                                 // A's world pose; B's is world_a * rel
  sepax::RigidTransform<float> pose_a, pose_b;  // the world poses rounded to float
  std::vector<V3f> bverts;                      // B posed by rel in double, rounded to float
  ConvexPolyhedron<float> bf;                   // B pre-posed, float
  ConvexPolyhedron<double> bd;                  // same vertices, double
  float margin = 0;                             // speculative margin: 2% of the larger shape's extent
  // exact reference (mpq SAT on A and the pre-posed B)
  bool ref_overlap = false;
  double ref_sep = 0;  // to_double of the exact separation (< 0: penetration depth)
  // exact reference of the posed rows: mpq SAT on A and posed(B, X), X =
  // relative_pose(pose_a, pose_b) (posing.hpp: the input posed queries decide on)
  bool ref_posed_overlap = false;
  double ref_posed_sep = 0;
};

struct Cell {
  std::string workload;  // the WorkloadSpec's name
  int n = 0;
  std::string poses;  // the pose set
  Pool* pool = nullptr;
  std::vector<PairData> pairs;
  int frames = 0;  // trajectories: pairs are `frames` consecutive poses each
};

/// The pairs of one pose set (`pairs` pairs; trajectories for the moving and
/// coherent sets).
void setup_cell(Cell& c, const WorkloadSpec& spec, const std::string& poses, Pool& pool, int pairs);

/// The pre-posed B of a pair: B's local vertices by pose, in double, rounded to float.
std::vector<V3f> pose_vertices(const ConvexPolyhedron<float>& p, const Pose& pose);

inline const ConvexPolyhedron<float>& local_a(const Cell& c, std::size_t i) {
  return c.pool->shapes[static_cast<std::size_t>(c.pairs[i].a)].f;
}
inline const ConvexPolyhedron<float>& local_b(const Cell& c, std::size_t i) {
  return c.pool->shapes[static_cast<std::size_t>(c.pairs[i].b)].f;
}

}  // namespace bench
