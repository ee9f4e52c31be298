// Ellipsoid obstacles (EllipseSpec::ellipsoid on an obstacle: a 3D cluster of a point cloud) in
// the application layer: refused at the edge naming the field and value, as ~add_obstacles and
// ~obstacles refuse them; stored and placed by their exact shadow on the fixed frame's plane,
// checked against the quad-precision shadow oracle (test/support/shadow_oracle.h) built from the
// spec's own fields; and a probe that only the shadow reaches is in collision.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/core/number_format.h"
#include "random_source.h"
#include "shadow_oracle.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// A slab 0.6 m wide, 0.1 m thin and 0.8 m tall standing on its side: radii (0.3, 0.05, 0.4)
/// rolled a quarter turn about its x axis, so its shadow is 0.3 x 0.4 where its planar ellipse
/// would be 0.3 x 0.05.
EllipseSpec standingSlab(const std::string& name, const std::string& frame, double x, double y) {
  EllipseSpec spec = test::circle(name, frame, x, y, 0.3);
  spec.radius_y = 0.05;
  spec.ellipsoid = EllipsoidPart{0.0, kPi / 2, 0.0, 0.4};
  return spec;
}

/// Every frame at the identity but "side", rolled a quarter turn about x (seen edge-on).
TransformLookup fixedAndSide() {
  return [](const std::string& frame) {
    FrameTransform transform;
    transform.ok = frame == "map" || frame == "side";
    if (!transform.ok) transform.error = "frame '" + frame + "' does not exist";
    if (frame == "side") {
      transform.fixed_from_frame.linear() =
          Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
    return transform;
  };
}

struct BadEllipsoid {
  double z, roll, pitch, radius_z;
  const char* message;
};

TEST(EllipsoidObstacles, BadFieldsAreRefusedNamingFieldAndValue) {
  const char* const forgotten =
      ": expected 0 when radius_z = 0 (a planar ellipse); z, roll and pitch describe an "
      "ellipsoid, which needs radius_z > 0";
  const std::vector<BadEllipsoid> cases = {
      {0.0, 0.0, 0.0, -1.0, "obstacles[1].radius_z = -1: expected a finite number > 0"},
      {0.0, 0.0, 0.0, kNaN, "obstacles[1].radius_z = nan: expected a finite number > 0"},
      {0.0, 0.0, 0.0, kInf, "obstacles[1].radius_z = inf: expected a finite number > 0"},
      {0.0, 0.0, 0.0, 0.0, "obstacles[1].radius_z = 0: expected a finite number > 0"},
      {0.3, 0.0, 0.0, 0.0, "obstacles[1].z = 0.3"},
      {0.0, 1.5, 0.0, 0.0, "obstacles[1].roll = 1.5"},
      {0.0, 0.0, -0.2, 0.0, "obstacles[1].pitch = -0.2"},
      {0.0, 0.5, 0.2, 0.0, "obstacles[1].roll = 0.5"},  // the first of them
      {kNaN, 0.0, 0.0, 0.4, "obstacles[1].z = nan: expected a finite number"},
      {0.0, kInf, 0.0, 0.4, "obstacles[1].roll = inf: expected a finite number"},
      {0.0, 0.0, kNaN, 0.0, "obstacles[1].pitch = nan: expected a finite number"},
  };
  CheckSettings settings;
  settings.fixed_frame = "map";
  for (const BadEllipsoid& c : cases) {
    EllipseSpec bad = standingSlab("bad", "map", 0.0, 0.0);
    bad.ellipsoid = EllipsoidPart{c.z, c.roll, c.pitch, c.radius_z};
    const std::string error = validateAttached({standingSlab("good", "map", 1.0, 0.0), bad},
                                               "obstacles", settings, fixedAndSide());
    const std::string expected = c.message;
    if (expected.find(':') == std::string::npos) {
      EXPECT_EQ(error, expected + forgotten);
    } else {
      EXPECT_EQ(error, expected);
    }
  }
  // The padded depth obeys the core's range as the other radii do.
  EllipseSpec huge = standingSlab("huge", "map", 0.0, 0.0);
  huge.ellipsoid->radius_z = core::kMaxRadius;
  huge.padding = 1.0;
  const std::string error = validateAttached({huge}, "obstacles", settings, fixedAndSide());
  EXPECT_EQ(error.rfind("obstacles[0].radius_z = " + core::formatNumber(core::kMaxRadius) +
                            ": expected a number whose padded radius (radius_z + padding 1",
                        0),
            0u)
      << error;
  EXPECT_EQ(validateAttached({standingSlab("good", "side", 0.0, 0.0)}, "obstacles", settings,
                             fixedAndSide()),
            "");
}

/// The oracle's own placed ellipsoid, from the spec's fields as documented (ellipse_spec.h):
/// centre (x, y, z), orientation Rz(angle) Ry(pitch) Rx(roll) evaluated in quad, each radius
/// grown to radius + padding + global padding (as doubles, summed in that order).
test::PlacedEllipsoid documentedPlacement(const EllipseSpec& spec, double global_padding,
                                          const Eigen::Isometry3d& fixed_from_frame) {
  using test::quad;
  const auto turn = [](double angle, int axis) {
    quad s, c;
    sincosq(static_cast<quad>(angle), &s, &c);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane the turn acts in
    test::QMat3 r = test::QMat3::Identity();
    r(i, i) = c, r(i, j) = -s, r(j, i) = s, r(j, j) = c;
    return r;
  };
  const EllipsoidPart& part = *spec.ellipsoid;
  const test::QMat3 rotation = turn(spec.angle, 2) * turn(part.pitch, 1) * turn(part.roll, 0);
  const auto grown = [&](double radius) { return radius + spec.padding + global_padding; };
  return test::placeInQuad(test::QVec3(spec.x, spec.y, part.z), rotation,
                           test::QVec3(grown(spec.radius_x), grown(spec.radius_y),
                                       grown(part.radius_z)),
                           fixed_from_frame);
}

Eigen::Isometry3d randomPose(test::RandomSource& random, double reach) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(random.normal(), random.normal(), random.normal(),
                                     random.normal())
                      .normalized()
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(random.uniform(-reach, reach),
                                       random.uniform(-reach, reach), random.uniform(-reach, reach));
  return pose;
}

