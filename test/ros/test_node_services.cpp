// rostest client: the node's services through a C++ client (scene: test_scene.yaml,
// frames: test_frames.yaml). Every test leaves the node as it found it.
#include <cmath>
#include <limits>

#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

class NodeServices : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
    connectServices(nh_);
    // tf is up once every frame of the helper is seen (camera_link is missing on purpose).
    ASSERT_TRUE(waitUntil(
        [this] {
          const CheckCollisions::Response r = check();
          return r.success && r.unavailable_frames == std::vector<std::string>{"camera_link"};
        },
        30.0));
  }

  CheckCollisions::Response minDistanceOf(const std::string& name,
                                          const std::vector<Ellipse>& query = {}) {
    return check({}, query, ros::Time(0), name);
  }

  ros::NodeHandle nh_;
};

TEST_F(NodeServices, TiltedFrameIsProjectedExactly) {
  const CheckCollisions::Response r = check();
  ASSERT_TRUE(r.success) << r.message;
  // The plate (0.4 m circle tilted 60 deg) is 0.2 m tall in base_link: post_near (0.1 m at
  // 0.25 m) touches at scale 0.25 / 0.3; post (0.35 m) misses, though the untilted circle would
  // hit.
  const CollisionPair* near = findPair(r.collisions, "plate", "post_near");
  ASSERT_TRUE(near);
  EXPECT_NEAR(near->contact_scale, 0.25 / 0.3, 1e-9);
  EXPECT_FALSE(findPair(r.collisions, "plate", "post"));
  EXPECT_TRUE(r.in_collision);
}

TEST_F(NodeServices, AllowedPairIsNeverReportedThoughTheEllipsesOverlap) {
  // A query twin of bumper shows that body and bumper do overlap.
  const CheckCollisions::Response twin =
      check({}, {ellipseMsg("bumper_twin", "base_link", 0.5, 0.0, 0.1, 0.3)});
  ASSERT_TRUE(twin.success) << twin.message;
  EXPECT_TRUE(findPair(twin.collisions, "bumper_twin", "body"));
  EXPECT_FALSE(findPair(twin.collisions, "body", "bumper"));
  EXPECT_FALSE(findPair(twin.collisions, "bumper", "body"));
}

TEST_F(NodeServices, MissingFrameIsListedWhileOtherPairsAreStillChecked) {
  const CheckCollisions::Response r = check();
  ASSERT_TRUE(r.success);
  EXPECT_EQ(r.unavailable_frames, std::vector<std::string>{"camera_link"});
  EXPECT_CONTAINS(r.message, "camera: frame 'camera_link' unavailable");
  EXPECT_TRUE(findPair(r.collisions, "plate", "post_near"));
  EXPECT_FALSE(mentions(r.collisions, "camera"));
}

TEST_F(NodeServices, NameFilterKeepsOnlyPairsInvolvingListedNames) {
  EXPECT_EQ(check({"post_near"}).collisions.size(), 1u);
  const CheckCollisions::Response crate_only = check({"crate"});
  ASSERT_TRUE(crate_only.success);
  EXPECT_TRUE(crate_only.collisions.empty());
  EXPECT_FALSE(crate_only.in_collision);
}

TEST_F(NodeServices, QueryIsCheckedAgainstStoredEllipsesButNotStored) {
  // Centred on crate, given in crate's own frame: coincident centres give contact scale 0.
  const std::vector<Ellipse> query = {ellipseMsg("probe", "odom", 2.0, 0.0, 0.1, 0.1)};
  const CheckCollisions::Response r = check({"probe"}, query);
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].name_a, "probe");
  EXPECT_EQ(r.collisions[0].name_b, "crate");
  EXPECT_NEAR(r.collisions[0].contact_scale, 0.0, 1e-12);
  EXPECT_FALSE(isStored("probe"));
}

TEST_F(NodeServices, QueryInTheSameFrameAsItsObstacleMatchesTheHandComputedPlacement) {
  // crate is at (1, 2) in base_link with its 0.3 m axis along y: a base_link query at (1, 2.5)
  // of radius 0.25 reaches it at scale 0.5 / (0.3 + 0.25).
  const CheckCollisions::Response r =
      check({"q"}, {ellipseMsg("q", "base_link", 1.0, 2.5, 0.25, 0.25)});
  ASSERT_TRUE(r.success) << r.message;
  const CollisionPair* pair = findPair(r.collisions, "q", "crate");
  ASSERT_TRUE(pair);
  EXPECT_NEAR(pair->contact_scale, 0.5 / 0.55, 1e-9);
}

