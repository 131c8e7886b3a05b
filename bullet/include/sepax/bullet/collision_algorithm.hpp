// sepax/bullet/collision_algorithm.hpp
//
// sepax inside Bullet: a btCollisionAlgorithm for pairs of convex polyhedra
// (btBoxShape, btConvexHullShape, btConvexPointCloudShape) that Bullet's
// dispatcher uses in place of its own convex-convex and box-box algorithms.
//
//   btDefaultCollisionConfiguration config;
//   btCollisionDispatcher dispatcher(&config);
//   sepax::bullet::CreateFunc sepax_cf(config);       // outlives the world
//   sepax::bullet::register_algorithm(dispatcher, sepax_cf);
//
// Per pair and step (CollisionAlgorithm): the posed robust traversal SAT with
// the contact breaking threshold as the speculative margin and a per-pair
// cache, then sepax's manifold written into the pair's btPersistentManifold
// with sepax's feature ids.  Shapes are prepared once per btCollisionShape*
// (ShapeCache); shapes sepax refuses go to Bullet's own algorithm for the
// pair (CreateFunc).  docs/bullet.md has the whole story.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include <BulletCollision/BroadphaseCollision/btCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionConfiguration.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>

class btCollisionShape;
class btPersistentManifold;

namespace sepax::bullet {

/// A prepared hull (sepax::PreparedShape<float>, opaque here so that users of
/// this header need neither sepax's robust headers nor CGAL).
struct Prepared;

/// True for the Bullet shape types the algorithm handles.
bool is_supported(int shape_type);

/// The key a prepared shape is checked against at every step (see ShapeCache).
struct ShapeKey {
  int type = -1;
  float scaling[3] = {0, 0, 0};
  float size[3] = {0, 0, 0};     // box: half extents with margin
  const void* points = nullptr;  // hull / point cloud: the point array
  int point_count = 0;
  friend bool operator==(const ShapeKey&, const ShapeKey&) = default;
};

/// The key of a supported shape (type -1 for an unsupported one).
ShapeKey shape_key(const btCollisionShape& shape);

/// One PreparedShape per btCollisionShape*.
/// Shapes are prepared once: CreateFunc keeps one PreparedShape per
/// btCollisionShape* (ShapeCache), shared by every pair using that shape.  The
/// cache compares each shape's type, local scaling and size data (half extents;
/// point count and point array) at every step, so a shape rescaled or resized
/// in place is prepared again; a shape whose points are edited in place, or a
/// shape deleted while another is allocated at its address with equal data,
/// must be dropped with ShapeCache::forget.  A shape sepax refuses (a flat or
/// degenerate hull: InvalidInput) is handed to the algorithm Bullet's
/// configuration had for that pair, which the CreateFunc keeps.
class ShapeCache {
 public:
  ShapeCache();
  ~ShapeCache();
  ShapeCache(const ShapeCache&) = delete;
  ShapeCache& operator=(const ShapeCache&) = delete;

  /// The prepared hull of `shape` with key `key`, prepared now if the cache
  /// holds none or one with another key.  Throws sepax::InvalidInput when
  /// sepax refuses the shape (its ErrorCode and message).
  std::shared_ptr<const Prepared> get(const btCollisionShape& shape, const ShapeKey& key);
  /// Drops the entry of `shape` (after editing its points in place or before
  /// reusing its address).
  void forget(const btCollisionShape* shape);
  std::size_t size() const;
  /// Shapes prepared so far (a re-preparation counts again).
  std::int64_t preparations() const;

