// sepax::bullet's collision algorithm inside Bullet's dispatcher.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <btBulletCollisionCommon.h>

#include <sepax/bullet/collision_algorithm.hpp>

namespace {

struct Pair {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  std::unique_ptr<sepax::bullet::CreateFunc> cf;
  btCollisionObject a, b;

  Pair(btCollisionShape* sa, btCollisionShape* sb, const btTransform& ta, const btTransform& tb,
       bool use_sepax) {
    if (use_sepax) {
      cf = std::make_unique<sepax::bullet::CreateFunc>(config);
      sepax::bullet::register_algorithm(dispatcher, *cf);
    }
    a.setCollisionShape(sa);
    b.setCollisionShape(sb);
    a.setWorldTransform(ta);
    b.setWorldTransform(tb);
    world.addCollisionObject(&a);
    world.addCollisionObject(&b);
  }
  ~Pair() {
    world.removeCollisionObject(&a);
    world.removeCollisionObject(&b);
  }
  const btPersistentManifold* manifold() {
    world.performDiscreteCollisionDetection();
    for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
      const auto* m = dispatcher.getManifoldByIndexInternal(i);
      if (m->getNumContacts() > 0) return m;
    }
    return nullptr;
  }
};

btTransform at(float x, float y, float z, const btQuaternion& q = btQuaternion::getIdentity()) {
  return btTransform(q, btVector3(x, y, z));
}

/// Every point: its depth equals (A's point - B's point) . normal on B, the
/// point on A is below B's ... checked against Bullet's own convention: the
/// point on body 0 = point on body 1 + normal * distance.
void check_convention(const btPersistentManifold& m) {
  for (int i = 0; i < m.getNumContacts(); ++i) {
    const auto& p = m.getContactPoint(i);
    const btVector3 d =
        p.getPositionWorldOnA() - (p.getPositionWorldOnB() + p.m_normalWorldOnB * p.getDistance());
    CHECK(d.length() < 1e-5f);
    CHECK(std::abs(p.m_normalWorldOnB.length() - 1) < 1e-5f);
    const btVector3 la = m.getBody0()->getWorldTransform()(p.m_localPointA);
    CHECK((la - p.getPositionWorldOnA()).length() < 1e-5f);
  }
}

}  // namespace

TEST_CASE("bullet: a box resting on a box gets the same manifold as Bullet's box-box detector") {
  btBoxShape floor(btVector3(5, 0.5f, 5)), box(btVector3(0.5f, 0.5f, 0.5f));
  const btTransform tf = at(0, -0.5f, 0), tb = at(0.1f, 0.49f, 0.2f);  // 1 cm deep
  Pair bullet(&floor, &box, tf, tb, false), sepax(&floor, &box, tf, tb, true);
  const auto* mb = bullet.manifold();
  const auto* ms = sepax.manifold();
  REQUIRE(mb);
  REQUIRE(ms);
  check_convention(*ms);
  REQUIRE(ms->getNumContacts() == 4);
  REQUIRE((ms->getBody0() == &sepax.a) == (mb->getBody0() == &bullet.a));
  for (int i = 0; i < 4; ++i) {
    const auto& p = ms->getContactPoint(i);
    CHECK(p.getDistance() == Approx(-0.01).margin(1e-5));
    // the same normal as Bullet's (same body order)
    CHECK((p.m_normalWorldOnB - mb->getContactPoint(0).m_normalWorldOnB).length() < 1e-5f);
    // sepax's ids: part = feature kind (1 vertex, 2 edge, 3 face), index the feature
    CHECK(p.m_partId0 >= 1);
    CHECK(p.m_partId1 >= 1);
    CHECK(p.m_index0 >= 0);
    CHECK(p.m_index1 >= 0);
  }
  REQUIRE(sepax.cf->counters().manifolds == 1);
}