TEST_F(NodeServices, StampOutsideTheTfCacheMakesOnlyTheMovingFrameUnavailable) {
  const CheckCollisions::Response r = check({}, {}, ros::Time::now() - ros::Duration(1000.0));
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.unavailable_frames, (std::vector<std::string>{"arm_link", "camera_link"}));
  EXPECT_TRUE(findPair(r.collisions, "plate", "post_near"));  // static frames hold at any time
}

// probe: a 0.05 m circle at (0, 10.52), 0.17 m above post (0.1 m at (0, 10.35)): 0.02 m apart,
// closest at (0, 10.47) and (0, 10.45); 0.27 m from plate and 0.12 m from post_near.
Ellipse probeNearPost() { return ellipseMsg("probe", "base_link", 0.0, 10.52, 0.05, 0.05); }

void expectPair(const ClearancePair& pair, const std::string& a, const std::string& b,
                double distance, double ax, double ay, double bx, double by) {
  EXPECT_EQ(pair.name_a, a);
  EXPECT_EQ(pair.name_b, b);
  EXPECT_NEAR(pair.distance, distance, 1e-9);
  EXPECT_NEAR(pair.point_a.x, ax, 1e-9);
  EXPECT_NEAR(pair.point_a.y, ay, 1e-9);
  EXPECT_NEAR(pair.point_b.x, bx, 1e-9);
  EXPECT_NEAR(pair.point_b.y, by, 1e-9);
  EXPECT_EQ(pair.point_a.z, 0.0);
  EXPECT_EQ(pair.point_b.z, 0.0);
}

TEST_F(NodeServices, TwoCirclesCloserThanTheWarningDistanceAreAWarningWithTheirClosestPoints) {
  const CheckCollisions::Response r = check({"probe"}, {probeNearPost()});
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(r.collisions.empty());
  EXPECT_FALSE(r.in_collision);
  ASSERT_EQ(r.warnings.size(), 1u);  // not post_near (0.12 m) nor plate (0.27 m): beyond 0.1 m
  expectPair(r.warnings[0], "probe", "post", 0.02, 0.0, 10.47, 0.0, 10.45);
  EXPECT_FALSE(r.has_min_distance);  // not asked
}

TEST_F(NodeServices, FullCheckReportsTheStoredWarningPairAndTheNameFilterAppliesToWarnings) {
  const CheckCollisions::Response r = check();
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_EQ(r.warnings.size(), 1u);
  expectPair(r.warnings[0], "plate", "post", 0.05, 0.0, 10.2, 0.0, 10.25);
  EXPECT_EQ(check({"post"}).warnings.size(), 1u);
  EXPECT_TRUE(check({"crate"}).warnings.empty());
  // The pair that collides is in collisions, never in warnings.
  EXPECT_FALSE(findWarning(r.warnings, "plate", "post_near"));
}

TEST_F(NodeServices, MinDistanceOfAStoredEllipseIsItsNearestPartnerWithItFirst) {
  const CheckCollisions::Response r = minDistanceOf("post");
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_TRUE(r.has_min_distance);
  expectPair(r.nearest, "post", "plate", 0.05, 0.0, 10.25, 0.0, 10.2);
  EXPECT_EQ(r.warnings.size(), 1u);  // the check itself is answered as usual
}

TEST_F(NodeServices, MinDistanceOfAQueryAndOfACollidingEllipse) {
  CheckCollisions::Response r = minDistanceOf("probe", {probeNearPost()});
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_TRUE(r.has_min_distance);
  expectPair(r.nearest, "probe", "post", 0.02, 0.0, 10.47, 0.0, 10.45);

  r = minDistanceOf("post_near");  // collides with plate
  ASSERT_TRUE(r.has_min_distance) << r.message;
  EXPECT_EQ(r.nearest.name_a, "post_near");
  EXPECT_EQ(r.nearest.name_b, "plate");
  EXPECT_EQ(r.nearest.distance, 0.0);
}

TEST_F(NodeServices, MinDistanceFollowsThePairRules) {
  // bumper overlaps body, but that pair is allowed: its nearest partner is crate, 1.4 m away.
  const CheckCollisions::Response r = minDistanceOf("bumper");
  ASSERT_TRUE(r.has_min_distance) << r.message;
  EXPECT_EQ(r.nearest.name_b, "crate");
  EXPECT_GT(r.nearest.distance, 1.0);
  // post is an obstacle: post_near (an obstacle 0 m away) is no partner of it.
  EXPECT_EQ(minDistanceOf("post").nearest.name_b, "plate");
}

