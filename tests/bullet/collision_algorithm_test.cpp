// sepax::bullet's collision algorithm inside Bullet's dispatcher.
#include <catch2/catch.hpp>

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

  Pair(btCollisionShape* sa, btCollisionShape* sb, const btTransform& ta, const btTransform& tb, bool use_sepax) {
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
    const btVector3 d = p.getPositionWorldOnA() - (p.getPositionWorldOnB() + p.m_normalWorldOnB * p.getDistance());
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