TEST_CASE("bullet: the algorithm keeps a point's accumulated impulse when its features stay in contact") {
  btBoxShape floor(btVector3(5, 0.5f, 5)), box(btVector3(0.5f, 0.5f, 0.5f));
  Pair p(&floor, &box, at(0, -0.5f, 0), at(0, 0.49f, 0), true);
  auto* m = const_cast<btPersistentManifold*>(p.manifold());
  REQUIRE(m);
  REQUIRE(m->getNumContacts() == 4);
  for (int i = 0; i < 4; ++i) m->getContactPoint(i).m_appliedImpulse = static_cast<btScalar>(i + 1);
  std::vector<btManifoldPoint> before;
  for (int i = 0; i < 4; ++i) before.push_back(m->getContactPoint(i));
  // move the box by 5 mm sideways: the same features touch
  p.b.setWorldTransform(at(0.005f, 0.49f, 0));
  m = const_cast<btPersistentManifold*>(p.manifold());
  REQUIRE(m);
  REQUIRE(m->getNumContacts() == 4);
  for (int i = 0; i < 4; ++i) {
    const auto& q = m->getContactPoint(i);
    bool found = false;
    for (const auto& o : before) {
      if (o.m_partId0 == q.m_partId0 && o.m_index0 == q.m_index0 && o.m_partId1 == q.m_partId1 &&
          o.m_index1 == q.m_index1) {
        found = true;
        CHECK(q.m_appliedImpulse == o.m_appliedImpulse);
      }
    }
    CHECK(found);
  }
  CHECK(p.cf->counters().id_matches == 4);
}

TEST_CASE("bullet: a point whose features changed keeps the impulse of the stored point at its place") {
  btBoxShape floor(btVector3(5, 0.5f, 5)), box(btVector3(0.5f, 0.5f, 0.5f));
  Pair p(&floor, &box, at(0, -0.5f, 0), at(0, 0.49f, 0), true);
  auto* m = const_cast<btPersistentManifold*>(p.manifold());
  REQUIRE(m);
  REQUIRE(m->getNumContacts() == 4);
  const btScalar threshold = m->getContactBreakingThreshold();
  // The stored points get ids no new point has (as when a vertex of B
  // crosses a side plane of A's face and the clip names the point by an
  // edge); point 3 is also moved farther than the threshold from where the
  // new point will be.
  std::vector<btVector3> where;
  for (int i = 0; i < 4; ++i) {
    auto& q = m->getContactPoint(i);
    q.m_appliedImpulse = static_cast<btScalar>(i + 1);
    q.m_index0 += 100;
    q.m_index1 += 100;
    if (i == 3) q.m_localPointB += btVector3(2 * threshold, 0, 0);
    where.push_back(q.m_localPointB);
  }
  m = const_cast<btPersistentManifold*>(p.manifold());
  REQUIRE(m);
  REQUIRE(m->getNumContacts() == 4);
  int kept = 0, fresh = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& q = m->getContactPoint(i);
    CHECK(q.m_index0 < 100);
    CHECK(q.m_index1 < 100);
    // the stored point within the threshold of this one, if any
    int near = -1;
    for (int k = 0; k < 4; ++k) {
      if ((where[static_cast<std::size_t>(k)] - q.m_localPointB).length() < threshold) near = k;
    }
    if (near >= 0) {
      CHECK(q.m_appliedImpulse == static_cast<btScalar>(near + 1));
      ++kept;
    } else {
      CHECK(q.m_appliedImpulse == 0);
      ++fresh;
    }
  }
  CHECK(kept == 3);
  CHECK(fresh == 1);
  CHECK(p.cf->counters().id_matches == 0);
}