TEST_F(NodeServices, MinDistanceOfAnEllipseThatCannotBePlacedIsNotMeasured) {
  CheckCollisions::Response r = minDistanceOf("camera");  // camera_link has no transform
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_FALSE(r.has_min_distance);
  EXPECT_CONTAINS(r.message, "min_distance_of = 'camera': not measured");
  // The stamp rules of the check: at a time the tf cache does not hold, arm_link is unavailable.
  r = check({}, {}, ros::Time::now() - ros::Duration(1000.0), "arm");
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_FALSE(r.has_min_distance);
  EXPECT_CONTAINS(r.message, "min_distance_of = 'arm'");
  EXPECT_TRUE(check({}, {}, ros::Time::now() - ros::Duration(1000.0), "post").has_min_distance);
}

TEST_F(NodeServices, AddedObstacleCollidesThenIsReplacedAndRemoved) {
  AddObstacles::Response added = add({ellipseMsg("box", "base_link", 0.0, 0.0, 0.2, 0.2)});
  ASSERT_TRUE(added.success) << added.message;
  const CollisionPair* hit = findPair(check().collisions, "body", "box");
  ASSERT_TRUE(hit);

  added = add({ellipseMsg("box", "base_link", 0.0, 3.0, 0.2, 0.2)});
  ASSERT_TRUE(added.success) << added.message;
  EXPECT_FALSE(mentions(check().collisions, "box"));
  EXPECT_TRUE(isStored("box"));

  const RemoveObstacles::Response removed = remove({"box"});
  EXPECT_TRUE(removed.success) << removed.message;
  EXPECT_FALSE(isStored("box"));
  const RemoveObstacles::Response again = remove({"box"});
  EXPECT_FALSE(again.success);
  EXPECT_CONTAINS(again.message, "names[0] = 'box'");
}

TEST_F(NodeServices, ConfiguredObstacleCanBeReplacedByTheService) {
  ASSERT_TRUE(add({ellipseMsg("spare", "base_link", 0.0, 0.0, 0.1, 0.1)}).success);
  EXPECT_TRUE(findPair(check().collisions, "body", "spare"));
  ASSERT_TRUE(add({ellipseMsg("spare", "base_link", 50.0, 50.0, 0.1, 0.1)}).success);
  EXPECT_FALSE(mentions(check().collisions, "spare"));
}

TEST_F(NodeServices, RemovingALinkIsRefusedAndNothingIsRemoved) {
  const RemoveObstacles::Response r = remove({"post", "arm"});
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "names[1] = 'arm'");
  EXPECT_CONTAINS(r.message, "configured link");
  EXPECT_TRUE(isStored("arm"));
  EXPECT_TRUE(isStored("post"));
}

TEST_F(NodeServices, EdgeOnFrameIsReportedForThatEllipseOnly) {
  ASSERT_TRUE(add({ellipseMsg("blade", "edge_on_link", 0.0, 0.0, 0.3, 0.3)}).success);
  const CheckCollisions::Response r = check();
  EXPECT_TRUE(r.success);
  EXPECT_CONTAINS(r.message, "ellipse 'blade'");
  EXPECT_CONTAINS(r.message, "edge-on");
  EXPECT_TRUE(findPair(r.collisions, "plate", "post_near"));
  EXPECT_TRUE(remove({"blade"}).success);

  const CheckCollisions::Response query =
      check({}, {ellipseMsg("knife", "edge_on_link", 0.0, 0.0, 0.3, 0.3)});
  EXPECT_FALSE(query.success);
  EXPECT_CONTAINS(query.message, "query[0]: ellipse 'knife'");
}