TEST(EllipsoidObstacles, StoredObstacleIsPlacedAsItsShadow) {
  // 60 ellipsoid obstacles (needles and pancakes up to 1:100) in 6 frames posed at random, and
  // one in the fixed frame; placed by checks as the node makes them (through the placement cache,
  // twice: the second check reuses the projections). Each placed obstacle against the oracle.
  test::RandomSource random(34);
  std::map<std::string, Eigen::Isometry3d> poses{{"map", Eigen::Isometry3d::Identity()}};
  for (int f = 0; f < 6; ++f) poses["frame" + std::to_string(f)] = randomPose(random, 5.0);
  std::vector<EllipseSpec> obstacles;
  for (int i = 0; i < 61; ++i) {
    EllipseSpec spec = test::circle("cluster" + std::to_string(i),
                                    i == 60 ? "map" : "frame" + std::to_string(i % 6),
                                    random.uniform(-2, 2), random.uniform(-2, 2), 1.0);
    const double size = random.logUniform(0.01, 1.0);
    spec.radius_x = size * random.logUniform(0.01, 1.0);
    spec.radius_y = size * random.logUniform(0.01, 1.0);
    spec.angle = random.uniform(-kPi, kPi);
    spec.padding = i % 3 == 0 ? 0.0 : random.uniform(0.0, 0.05);
    spec.ellipsoid = EllipsoidPart{random.uniform(-1, 1), random.uniform(-kPi, kPi),
                                   random.uniform(-kPi, kPi), size};
    obstacles.push_back(spec);
  }
  EllipseRegistry registry({test::circle("body", "map", 100.0, 100.0, 0.5)}, {});
  ASSERT_EQ(registry.addObstacles(obstacles, "obstacles"), "");
  CheckSettings settings;
  settings.fixed_frame = "map";
  settings.global_padding_m = 0.01;
  const TransformLookup lookup = [&poses](const std::string& frame) {
    FrameTransform transform;
    transform.ok = poses.count(frame) != 0;
    if (transform.ok) transform.fixed_from_frame = poses.at(frame);
    return transform;
  };
  PlacementCache cache;
  double worst_outside = -1.0, worst_slack = 0.0;
  for (int check = 0; check < 2; ++check) {
    const CheckOutcome outcome = runCheck({}, registry, settings, lookup, 0.0, &cache);
    ASSERT_EQ(outcome.error, "");
    ASSERT_TRUE(outcome.skipped.empty()) << outcome.skipped[0];
    ASSERT_EQ(outcome.placed.size(), obstacles.size() + 1);
    for (std::size_t k = 0; k < outcome.placed.size(); ++k) {
      if (outcome.placed.role(k) != core::EllipseRole::Obstacle) continue;
      const EllipseSpec& spec = registry.entries().at(outcome.placed.name(k)).spec;
      const test::ShadowAgreement agreement = test::compareShadow(
          outcome.placed.ellipse(k),
          documentedPlacement(spec, settings.global_padding_m, poses.at(spec.frame_id)), random);
      worst_outside = std::max(worst_outside, agreement.worst_outside);
      worst_slack = std::max(worst_slack, agreement.worst_slack);
      EXPECT_TRUE(agreement.exact())
          << spec.name << " in check " << check << ": worst form - 1 " << agreement.worst_outside
          << " (support points " << agreement.worst_support_outside << "), support slack " << agreement.worst_slack << " (allowed "
          << agreement.allowed_slack << ")";
    }
  }
  std::printf("[ record   ] 61 ellipsoid obstacles, 2 checks: worst surface-sample form - 1 = "
              "%.3g, worst support slack = %.3g\n",
              worst_outside, worst_slack);
}