TEST_CASE("bullet: each shape is prepared once, whatever the number of pairs") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btCollisionWorld world(&dispatcher, &broadphase, &config);
  sepax::bullet::CreateFunc cf(config);
  sepax::bullet::register_algorithm(dispatcher, cf);
  std::vector<std::unique_ptr<btCollisionObject>> objs;
  for (int i = 0; i < 5; ++i) {
    objs.push_back(std::make_unique<btCollisionObject>());
    objs.back()->setCollisionShape(&box);
    objs.back()->setWorldTransform(at(0, 0.99f * static_cast<float>(i), 0));
    world.addCollisionObject(objs.back().get());
  }
  world.performDiscreteCollisionDetection();
  CHECK(cf.counters().manifolds == 4);
  CHECK(cf.shapes().preparations() == 1);
  CHECK(cf.shapes().size() == 1);
  for (auto& o : objs) world.removeCollisionObject(o.get());
}

TEST_CASE("bullet: a shape sepax refuses goes to Bullet's own algorithm") {
  btConvexHullShape segment;  // two points: no solid, no polygon
  segment.addPoint(btVector3(-0.5f, 0, 0), false);
  segment.addPoint(btVector3(0.5f, 0, 0), true);
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  Pair p(&box, &segment, at(0, 0, 0), at(0, 0.4f, 0), true);
  p.manifold();
  CHECK(p.cf->counters().fallback_pairs == 1);
  CHECK(p.cf->counters().queries == 0);
  CHECK(!p.cf->counters().last_error.empty());
}

TEST_CASE("bullet: pairs farther apart than the contact breaking threshold stop early and keep no point") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  Pair p(&box, &box, at(0, 0, 0), at(0, 0.99f, 0), true);
  REQUIRE(p.manifold());
  // still overlapping in the broadphase (AABBs grown by the breaking threshold) but separated
  const btScalar thr = gContactBreakingThreshold;
  p.b.setWorldTransform(at(0, 1.0f + 0.5f * thr, 0));
  const auto* m = p.manifold();
  REQUIRE(m);  // within the margin: speculative points
  CHECK(m->getContactPoint(0).getDistance() > 0);
  p.b.setWorldTransform(at(0, 1.0f + 2.0f * thr, 0));
  CHECK(p.manifold() == nullptr);
  CHECK(p.cf->counters().early_outs >= 1);
}

TEST_CASE("bullet: equal boxes stacked with a small tilt get a face contact, not one edge point") {
  // The touching faces' edges cross at tiny angles, where an edge pair's
  // separation rivals the faces' (as in a settling stack).
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1, 1);
  int face_manifolds = 0;
  const int n = 100;
  for (int k = 0; k < n; ++k) {
    const btQuaternion qa(btVector3(u(rng), u(rng), u(rng)).normalized(), 3e-3f * u(rng));
    const btQuaternion qb(btVector3(u(rng), u(rng), u(rng)).normalized(), 3e-3f * u(rng));
    Pair p(&box, &box, at(0, 0, 0, qa), at(0.01f * u(rng), 0.995f, 0.01f * u(rng), qb), true);
    const auto* m = p.manifold();
    REQUIRE(m);
    if (m->getNumContacts() == 4) ++face_manifolds;
  }
  CHECK(face_manifolds == n);
}

namespace {

/// The manifold's points as (position on B, depth, ids), for comparisons.
struct PointKey {
  btVector3 on_b;
  btScalar depth;
  int ids[4];
};

std::vector<PointKey> points_of(const btPersistentManifold* m) {
  std::vector<PointKey> out;
  if (!m) return out;
  for (int i = 0; i < m->getNumContacts(); ++i) {
    const auto& p = m->getContactPoint(i);
    out.push_back(PointKey{
        p.getPositionWorldOnB(), p.getDistance(), {p.m_partId0, p.m_index0, p.m_partId1, p.m_index1}});
  }
  std::sort(out.begin(), out.end(), [](const PointKey& x, const PointKey& y) {
    return std::lexicographical_compare(x.ids, x.ids + 4, y.ids, y.ids + 4);
  });
  return out;
}

}  // namespace