TEST_F(NodeServices, EllipsoidObstacleRolledAQuarterTurnIsCheckedByItsShadow) {
  // A slab 0.6 m wide, 0.1 m thin and 0.8 m tall, lying in base_link's plane as given and rolled
  // a quarter turn about its own x axis to stand on its side: its shadow is 0.3 x 0.4 m, its
  // planar ellipse would be 0.3 x 0.05. The probe 0.32 m beside its centre (radius 0.05) reaches
  // into the shadow only; the planar twin 5 m further on is missed by the same probe.
  const double quarter = M_PI / 2;
  AddObstacles::Response added =
      add({ellipsoidMsg("slab", "base_link", 0.0, 30.0, 0.3, 0.05, 0.4, quarter),
           ellipseMsg("slab_planar", "base_link", 5.0, 30.0, 0.3, 0.05)});
  ASSERT_TRUE(added.success) << added.message;
  CheckCollisions::Response r = check(
      {}, {ellipseMsg("probe", "base_link", 0.0, 30.32, 0.05, 0.05),
           ellipseMsg("probe_planar", "base_link", 5.0, 30.32, 0.05, 0.05)});
  ASSERT_TRUE(r.success) << r.message;
  const CollisionPair* hit = findPair(r.collisions, "probe", "slab");
  ASSERT_TRUE(hit);
  // The probe meets the shadow's rim at y = 30.4: scale (0.32) / (0.4 + 0.05).
  EXPECT_NEAR(hit->contact_scale, 0.32 / 0.45, 1e-9);
  EXPECT_FALSE(mentions(r.collisions, "probe_planar"));
  EXPECT_FALSE(mentions(r.collisions, "slab_planar"));

  // In edge_on_link (rolled a quarter turn about x) a planar ellipse is skipped edge-on; an
  // ellipsoid there is placed: a disk of radius 0.3 and thickness 0.04 shadows as 0.3 x 0.02 m.
  added = add({ellipsoidMsg("disk", "edge_on_link", 0.0, 0.0, 0.3, 0.3, 0.02, 0.0)});
  ASSERT_TRUE(added.success) << added.message;
  r = check({"disk"}, {ellipseMsg("touching", "base_link", 0.25, -20.0, 0.06, 0.01),
                       ellipseMsg("beside", "base_link", 0.0, -19.9, 0.05, 0.05)});
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.message.find("disk"), std::string::npos) << "the disk was skipped: " << r.message;
  EXPECT_TRUE(findPair(r.collisions, "touching", "disk"));
  EXPECT_FALSE(mentions(r.collisions, "beside")) << "the shadow is 0.02 m thin";
  EXPECT_TRUE(remove({"slab", "slab_planar", "disk"}).success);
}

struct BadObstacles {
  const char* what;
  std::vector<Ellipse> obstacles;
  const char* message_part;
};

Ellipse with(Ellipse msg, void (*change)(Ellipse&)) {
  change(msg);
  return msg;
}

TEST_F(NodeServices, EveryBadObstacleIsRefusedNamingFieldAndValue) {
  const Ellipse ok = ellipseMsg("rejected", "base_link", 0.0, 0.0, 0.2, 0.2);
  const std::vector<BadObstacles> cases = {
      {"nan x", {with(ok, [](Ellipse& m) { m.x = kNaN; })}, "obstacles[0].x = nan"},
      {"inf y", {with(ok, [](Ellipse& m) { m.y = kInf; })}, "obstacles[0].y = inf"},
      {"nan angle", {with(ok, [](Ellipse& m) { m.angle = kNaN; })}, "obstacles[0].angle = nan"},
      {"zero radius",
       {with(ok, [](Ellipse& m) { m.radius_x = 0; })},
       "obstacles[0].radius_x = 0"},
      {"negative radius",
       {with(ok, [](Ellipse& m) { m.radius_y = -1; })},
       "obstacles[0].radius_y = -1"},
      {"inf radius",
       {with(ok, [](Ellipse& m) { m.radius_x = kInf; })},
       "obstacles[0].radius_x = inf"},
      {"negative padding",
       {with(ok, [](Ellipse& m) { m.padding = -0.1; })},
       "obstacles[0].padding = -0.1"},
      {"empty name", {with(ok, [](Ellipse& m) { m.name = ""; })}, "obstacles[0].name = ''"},
      {"empty frame",
       {with(ok, [](Ellipse& m) { m.frame_id = ""; })},
       "obstacles[0].frame_id = ''"},
      {"unknown frame",
       {with(ok, [](Ellipse& m) { m.frame_id = "nowhere_link"; })},
       "obstacles[0].frame_id = 'nowhere_link'"},
      {"leading slash",
       {with(ok, [](Ellipse& m) { m.frame_id = "/base_link"; })},
       "obstacles[0].frame_id = '/base_link'"},
      {"duplicate name", {ok, ok}, "obstacles[1].name = 'rejected'"},
      {"name of a link",
       {with(ok, [](Ellipse& m) { m.name = "arm"; })},
       "obstacles[0].name = 'arm'"},
      {"negative radius_z",
       {with(ok, [](Ellipse& m) { m.radius_z = -0.4; })},
       "obstacles[0].radius_z = -0.4: expected a finite number > 0"},
      {"nan radius_z",
       {with(ok, [](Ellipse& m) { m.radius_z = kNaN; })},
       "obstacles[0].radius_z = nan: expected a finite number > 0"},
      {"inf radius_z",
       {with(ok, [](Ellipse& m) { m.radius_z = kInf; })},
       "obstacles[0].radius_z = inf: expected a finite number > 0"},
      {"roll without radius_z",
       {with(ok, [](Ellipse& m) { m.roll = 1.5; })},
       "obstacles[0].roll = 1.5: expected 0 when radius_z = 0 (a planar ellipse)"},
      {"nan pitch of an ellipsoid",
       {with(ok,
             [](Ellipse& m) {
               m.radius_z = 0.4;
               m.pitch = kNaN;
             })},
       "obstacles[0].pitch = nan: expected a finite number"},
      {"second entry bad",
       {ok, with(ok,
                 [](Ellipse& m) {
                   m.name = "second";
                   m.x = kNaN;
                 })},
       "obstacles[1].x = nan"},
  };
  for (const BadObstacles& c : cases) {
    const AddObstacles::Response r = add(c.obstacles);
    EXPECT_FALSE(r.success) << c.what;
    EXPECT_CONTAINS(r.message, c.message_part);
    EXPECT_FALSE(isStored("rejected")) << c.what << ": a refused request stored something";
    EXPECT_FALSE(isStored("second")) << c.what << ": a refused request stored something";
  }
  EXPECT_TRUE(check().success);  // still serving
}

