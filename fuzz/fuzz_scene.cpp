// Fuzz target: the core's scene-level entry points, checkScene(), nearestTo() and projectToPlane(),
// fed arbitrary names, roles, rules, transforms and field values (see fuzz_input.h).
//
// Invariants:
//  - checkScene() refuses a scene iff the warning distance is not finite and >= 0 or some entry
//    has an empty or duplicate name or an invalid ellipse, and the error names the first such
//    entry; refused scenes report nothing;
//  - an accepted scene reports exactly the wanted pairs that overlap(), each with its
//    contactScale(), and exactly the wanted separated pairs whose distance() is below the warning
//    distance, with its distance and points (brute force over all pairs, so a broadphase or bound
//    that drops a pair is caught), in the documented order, the same bits whatever the input order;
//  - checkMoversAgainst() with the obstacles in IndexedObstacles answers the same bits and tests
//    the same number of pairs; so does checkValidatedScene() with the movers first;
//  - checkValidatedScene() returns, with no sanitizer report, on any scene however broken its
//    promise (bad entries, obstacles before first_obstacle or links after): an answer, or a
//    refusal naming the warning distance, first_obstacle or an entry;
//  - nearestTo() answers what a brute force over all partners answers (colliding partner of the
//    smallest contact scale, else the smallest distance, ties in pair order);
//  - projectToPlane() refuses an invalid ellipse or a non-finite transform naming the ellipse; an
//    accepted projection is valid for the core (checkScene takes it), radius_x >= radius_y,
//    angle in (-pi/2, pi/2], and a rotation about z alone keeps the radii.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/ellipse_collision.h"
#include "ellipse_collision/core/frame_projection.h"
#include "ellipse_collision/core/scene_check.h"
#include "brute_force_scene.h"
#include "fuzz_input.h"