TEST_CASE("bullet: a resting pair keeps its face, with the manifold a fresh algorithm builds at every step") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  const btQuaternion tilt(btVector3(0.3f, 0.2f, 0.9f).normalized(), 2e-3f);
  Pair kept(&box, &box, at(0, 0, 0), at(0.02f, 0.998f, 0.01f, tilt), true);
  REQUIRE(kept.manifold());
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int step = 0; step < 40; ++step) {
    // small jitter: well inside the kept face's motion budget (0.5e-3 x extent)
    const btTransform tb = at(0.02f + 1e-5f * u(rng), 0.998f + 1e-5f * u(rng), 0.01f + 1e-5f * u(rng), tilt);
    kept.b.setWorldTransform(tb);
    const auto got = points_of(kept.manifold());
    Pair fresh(&box, &box, at(0, 0, 0), tb, true);
    const auto want = points_of(fresh.manifold());
    REQUIRE(got.size() == 4);
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      CHECK(std::equal(got[i].ids, got[i].ids + 4, want[i].ids));
      CHECK(got[i].depth == want[i].depth);
      CHECK(got[i].on_b == want[i].on_b);
    }
  }
  const auto c = kept.cf->counters();
  CHECK(c.kept == 40);
  CHECK(c.queries == 1);
}

TEST_CASE("bullet: a kept face is dropped when the pair moves beyond its budget or its margin") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  Pair p(&box, &box, at(0, 0, 0), at(0, 0.999f, 0), true);
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().queries == 1);
  p.b.setWorldTransform(at(0, 0.999f, 0.01f));  // 10 mm sideways: beyond 0.5e-3 x 1.73 m
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().queries == 2);
  CHECK(p.cf->counters().kept == 0);
  p.b.setWorldTransform(at(0, 0.9992f, 0.01f));  // 0.2 mm: kept
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().kept == 1);
  const btScalar thr = gContactBreakingThreshold;
  p.b.setWorldTransform(at(0, 1.0f + 2.0f * thr, 0.01f));  // beyond the margin: the SAT decides
  CHECK(p.manifold() == nullptr);
  CHECK(p.cf->counters().queries == 3);
  CHECK(p.cf->counters().early_outs == 1);
}

TEST_CASE("bullet: pairs whose bounding spheres are beyond the margin are culled without a query") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  // the broadphase pairs AABBs grown by the breaking threshold; along a
  // diagonal the AABBs overlap while the spheres (radius 0.866, 1.78 apart)
  // are farther apart than the threshold (0.017)
  Pair p(&box, &box, at(0, 0, 0), at(1.03f, 1.03f, 1.03f), true);
  CHECK(p.manifold() == nullptr);
  const auto c = p.cf->counters();
  CHECK(c.culled == 1);
  CHECK(c.queries == 0);
}

TEST_CASE(
    "bullet: a pair proven beyond the margin stays so without a query while it moves less than its gap") {
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  const btScalar thr = gContactBreakingThreshold;  // AABBs grown by it: the pair stays in the broadphase
  Pair p(&box, &box, at(0, 0, 0), at(0, 1.0f + 1.5f * thr, 0), true);
  CHECK(p.manifold() == nullptr);
  CHECK(p.cf->counters().queries == 1);
  CHECK(p.cf->counters().early_outs == 1);
  // 1 mm closer: still 1.5 thr - 1 mm apart, more than the threshold (at most 0.02 m x 0.87)
  p.b.setWorldTransform(at(0, 1.0f + 1.5f * thr - 0.001f, 0));
  CHECK(p.manifold() == nullptr);
  CHECK(p.cf->counters().kept_apart == 1);
  CHECK(p.cf->counters().queries == 1);
  // within the threshold: the query runs and finds the speculative contact
  p.b.setWorldTransform(at(0, 1.0f + 0.5f * thr, 0));
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().queries == 2);
}