struct BadCheck {
  const char* what;
  std::vector<std::string> names;
  std::vector<Ellipse> query;
  const char* message_part;
  std::string min_distance_of{};  // empty: not asked
};

TEST_F(NodeServices, EveryBadCheckRequestIsAnAnswerNamingFieldAndValue) {
  const Ellipse ok = ellipseMsg("p", "base_link", 0.0, 0.0, 0.2, 0.2);
  const std::vector<BadCheck> cases = {
      {"unknown name", {"ghost"}, {}, "names[0] = 'ghost'"},
      {"empty name", {""}, {}, "names[0] = ''"},
      {"duplicate name", {"arm", "arm"}, {}, "names[1] = 'arm'"},
      {"nan query", {}, {with(ok, [](Ellipse& m) { m.x = kNaN; })}, "query[0].x = nan"},
      {"inf query",
       {},
       {with(ok, [](Ellipse& m) { m.radius_y = kInf; })},
       "query[0].radius_y = inf"},
      {"zero radius",
       {},
       {with(ok, [](Ellipse& m) { m.radius_x = 0; })},
       "query[0].radius_x = 0"},
      {"negative radius",
       {},
       {with(ok, [](Ellipse& m) { m.radius_y = -2; })},
       "query[0].radius_y = -2"},
      {"empty query name",
       {},
       {with(ok, [](Ellipse& m) { m.name = ""; })},
       "query[0].name = ''"},
      {"query named like a stored ellipse",
       {},
       {with(ok, [](Ellipse& m) { m.name = "crate"; })},
       "query[0].name = 'crate'"},
      {"duplicate query", {}, {ok, ok}, "query[1].name = 'p'"},
      {"unknown query frame",
       {},
       {with(ok, [](Ellipse& m) { m.frame_id = "nowhere_link"; })},
       "query[0].frame_id = 'nowhere_link'"},
      {"unknown min_distance_of", {}, {}, "min_distance_of = 'ghost'", "ghost"},
      {"min_distance_of a refused query",
       {},
       {with(ok, [](Ellipse& m) { m.x = kNaN; })},
       "query[0].x = nan",
       "p"},
      {"min_distance_of with a bad name filter", {"ghost"}, {}, "names[0] = 'ghost'", "post"},
  };
  for (const BadCheck& c : cases) {
    const CheckCollisions::Response r = check(c.names, c.query, ros::Time(0), c.min_distance_of);
    EXPECT_FALSE(r.success) << c.what;
    EXPECT_CONTAINS(r.message, c.message_part);
    EXPECT_TRUE(r.collisions.empty()) << c.what;
    EXPECT_TRUE(r.warnings.empty()) << c.what;
    EXPECT_FALSE(r.has_min_distance) << c.what;
  }
  EXPECT_TRUE(check().success);
}

TEST_F(NodeServices, EveryBadRemoveRequestIsRefusedNamingTheName) {
  RemoveObstacles::Response r = remove({"ghost"});
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "names[0] = 'ghost'");
  r = remove({""});
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "names[0] = ''");
  r = remove({"post", "post"});
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "names[1] = 'post'");
  EXPECT_TRUE(isStored("post"));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_node_services");
}