TEST(EllipsoidObstacles, ProbeThatOnlyTheShadowReachesCollides) {
  // The slab's shadow reaches y = 0.4; its planar ellipse only 0.05. A probe of radius 0.05 at
  // y = 0.32 overlaps the shadow (to y = 0.27) and is 0.22 m from the planar ellipse.
  CheckSettings settings;
  settings.fixed_frame = "map";
  const EllipseSpec probe = test::circle("probe", "map", 0.0, 0.32, 0.05);
  const CheckOutcome outcome = runCheck({}, EllipseRegistry({probe}, {standingSlab("slab", "map", 0, 0)}),
                                        settings, fixedAndSide(), 0.0);
  ASSERT_EQ(outcome.error, "");
  ASSERT_EQ(outcome.collisions.size(), 1u);
  EXPECT_EQ(outcome.collisions[0].name_a, "probe");
  EXPECT_EQ(outcome.collisions[0].name_b, "slab");

  EllipseSpec planar = standingSlab("slab", "map", 0, 0);
  planar.ellipsoid.reset();
  EXPECT_TRUE(runCheck({}, EllipseRegistry({probe}, {planar}), settings, fixedAndSide(), 0.0)
                  .collisions.empty());

  // In a frame seen edge-on the planar obstacle is skipped; the ellipsoid (here standing upright
  // again: its roll undoes the frame's) is placed, 0.3 x 0.05 at the origin.
  EllipseSpec upright = standingSlab("slab", "side", 0, 0);
  upright.ellipsoid->roll = -kPi / 2;
  const CheckOutcome side = runCheck({}, EllipseRegistry({test::circle("probe", "map", 0.0, 0.09, 0.05)},
                                                         {upright}),
                                     settings, fixedAndSide(), 0.0);
  ASSERT_EQ(side.error, "");
  EXPECT_TRUE(side.skipped.empty());
  EXPECT_EQ(side.collisions.size(), 1u);
  upright.ellipsoid.reset();
  const CheckOutcome lost = runCheck({}, EllipseRegistry({probe}, {upright}), settings,
                                     fixedAndSide(), 0.0);
  EXPECT_EQ(lost.skipped.size(), 1u);
}

TEST(EllipsoidObstacles, AShadowTheCoreCannotTakeIsReportedNotChecked) {
  // Every field within the rules, but a shadow the core cannot take: a ball of radius kMaxRadius,
  // whose shadow is certified by growing it a few ulps past kMaxRadius, and a needle 1e9 m long
  // and 1e-9 m thin, 1e9 m away, too thin to certify (core::shadowOnPlane()). Like a planar
  // ellipse seen edge-on it is not checked: a query fails the request naming it, a stored
  // obstacle is skipped and the check is not complete.
  EllipseSpec ball = test::circle("ball", "map", 0.0, 0.0, core::kMaxRadius);
  ball.ellipsoid = EllipsoidPart{0.0, 0.0, 0.0, core::kMaxRadius};
  EllipseSpec needle = test::circle("needle", "map", core::kMaxCoordinate, 0.0, core::kMaxRadius);
  needle.radius_y = core::kMinRadius;
  needle.ellipsoid = EllipsoidPart{0.0, 0.0, 0.5, core::kMaxRadius};
  CheckSettings settings;
  settings.fixed_frame = "map";
  const EllipseRegistry registry({test::circle("body", "map", 0.0, 0.0, 0.5)}, {});
  const std::pair<const EllipseSpec*, const char*> cases[] = {
      {&ball, "ellipsoid 'ball': its shadow is out of range (radius_x = "},
      {&needle, "ellipsoid 'needle': its shadow is too thin to certify (axis ratio "}};
  for (const auto& [spec, reason] : cases) {
    CheckRequest request;
    request.query = {*spec};
    ASSERT_EQ(validateCheckRequest(request, registry, 0.0), "");
    const CheckOutcome query = runCheck(request, registry, settings, fixedAndSide(), 0.0);
    EXPECT_EQ(query.error_kind, ErrorKind::InvalidRequest);
    EXPECT_EQ(query.error.rfind(std::string("query[0]: ") + reason, 0), 0u) << query.error;

    const CheckOutcome stored =
        runCheck({}, EllipseRegistry({test::circle("body", "map", 0.0, 0.0, 0.5)}, {*spec}),
                 settings, fixedAndSide(), 0.0);
    EXPECT_EQ(stored.error, "");
    ASSERT_EQ(stored.skipped.size(), 1u);
    EXPECT_EQ(stored.skipped[0].rfind(reason, 0), 0u) << stored.skipped[0];
    EXPECT_FALSE(stored.complete);
  }
}

}  // namespace
}  // namespace ellipse_collision::app