namespace {

/// Moves `kept`'s body b through `poses` one step each, and checks every
/// step's manifold against a fresh algorithm's at the same poses (ids,
/// depths, positions).  Returns the point counts per step.
std::vector<std::size_t> follow_fresh(Pair& kept, btCollisionShape* sa, btCollisionShape* sb,
                                      const std::vector<btTransform>& poses) {
  std::vector<std::size_t> counts;
  for (const btTransform& tb : poses) {
    kept.b.setWorldTransform(tb);
    const auto got = points_of(kept.manifold());
    Pair fresh(sa, sb, kept.a.getWorldTransform(), tb, true);
    const auto want = points_of(fresh.manifold());
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      CHECK(std::equal(got[i].ids, got[i].ids + 4, want[i].ids));
      CHECK(got[i].depth == want[i].depth);
      CHECK(got[i].on_b == want[i].on_b);
    }
    counts.push_back(got.size());
  }
  return counts;
}

}  // namespace

TEST_CASE("bullet: a refreshed kept face gives a fresh algorithm's points while points leave the margin") {
  // A 10 cm box tilted by about 0.2 rad on a floor: its bottom face's low
  // side 1 mm deep, its high side just under the contact breaking threshold.
  // Raising it by 5 um per step lifts the high side's two points beyond the
  // threshold (the refreshed point set shrinks from 4 to 2) while the pair
  // stays within the kept face's budget (0.5e-3 x 0.17 m).  With the floor as
  // body 0 the reference face is a face of A (its side planes kept), with the
  // box as body 0 a face of B (its side planes move with B').
  btBoxShape floor(btVector3(5, 0.5f, 5)), box(btVector3(0.05f, 0.05f, 0.05f));
  const btTransform tf = at(0, -0.5f, 0);
  for (const bool floor_first : {true, false}) {
    btCollisionShape* s0 = floor_first ? static_cast<btCollisionShape*>(&floor) : &box;
    btCollisionShape* s1 = floor_first ? static_cast<btCollisionShape*>(&box) : &floor;
    Pair probe(&floor, &box, tf, at(0, 0.049f, 0), true);
    const btPersistentManifold* m0 = probe.manifold();
    REQUIRE(m0);
    const float thr = m0->getContactBreakingThreshold();
    const float s = (thr + 0.001f - 30e-6f) / 0.1f;  // sin of the tilt: high side 30 um under the threshold
    const float angle = std::asin(s);
    const btQuaternion tilt(btVector3(0, 0, 1), angle);
    const float c = std::cos(angle);
    const float y = -0.001f + 0.05f * s + 0.05f * c;  // lowest vertex 1 mm deep
    const btTransform t0 = at(0.3f, y, 0.2f, tilt);
    // body 1 moves: the box, or the floor the opposite way
    std::vector<btTransform> poses;
    for (int step = 1; step <= 12; ++step) {
      const float up = 5e-6f * static_cast<float>(step);
      poses.push_back(floor_first ? at(0.3f, y + up, 0.2f, tilt) : at(0, -0.5f - up, 0));
    }
    Pair kept(s0, s1, floor_first ? tf : t0, floor_first ? t0 : tf, true);
    const btPersistentManifold* m1 = kept.manifold();
    REQUIRE(m1);
    REQUIRE(m1->getNumContacts() == 4);
    for (int i = 0; i < 4; ++i) {  // the floor's face is the reference face: a face of B when it is body 1
      const auto& q = m1->getContactPoint(i);
      CHECK((floor_first ? q.m_partId0 : q.m_partId1) == 3);
      CHECK((floor_first ? q.m_partId1 : q.m_partId0) == 1);
    }
    const auto counts = follow_fresh(kept, s0, s1, poses);
    CHECK(counts.front() == 4);
    CHECK(counts.back() == 2);
    const auto cnt = kept.cf->counters();
    CHECK(cnt.queries == 1);
    CHECK(cnt.kept == 12);
    CHECK(cnt.refreshed == cnt.kept);
  }
}