 private:
  struct Entry {
    ShapeKey key;
    std::shared_ptr<const Prepared> prepared;
  };
  mutable std::mutex mutex_;
  std::unordered_map<const btCollisionShape*, Entry> entries_;
  std::int64_t preparations_ = 0;
};

/// Counters over every pair of one CreateFunc (a snapshot; the live
/// counters are atomic, so a multithreaded dispatcher may update them).
struct Counters {
  std::int64_t queries = 0;         // SAT queries run
  std::int64_t early_outs = 0;      // queries that stopped beyond the margin
  std::int64_t culled = 0;          // steps of pairs whose bounding spheres are beyond the margin (no query)
  std::int64_t kept = 0;            // steps that re-evaluated the kept face instead of a query
  std::int64_t refreshed = 0;       // of those, manifolds refreshed (no support-vertex fallback)
  std::int64_t reduced = 0;         // of those, clips that left more than four points (reduced to four)
  std::int64_t kept_apart = 0;      // steps still beyond the margin by the last query's answer (no query)
  std::int64_t manifolds = 0;       // manifolds built
  std::int64_t points = 0;          // points written
  std::int64_t id_matches = 0;      // points that replaced the point with their ids
  std::int64_t errors = 0;          // queries sepax refused (InvalidInput): manifold cleared
  std::int64_t fallback_pairs = 0;  // pairs handed to Bullet's algorithm at creation
  std::string last_error;
};

/// The algorithm for one pair (created by CreateFunc).
/// Per pair and step the algorithm runs the posed robust traversal SAT
/// (float, sat::traversal<policy::Robust>) on the two shapes' prepared hulls
/// at the bodies' world transforms, with
///   * Bullet's contact breaking threshold of the pair's manifold as the
///     speculative margin (SatOptions::margin with early_out): a pair farther
///     apart than that stops at the first axis proven to separate by more;
///   * a per-pair SatCache (warm start);
///   * sepax's contact manifold (at most four points, within the margin).
/// The points go into the pair's btPersistentManifold with sepax's feature ids
/// (contact_feature.hpp) as Bullet's part/index ids: m_partId = the feature's
/// kind (1 vertex, 2 edge, 3 face), m_index = its index, for each body.  A new
/// point whose ids equal those of a point already in the manifold replaces it
/// (btPersistentManifold::replaceContactPoint keeps the accumulated impulses,
/// Bullet's warm start).  A new point whose ids no stored point has replaces,
/// as btPersistentManifold::getCacheEntry does, the nearest remaining stored
/// point within the contact breaking threshold (the same place named by
/// another feature keeps its impulse); stored points no new point took are
/// removed.  The manifold written here is always complete, so
/// refreshContactPoints has nothing to add and is not called.
/// Friction, restitution, rolling/spinning friction, contact stiffness and
/// damping, friction anchors and the contact callbacks are set as
/// btManifoldResult::addContactPoint sets them.
///
/// Collision margin.  The geometry is the one btPolyhedralContactClipping (Bullet's
/// own SAT, btConvexConvexAlgorithm's polyhedral path) collides: a box is its
/// full half extents (btBoxShape::getHalfExtentsWithMargin: Bullet's box margin
/// is inside the box), a hull is its scaled points as given (its margin, which
/// GJK adds around the points, is not added).  The margin only enters through
/// the contact breaking threshold (the speculative margin).
class CollisionAlgorithm : public btActivatingCollisionAlgorithm {
 public:
  CollisionAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                     const btCollisionObjectWrapper* body1, class CreateFunc& owner);
  ~CollisionAlgorithm() override;

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override;
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return btScalar(1);
  }
  void getAllContactManifolds(btManifoldArray& out) override;

 private:
  struct State;
  CreateFunc& owner_;
  btPersistentManifold* manifold_ = nullptr;
  std::unique_ptr<State> state_;
};

/// Creates CollisionAlgorithm for supported pairs; keeps the shape cache, the
/// counters and the configuration's own create functions (the fallback for
/// shapes sepax refuses).  Must outlive every world using it.
/// Threads: CreateFunc's cache is guarded by a mutex; the queries use sepax's
/// per-thread scratch, so btCollisionDispatcherMt may run pairs in parallel.
class CreateFunc : public btCollisionAlgorithmCreateFunc {
 public:
  explicit CreateFunc(btCollisionConfiguration& config);
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override;

  ShapeCache& shapes() { return shapes_; }
  Counters counters() const;
  void reset_counters();

 private:
  friend class CollisionAlgorithm;
  struct Live;
  btCollisionConfiguration& config_;
  ShapeCache shapes_;
  std::shared_ptr<Live> live_;
};

/// Registers `cf` with `dispatcher` for every pair of supported shape types.
void register_algorithm(btCollisionDispatcher& dispatcher, CreateFunc& cf);

}  // namespace sepax::bullet