namespace ellipse_collision::fuzz {
namespace {

constexpr int kMaxEllipses = 10;
// Names from a small alphabet so that duplicates, allowed pairs and filters actually match.
const char* const kNames[] = {"", "a", "b", "c", "d", "e", "f", "g", "h", "link/1", "obstacle 2"};
constexpr int kNameCount = sizeof(kNames) / sizeof(kNames[0]);

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

bool sameNear(const core::NearPair& p, const core::NearPair& q) {
  return p.name_a == q.name_a && p.name_b == q.name_b && sameBits(p.distance, q.distance) &&
         sameBits(p.point_a.x(), q.point_a.x()) && sameBits(p.point_a.y(), q.point_a.y()) &&
         sameBits(p.point_b.x(), q.point_b.x()) && sameBits(p.point_b.y(), q.point_b.y());
}

bool sameResult(const core::SceneCheckResult& x, const core::SceneCheckResult& y) {
  if (x.warnings.size() != y.warnings.size()) return false;
  for (std::size_t i = 0; i < x.warnings.size(); ++i) {
    if (!sameNear(x.warnings[i], y.warnings[i])) return false;
  }
  if (x.error != y.error || x.collisions.size() != y.collisions.size()) return false;
  for (std::size_t i = 0; i < x.collisions.size(); ++i) {
    const core::CollidingPair& p = x.collisions[i];
    const core::CollidingPair& q = y.collisions[i];
    // Same bits: the scene is a set, its order must not change any rounding.
    if (p.name_a != q.name_a || p.name_b != q.name_b ||
        std::memcmp(&p.contact_scale, &q.contact_scale, sizeof(double)) != 0) {
      return false;
    }
  }
  return true;
}

/// The first bad entry, restating scene_check.h's rules; -1 when the scene is good.
int firstBadEntry(const std::vector<core::NamedEllipse>& scene) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene[i].name.empty() || !seen.insert(scene[i].name).second ||
        !documentedValid(scene[i].ellipse)) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

void checkScenes(FuzzInput& input) {
  std::vector<core::NamedEllipse> scene(static_cast<std::size_t>(input.integer(0, kMaxEllipses)));
  for (core::NamedEllipse& entry : scene) {
    entry.name = kNames[input.integer(0, kNameCount - 1)];
    entry.role = static_cast<core::EllipseRole>(input.integer(0, 2));
    entry.ellipse = input.ellipse();
    // Mostly valid fields, so that the pair loop runs: arbitrary values are rarely valid.
    if (input.flag()) {
      entry.ellipse.center = entry.ellipse.center.unaryExpr(
          [](double v) { return std::isfinite(v) ? std::fmod(v, 100.0) : 1.0; });
      entry.ellipse.radius_x = std::clamp(std::fabs(entry.ellipse.radius_x), 1e-3, 1e3);
      entry.ellipse.radius_y = std::clamp(std::fabs(entry.ellipse.radius_y), 1e-3, 1e3);
      if (!std::isfinite(entry.ellipse.angle)) entry.ellipse.angle = 0.0;
      if (!std::isfinite(entry.ellipse.radius_x)) entry.ellipse.radius_x = 1.0;
      if (!std::isfinite(entry.ellipse.radius_y)) entry.ellipse.radius_y = 1.0;
    }
  }
  core::SceneRules rules;
  rules.self_collision = input.flag();
  for (int i = input.integer(0, 4); i > 0; --i) {
    rules.allowed.add(kNames[input.integer(0, kNameCount - 1)],
                      kNames[input.integer(0, kNameCount - 1)]);
  }
  std::set<std::string> only_names;
  for (int i = input.integer(0, 3); i > 0; --i)
    only_names.insert(kNames[input.integer(0, kNameCount - 1)]);
  switch (input.integer(0, 2)) {
    case 0:
      break;  // no warnings
    case 1:
      rules.warning_distance = input.number();  // NaN, inf, negative ...
      break;
    default: {
      const double d = std::fabs(input.number());
      rules.warning_distance = std::isfinite(d) ? std::fmod(d, 10.0) : 0.5;
    }
  }
  const std::string nearest_name = kNames[input.integer(0, kNameCount - 1)];

  // The vouched entry point on whatever the input is: bad entries, any roles on either side of
  // first_obstacle. Only that it returns is checked here; the bits are checked below when the
  // promise holds.
  const std::size_t first_obstacle =
      static_cast<std::size_t>(input.integer(0, static_cast<int>(scene.size()) + 1));
  const core::SceneCheckResult broken =
      core::checkValidatedScene(core::Scene(scene), first_obstacle, rules, only_names);
  FUZZ_REQUIRE(broken.ok() || broken.error.rfind("ellipses[", 0) == 0 ||
                   broken.error.rfind("first_obstacle = ", 0) == 0 ||
                   broken.error.rfind("warning_distance = ", 0) == 0,
               "checkValidatedScene: an unexpected refusal: " + broken.error);

  const core::SceneCheckResult result = core::checkScene(scene, rules, only_names);
  const core::NearestResult nearest = core::nearestTo(scene, rules, nearest_name);
  if (!(std::isfinite(rules.warning_distance) && rules.warning_distance >= 0.0)) {
    FUZZ_REQUIRE(!result.ok() && result.collisions.empty() && result.warnings.empty() &&
                     result.error.rfind("warning_distance = ", 0) == 0 && !nearest.ok(),
                 "checkScene accepted warning_distance " + text(rules.warning_distance));
    return;
  }
  const int bad = firstBadEntry(scene);
  if (bad >= 0) {
    FUZZ_REQUIRE(!nearest.ok() && !nearest.found, "nearestTo accepted a bad scene");
    FUZZ_REQUIRE(!result.ok() && result.collisions.empty(),
                 "checkScene accepted a scene whose entry " + std::to_string(bad) + " is bad");
    const std::string where = "ellipses[" + std::to_string(bad) + "]";
    FUZZ_REQUIRE(result.error.rfind(where, 0) == 0,
                 "checkScene error does not start with " + where + ": " + result.error);
    return;
  }
  FUZZ_REQUIRE(result.ok(), "checkScene refused a good scene: " + result.error);

  const core::SceneCheckResult expected = core::test::bruteForceScene(scene, rules, only_names);
  FUZZ_REQUIRE(sameResult(result, expected),
               "checkScene differs from the brute force over all pairs (" +
                   std::to_string(result.collisions.size()) + " vs " +
                   std::to_string(expected.collisions.size()) + " collisions, " +
                   std::to_string(result.warnings.size()) + " vs " +
                   std::to_string(expected.warnings.size()) + " warnings)");

  // nearestTo(): every partner the rules allow, whatever the name filter.
  const auto target = std::find_if(scene.begin(), scene.end(),
                                   [&](const core::NamedEllipse& e) { return e.name == nearest_name; });
  if (target == scene.end()) {
    FUZZ_REQUIRE(!nearest.ok() && !nearest.found, "nearestTo found an unknown name");
  } else {
    FUZZ_REQUIRE(nearest.ok(), "nearestTo refused a good scene: " + nearest.error);
    const core::NearestResult reference = core::test::bruteForceNearest(scene, rules, *target);
    const bool found = reference.found;
    const core::NearPair& best = reference.nearest;
    FUZZ_REQUIRE(nearest.found == found && (!found || sameNear(nearest.nearest, best)),
                 "nearestTo('" + nearest_name + "') answered '" + nearest.nearest.name_b + "' at " +
                     text(nearest.nearest.distance) + ", the brute force '" + best.name_b +
                     "' at " + text(best.distance));
  }

  const core::NearestResult nearest_of_columns =
      core::nearestTo(core::Scene(scene), rules, nearest_name);
  FUZZ_REQUIRE(nearest_of_columns.found == nearest.found &&
                   (!nearest.found || sameNear(nearest_of_columns.nearest, nearest.nearest)),
               "nearestTo of a Scene differs from nearestTo of the same entries");

  std::vector<core::NamedEllipse> reversed(scene.rbegin(), scene.rend());
  FUZZ_REQUIRE(sameResult(result, core::checkScene(reversed, rules, only_names)),
               "checkScene depends on the order of the ellipses");

  // The node's path for standing obstacles: the obstacles gridded once, the movers looked up.
  std::vector<core::NamedEllipse> movers, obstacles;
  for (const core::NamedEllipse& entry : scene) {
    (entry.role == core::EllipseRole::Obstacle ? obstacles : movers).push_back(entry);
  }
  const core::IndexedObstacles indexed(std::move(obstacles));
  FUZZ_REQUIRE(indexed.error().empty(),
               "IndexedObstacles refused good obstacles: " + indexed.error());
  const core::SceneCheckResult against =
      core::checkMoversAgainst(movers, indexed, rules, only_names);
  FUZZ_REQUIRE(sameResult(against, expected) && against.pair_tests == result.pair_tests,
               "checkMoversAgainst differs from checkScene");
  // The node's path for moving obstacles: the movers first, every entry vouched for.
  std::vector<core::NamedEllipse> ordered = movers;
  ordered.insert(ordered.end(), indexed.obstacles().begin(), indexed.obstacles().end());
  const core::SceneCheckResult vouched =
      core::checkValidatedScene(core::Scene(ordered), movers.size(), rules, only_names);
  FUZZ_REQUIRE(sameResult(vouched, expected) && vouched.pair_tests == result.pair_tests,
               "checkValidatedScene differs from checkScene");
}

void checkProjection(FuzzInput& input) {
  const core::Ellipse in_frame = input.ellipse();
  const Eigen::Vector3d translation(input.number(), input.number(), input.number());
  const bool about_z_only = input.flag();
  Eigen::Matrix3d rotation;
  if (about_z_only) {
    rotation = Eigen::AngleAxisd(input.number(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  } else {
    Eigen::Quaterniond q(input.number(), input.number(), input.number(), input.number());
    const double norm = q.norm();
    // tf hands out unit quaternions; a zero or non-finite one stays as it is to test the refusal.
    if (std::isfinite(norm) && norm > 0.0) q.coeffs() /= norm;
    rotation = q.toRotationMatrix();
  }
  Eigen::Isometry3d fixed_from_frame = Eigen::Isometry3d::Identity();
  fixed_from_frame.linear() = rotation;
  fixed_from_frame.translation() = translation;

  const core::ProjectionResult result = core::projectToPlane(in_frame, fixed_from_frame, "e");
  if (!documentedValid(in_frame) || !fixed_from_frame.matrix().allFinite()) {
    FUZZ_REQUIRE(!result.ok() && result.error.find("'e'") != std::string::npos,
                 "projectToPlane accepted an invalid ellipse or transform: " + describe(in_frame));
    return;
  }
  if (!result.ok()) {
    // A rotation about z alone never makes a frame edge-on; a translation can move any centre
    // out of range.
    const bool edge_on = result.error.find("edge-on") != std::string::npos && !about_z_only;
    const bool out_of_range = result.error.find("out of range") != std::string::npos;
    FUZZ_REQUIRE(edge_on || out_of_range, "projectToPlane refused a valid input: " + result.error);
    return;
  }
  FUZZ_REQUIRE(
      documentedValid(result.ellipse),
      "projectToPlane accepted a projection the core refuses: " + describe(result.ellipse));
  const core::Ellipse& e = result.ellipse;
  // radius_x >= radius_y up to rounding: for a near-circle the minor radius |det| / major can
  // come out an ulp above the major one, which changes no collision answer.
  FUZZ_REQUIRE(std::isfinite(e.center.x()) && std::isfinite(e.center.y()) &&
                   std::isfinite(e.angle) && e.radius_y <= e.radius_x * (1.0 + 1e-15) &&
                   e.radius_y > 0.0 && std::isfinite(e.radius_x) && e.angle > -M_PI / 2 &&
                   e.angle <= M_PI / 2,
               "projectToPlane returned " + describe(e) + " for " + describe(in_frame));
  if (about_z_only) {
    const double major = std::max(in_frame.radius_x, in_frame.radius_y);
    const double minor = std::min(in_frame.radius_x, in_frame.radius_y);
    FUZZ_REQUIRE(
        std::fabs(e.radius_x - major) <= 1e-12 * major &&
            std::fabs(e.radius_y - minor) <= 1e-12 * major,
        "a rotation about z changed the radii: " + describe(e) + " from " + describe(in_frame));
  }
  // The node hands projections straight to checkScene.
  const core::SceneCheckResult scene = core::checkScene(
      {{"e", core::EllipseRole::Link, e}, {"f", core::EllipseRole::Obstacle, in_frame}}, core::SceneRules{});
  FUZZ_REQUIRE(scene.ok(), "checkScene refused a projection: " + scene.error);
}

}  // namespace
}  // namespace ellipse_collision::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ellipse_collision::fuzz::FuzzInput input(data, size);
  if (input.flag()) {
    ellipse_collision::fuzz::checkScenes(input);
  } else {
    ellipse_collision::fuzz::checkProjection(input);
  }
  return 0;
}