TEST_CASE("bullet: a kept face whose clip leaves five points is refreshed with the full path's reduction") {
  // A 10 cm box turned about the vertical near the floor's +x side, one
  // corner 20 um inside it; 5 um per step outwards: the corner crosses the
  // side plane, the clip leaves five points, and the refresh reduces them to
  // the four the full path (a fresh algorithm) keeps.
  btBoxShape floor(btVector3(0.5f, 0.5f, 0.5f)), box(btVector3(0.05f, 0.05f, 0.05f));
  const btTransform tf = at(0, -0.5f, 0);
  const float angle = 0.3f;
  const btQuaternion turn(btVector3(0, 1, 0), angle);
  const float reach = 0.05f * (std::cos(angle) + std::sin(angle));  // the corner's x offset
  const float x = 0.5f - reach - 20e-6f;
  Pair kept(&floor, &box, tf, at(x, 0.049f, 0, turn), true);
  REQUIRE(kept.manifold());
  REQUIRE(kept.manifold()->getNumContacts() == 4);
  std::vector<btTransform> poses;
  for (int step = 1; step <= 10; ++step)
    poses.push_back(at(x + 5e-6f * static_cast<float>(step), 0.049f, 0, turn));
  const auto counts = follow_fresh(kept, &floor, &box, poses);
  for (const std::size_t n : counts) CHECK(n == 4);
  const auto cnt = kept.cf->counters();
  CHECK(cnt.queries == 1);
  CHECK(cnt.kept == 11);
  CHECK(cnt.refreshed == cnt.kept);
  CHECK(cnt.reduced > 0);         // after the corner crosses: five points reduced
  CHECK(cnt.reduced < cnt.kept);  // before: four points
}

namespace {

/// A prism of `sides` sides (radius 0.1, height 0.06) resting on its cap on
/// a large floor, slightly tilted, 1 mm deep, jittered in position and
/// rotation within the kept face's budget for `steps` steps (seed): with the
/// floor as body 0 (the kept face a face of A) and as body 1 (a face of B),
/// every step's points are a fresh algorithm's, four of them, every step
/// refreshed from the kept face and reduced from more than four.
void check_prism_on_floor(int sides, unsigned seed, int steps) {
  btBoxShape floor(btVector3(5, 0.5f, 5));
  btConvexHullShape prism;
  for (int k = 0; k < sides; ++k) {
    const float t = 2.0f * 3.14159265f * static_cast<float>(k) / static_cast<float>(sides) + 0.1f;
    prism.addPoint(btVector3(0.1f * std::cos(t), -0.03f, 0.1f * std::sin(t)), false);
    prism.addPoint(btVector3(0.1f * std::cos(t), 0.03f, 0.1f * std::sin(t)), false);
  }
  prism.recalcLocalAabb();
  const btTransform tf = at(0, -0.5f, 0);
  const btQuaternion tilt(btVector3(0.3f, 0.1f, 0.8f).normalized(), 2e-3f);
  for (const bool floor_first : {true, false}) {
    INFO("floor first: " << floor_first);
    btCollisionShape* s0 = floor_first ? static_cast<btCollisionShape*>(&floor) : &prism;
    btCollisionShape* s1 = floor_first ? static_cast<btCollisionShape*>(&prism) : &floor;
    const btTransform tp = at(0.2f, 0.029f, -0.1f, tilt);
    Pair kept(s0, s1, floor_first ? tf : tp, floor_first ? tp : tf, true);
    REQUIRE(kept.manifold());
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1, 1);
    std::vector<btTransform> poses;  // body 1: the prism, or the floor
    for (int step = 0; step < steps; ++step) {
      const btQuaternion q =
          tilt * btQuaternion(btVector3(u(rng), u(rng), u(rng)).normalized(), 1e-5f * u(rng));
      const btVector3 d(1e-6f * u(rng), 1e-6f * u(rng), 1e-6f * u(rng));
      poses.push_back(floor_first ? btTransform(q, tp.getOrigin() + d)
                                  : btTransform(btQuaternion::getIdentity(), tf.getOrigin() + d));
    }
    const auto counts = follow_fresh(kept, s0, s1, poses);
    for (const std::size_t n : counts) CHECK(n == 4);
    const auto cnt = kept.cf->counters();
    CHECK(cnt.queries == 1);
    CHECK(cnt.kept == steps);
    CHECK(cnt.refreshed == cnt.kept);
    CHECK(cnt.reduced == cnt.kept);
  }
}

}  // namespace

TEST_CASE(
    "bullet: a hull whose vertex count is no multiple of the SIMD width keeps a fresh algorithm's points") {
  // A pentagonal prism: 10 vertices, so posing maps the last two outside its
  // SIMD groups; 5 faces around no vertex, 3 around each.  Its clip leaves
  // five points (reduced to four).
  check_prism_on_floor(5, 11, 30);
}

TEST_CASE(
    "bullet: a kept face whose polygon exceeds the fixed clip buffers keeps a fresh algorithm's points") {
  // A 40-sided prism (80 vertices): the clip's polygon has 40 vertices, more
  // than the refresh's fixed buffers hold (FixedPoly, 32), so the refresh
  // clips again in SmallVector buffers.
  check_prism_on_floor(40, 13, 20);
}

TEST_CASE("bullet: a kept face refuses a pose that is not a rotation, as a query does") {
  // B's basis scaled by 1 + 4e-4: |R^T R - I|_F = sqrt(3) (s^2 - 1) = 1.4e-3,
  // beyond posing's 1e-3, while |R1 - R0|_F reach = 6e-4 stays within the
  // kept face's budget (0.5e-3 x 1.73 m): the kept face's posing must refuse
  // it (no point, one refused query) exactly as a fresh algorithm does.
  btBoxShape box(btVector3(0.5f, 0.5f, 0.5f));
  const btTransform tb = at(0.01f, 0.999f, 0.02f);
  Pair p(&box, &box, at(0, 0, 0), tb, true);
  REQUIRE(p.manifold());
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().kept == 1);
  CHECK(p.cf->counters().errors == 0);
  btTransform scaled = tb;
  scaled.setBasis(tb.getBasis().scaled(btVector3(1 + 4e-4f, 1 + 4e-4f, 1 + 4e-4f)));
  p.b.setWorldTransform(scaled);
  CHECK(p.manifold() == nullptr);
  CHECK(p.cf->counters().errors == 1);
  Pair fresh(&box, &box, at(0, 0, 0), scaled, true);
  CHECK(fresh.manifold() == nullptr);
  CHECK(fresh.cf->counters().errors == 1);
  // back at a rotation: points again
  p.b.setWorldTransform(tb);
  CHECK(p.manifold() != nullptr);
}

TEST_CASE("bullet: a shape rescaled in place drops the kept face and queries again") {
  btBoxShape floor(btVector3(5, 0.5f, 5)), box(btVector3(0.5f, 0.5f, 0.5f));
  const btTransform tf = at(0, -0.5f, 0), tb = at(0, 0.499f, 0);
  Pair p(&floor, &box, tf, tb, true);
  REQUIRE(p.manifold());
  REQUIRE(p.manifold());
  CHECK(p.cf->counters().kept == 1);
  box.setLocalScaling(
      btVector3(1.5f, 1, 1.5f));  // same pose, wider box: the kept face's data are the old shape's
  const auto got = points_of(p.manifold());
  CHECK(p.cf->counters().queries == 2);
  CHECK(p.cf->counters().kept == 1);
  Pair fresh(&floor, &box, tf, tb, true);
  const auto want = points_of(fresh.manifold());
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i].on_b == want[i].on_b);
}
