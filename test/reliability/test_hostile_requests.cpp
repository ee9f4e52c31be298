// rostest client: hostile requests to every service and to the ~obstacles topic (scene:
// reliability_scene.yaml). The basic bad fields (NaN, inf, radius <= 0, empty, duplicate and
// unknown names and frames) of each service are in test/ros/test_node_services.cpp; this battery
// adds the topic, values the core cannot take although they are finite and positive, 100,000
// ellipses in one request, a frame that stops being published and a transform that jumps far
// away. Every test ends by checking that a normal request still gets the correct answer.
#include <diagnostic_msgs/DiagnosticArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <utility>

#include "../ros/node_test_utils.h"
#include "reliability_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kHuge = 100000;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

using Pairs = std::set<std::pair<std::string, std::string>>;

Pairs pairsOf(const std::vector<CollisionPair>& collisions) {
  Pairs pairs;
  for (const CollisionPair& p : collisions) pairs.emplace(p.name_a, p.name_b);
  return pairs;
}

std::string text(const Pairs& pairs) {
  std::string out;
  for (const auto& p : pairs) out += "(" + p.first + ", " + p.second + ") ";
  return out.empty() ? "none" : out;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A finite, positive value outside the range the core accepts (ellipse.h: radii in
/// [1e-9, 1e9] m, centres within 1e9 m), and the key an error must name.
struct OutOfRange {
  const char* what;
  void (*spoil)(Ellipse&);
  const char* key;
};

const std::vector<OutOfRange>& outOfRangeCases() {
  static const std::vector<OutOfRange> cases = {
      {"radius 1e-12 m", [](Ellipse& m) { m.radius_x = 1e-12; }, "radius_x"},
      {"subnormal radius", [](Ellipse& m) { m.radius_y = 5e-324; }, "radius_y"},
      {"radius 1e12 m", [](Ellipse& m) { m.radius_y = 1e12; }, "radius_y"},
      {"centre 1e12 m away", [](Ellipse& m) { m.x = 1e12; }, "x"},
      {"centre 1e300 m away", [](Ellipse& m) { m.y = -1e300; }, "y"},
      {"padding 1e300 m", [](Ellipse& m) { m.padding = 1e300; }, "padding"},
  };
  return cases;
}

class HostileRequests : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(connectServicesAndObstacles(nh_, obstacles_, 10));
    expectNormalAnswer("before the test");
  }

  void TearDown() override { expectNormalAnswer("after the test"); }

  /// The scene's answer to a plain check, worked out by hand in reliability_scene.yaml.
  void expectNormalAnswer(const std::string& when) {
    const CheckCollisions::Response r = check();
    EXPECT_TRUE(r.success) << when << ": " << r.message;
    EXPECT_TRUE(r.unavailable_frames.empty()) << when;
    ASSERT_EQ(r.collisions.size(), 1u) << when << ": " << text(pairsOf(r.collisions));
    EXPECT_EQ(r.collisions[0].name_a, "arm");
    EXPECT_EQ(r.collisions[0].name_b, "pillar");
    EXPECT_NEAR(r.collisions[0].contact_scale, 0.6, 1e-9);
  }

  ros::NodeHandle nh_;
  ros::Publisher obstacles_;
};

TEST_F(HostileRequests, ServicesRefuseFiniteValuesTheCoreCannotTakeNamingEntryAndKey) {
  const Ellipse ok = ellipseMsg("far_out", "base_link", 20.0, 0.0, 0.2, 0.2);
  for (const OutOfRange& c : outOfRangeCases()) {
    Ellipse bad = ok;
    c.spoil(bad);
    // Accepting it would be worse than refusing: the node could never check it.
    const AddObstacles::Response added = add({bad});
    EXPECT_FALSE(added.success) << c.what << ": accepted an obstacle the core cannot check";
    EXPECT_CONTAINS(added.message, std::string("obstacles[0].") + c.key);
    if (added.success) remove({"far_out"});

    bad.name = "q";
    const CheckCollisions::Response checked = check({}, {bad});
    EXPECT_FALSE(checked.success) << c.what;
    EXPECT_CONTAINS(checked.message, "query[0]");
    EXPECT_CONTAINS(checked.message, c.key);
    EXPECT_TRUE(checked.collisions.empty()) << c.what;
  }
}

TEST_F(HostileRequests, ObstaclesTopicRefusesEveryBadMessageWholeAndKeepsThePreviousSet) {
  Recorder<CollisionState> collisions(nh_, nodeTopic("collisions"));
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  const Ellipse good = ellipseMsg("stream_ok", "", 0.0, 0.0, 0.1, 0.1);  // on body
  publishObstacles(obstacles_, "base_link", {good});
  ASSERT_TRUE(collisions.waitForLatest(
      [](const CollisionState& s) { return findPair(s.collisions, "body", "stream_ok"); }, 10.0));

  const Ellipse ok = ellipseMsg("stream_bad", "", 0.0, 0.0, 0.1, 0.1);
  struct Case {
    const char* what;
    std::string header_frame;
    std::vector<Ellipse> ellipses;
    std::string message_part;
  };
  const auto with = [&ok](void (*spoil)(Ellipse&)) {
    Ellipse m = ok;
    spoil(m);
    return m;
  };
  std::vector<Case> cases = {
      {"nan x",
       "base_link",
       {good, with([](Ellipse& m) { m.x = kNaN; })},
       "ellipses[1].x = nan"},
      {"inf y", "base_link", {with([](Ellipse& m) { m.y = kInf; })}, "ellipses[0].y = inf"},
      {"-inf angle",
       "base_link",
       {with([](Ellipse& m) { m.angle = -kInf; })},
       "ellipses[0].angle = -inf"},
      {"zero radius",
       "base_link",
       {with([](Ellipse& m) { m.radius_x = 0.0; })},
       "ellipses[0].radius_x = 0"},
      {"negative radius",
       "base_link",
       {with([](Ellipse& m) { m.radius_y = -0.1; })},
       "ellipses[0].radius_y = -0.1"},
      {"nan radius",
       "base_link",
       {with([](Ellipse& m) { m.radius_y = kNaN; })},
       "ellipses[0].radius_y = nan"},
      {"inf padding",
       "base_link",
       {with([](Ellipse& m) { m.padding = kInf; })},
       "ellipses[0].padding = inf"},
      {"negative padding",
       "base_link",
       {with([](Ellipse& m) { m.padding = -1.0; })},
       "ellipses[0].padding = -1"},
      {"empty name",
       "base_link",
       {with([](Ellipse& m) { m.name = ""; })},
       "ellipses[0].name = ''"},
      {"duplicate names", "base_link", {ok, ok}, "ellipses[1].name = 'stream_bad'"},
      {"name of a link",
       "base_link",
       {with([](Ellipse& m) { m.name = "body"; })},
       "ellipses[0].name = 'body'"},
      {"name of a configured obstacle",
       "base_link",
       {with([](Ellipse& m) { m.name = "spare"; })},
       "ellipses[0].name = 'spare'"},
      {"unknown frame", "nowhere_link", {ok}, "ellipses[0].frame_id = 'nowhere_link'"},
      {"no frame at all", "", {ok}, "ellipses[0].frame_id = ''"},
      {"leading slash", "/base_link", {ok}, "ellipses[0].frame_id = '/base_link'"},
  };
  for (const OutOfRange& c : outOfRangeCases()) {
    cases.push_back({c.what, "base_link", {with(c.spoil)}, std::string("ellipses[0].") + c.key});
  }

  for (const Case& c : cases) {
    const std::size_t from = diagnostics.count();
    publishObstacles(obstacles_, c.header_frame, c.ellipses);
    EXPECT_TRUE(diagnostics.waitForAny(
        [&c](const diagnostic_msgs::DiagnosticArray& a) {
          return !a.status.empty() && a.status[0].message.find("last ~obstacles message refused: " +
                                                               c.message_part) != std::string::npos;
        },
        5.0, from))
        << c.what << ": no diagnostic naming " << c.message_part;
    // Refused as a whole: the previous topic set stays and nothing of the bad message appears.
    const std::size_t states = collisions.count();
    ASSERT_TRUE(collisions.waitForAny([](const CollisionState&) { return true; }, 5.0, states));
    CollisionState state;
    ASSERT_TRUE(collisions.waitForLatest([](const CollisionState&) { return true; }, 1.0, &state));
    EXPECT_TRUE(findPair(state.collisions, "body", "stream_ok")) << c.what;
    EXPECT_FALSE(mentions(state.collisions, "stream_bad")) << c.what;
    EXPECT_TRUE(isStored("stream_ok")) << c.what;
    EXPECT_FALSE(isStored("stream_bad")) << c.what;
  }

  publishObstacles(obstacles_, "base_link", {});
  EXPECT_TRUE(waitUntil([this] { return !isStored("stream_ok"); }, 10.0));
}

TEST_F(HostileRequests, HundredThousandQueryEllipsesGetTheCorrectAnswer) {
  // A grid far from the scene; every 1000th query sits on `spare` (concentric: contact scale 0).
  std::vector<Ellipse> query;
  query.reserve(kHuge);
  Pairs expected = {{"arm", "pillar"}};
  for (int i = 0; i < kHuge; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "q%06d", i);
    const bool on_spare = i % 1000 == 0;
    query.push_back(ellipseMsg(name, "base_link", on_spare ? 50.0 : 100.0 + 0.5 * (i % 300),
                               on_spare ? 50.0 : 100.0 + 0.5 * (i / 300), 0.1, 0.1));
    if (on_spare) expected.emplace(name, "spare");
  }
  auto start = std::chrono::steady_clock::now();
  CheckCollisions::Response r = check({}, query);
  const double seconds = secondsSince(start);
  std::printf("100000 query ellipses answered in %.2f s\n", seconds);
  RecordProperty("query_100000_seconds", std::to_string(seconds));
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_EQ(pairsOf(r.collisions), expected) << text(pairsOf(r.collisions));
  for (const CollisionPair& p : r.collisions) {
    if (p.name_b == "spare") {
      EXPECT_EQ(p.contact_scale, 0.0) << p.name_a;
    }
  }
  EXPECT_LT(seconds, 20.0) << "a 100,000-ellipse query blocks the node for too long";

  // The same request with one bad entry at the very end: refused, naming it.
  query.back().x = kNaN;
  start = std::chrono::steady_clock::now();
  r = check({}, query);
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "query[99999].x = nan");
  EXPECT_TRUE(r.collisions.empty());
  EXPECT_LT(secondsSince(start), 20.0);

  // 100,000 names, the last one unknown.
  std::vector<std::string> names(kHuge, "arm");
  for (int i = 0; i < kHuge; ++i) names[i] = query[i].name;
  query.back().x = 100.0;
  names.back() = "ghost";
  r = check(names, query);
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "names[99999] = 'ghost'");
}

TEST_F(HostileRequests, HundredThousandObstaclesAreAddedCheckedAndRemoved) {
  std::vector<Ellipse> obstacles;
  std::vector<std::string> names;
  for (int i = 0; i < kHuge; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "o%06d", i);
    obstacles.push_back(
        ellipseMsg(name, "base_link", 100.0 + 0.5 * (i % 300), 100.0 + 0.5 * (i / 300), 0.1, 0.1));
    names.push_back(name);
  }
  auto start = std::chrono::steady_clock::now();
  const AddObstacles::Response added = add(obstacles);
  std::printf("100000 obstacles added in %.2f s\n", secondsSince(start));
  ASSERT_TRUE(added.success) << added.message;

  start = std::chrono::steady_clock::now();
  const CheckCollisions::Response r = check();
  const double seconds = secondsSince(start);
  std::printf("check with 100000 stored obstacles answered in %.2f s\n", seconds);
  RecordProperty("check_100000_obstacles_seconds", std::to_string(seconds));
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_EQ(pairsOf(r.collisions), (Pairs{{"arm", "pillar"}}));
  EXPECT_LT(seconds, 20.0);

  // Removing them all but one unknown name removes nothing; then all of them go.
  std::vector<std::string> with_unknown = names;
  with_unknown.back() = "ghost";
  RemoveObstacles::Response removed = remove(with_unknown);
  EXPECT_FALSE(removed.success);
  EXPECT_CONTAINS(removed.message, "names[99999] = 'ghost'");
  EXPECT_TRUE(isStored("o000000"));
  removed = remove(names);
  EXPECT_TRUE(removed.success) << removed.message;
  EXPECT_FALSE(isStored("o000000"));
  EXPECT_FALSE(isStored("o099999"));
}

TEST_F(HostileRequests, FrameThatStopsBeingPublishedIsUnavailableWhileOthersAreStillChecked) {
  TestFrames frames;
  frames.set("vanishing_link", 0.0, 0.0);
  AddObstacles::Response added;
  ASSERT_TRUE(waitUntil(
      [&] {
        added = add({ellipseMsg("ghost", "vanishing_link", 0.0, 0.0, 0.1, 0.1)});
        return added.success;
      },
      10.0))
      << added.message;
  EXPECT_TRUE(findPair(check().collisions, "body", "ghost"));

  frames.stop("vanishing_link");
  ros::Duration(1.0).sleep();
  // At the current time the frame has no transform: listed, and every other pair still checked,
  // within the tf timeout rather than hanging.
  const auto start = std::chrono::steady_clock::now();
  CheckCollisions::Response r = check({}, {}, ros::Time::now());
  EXPECT_LT(secondsSince(start), 5.0);
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.unavailable_frames, std::vector<std::string>{"vanishing_link"});
  EXPECT_EQ(pairsOf(r.collisions), (Pairs{{"arm", "pillar"}}));
  // Latest-available checks (stamp 0) still answer, but no longer at the last known pose: the
  // transform is older than max_transform_age (0.5 s, the default), so the frame is stale and the
  // answer incomplete (issue 12; before it, the ghost was checked at its last pose forever).
  r = check();
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_TRUE(findPair(r.collisions, "arm", "pillar"));
  EXPECT_FALSE(findPair(r.collisions, "body", "ghost"));
  EXPECT_EQ(r.stale_frames, std::vector<std::string>{"vanishing_link"});
  EXPECT_TRUE(r.unavailable_frames.empty());
  EXPECT_FALSE(r.complete);
  // A new query in the vanished frame is a clear error.
  r = check({}, {ellipseMsg("q", "vanishing_link", 0.0, 0.0, 0.1, 0.1)}, ros::Time::now());
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "query[0].frame_id = 'vanishing_link'");

  // Published again: back in the checks.
  frames.set("vanishing_link", 0.0, 0.0);
  EXPECT_TRUE(waitUntil(
      [&] {
        const CheckCollisions::Response now = check({}, {}, ros::Time::now() - ros::Duration(0.1));
        return now.success && findPair(now.collisions, "body", "ghost");
      },
      10.0));
  EXPECT_TRUE(waitUntil([&] { return check().complete; }, 10.0)) << "fresh again at once";
  EXPECT_TRUE(remove({"ghost"}).success);
}

TEST_F(HostileRequests, TransformJumpingFarAwayGivesCorrectAnswersAndRecovers) {
  Recorder<CollisionState> collisions(nh_, nodeTopic("collisions"));
  TestFrames frames;
  frames.set("jumping_link", 0.0, 0.0);
  AddObstacles::Response added;
  ASSERT_TRUE(waitUntil(
      [&] {
        added = add({ellipseMsg("jumper", "jumping_link", 0.0, 0.0, 0.1, 0.1)});
        return added.success;
      },
      10.0))
      << added.message;
  EXPECT_TRUE(waitUntil([&] { return findPair(check().collisions, "body", "jumper"); }, 5.0));

  // Far, but within what the core takes: simply no collision.
  frames.set("jumping_link", 1e6, 0.0);
  EXPECT_TRUE(waitUntil(
      [&] {
        const CheckCollisions::Response r = check();
        return r.success && pairsOf(r.collisions) == Pairs{{"arm", "pillar"}};
      },
      5.0));

  // Beyond it (2e9 m, 1e300 m): the jumper cannot be checked, which must neither hide the other
  // collisions nor fail the whole check; the answer says what was left out.
  for (const double x : {2e9, 1e300}) {
    frames.set("jumping_link", x, 0.0);
    ros::Duration(0.5).sleep();
    const CheckCollisions::Response r = check();
    EXPECT_TRUE(r.success) << "x = " << x << ": " << r.message;
    EXPECT_EQ(pairsOf(r.collisions), (Pairs{{"arm", "pillar"}})) << "x = " << x;
    const bool reported =
        r.message.find("jumper") != std::string::npos ||
        std::count(r.unavailable_frames.begin(), r.unavailable_frames.end(), "jumping_link") > 0;
    EXPECT_TRUE(reported) << "x = " << x << ": the answer does not say that jumper was left out";
    CollisionState state;
    const std::size_t from = collisions.count();
    ASSERT_TRUE(collisions.waitForAny([](const CollisionState&) { return true; }, 5.0, from));
    ASSERT_TRUE(collisions.waitForLatest([](const CollisionState&) { return true; }, 1.0, &state));
    EXPECT_TRUE(findPair(state.collisions, "arm", "pillar"))
        << "x = " << x << ": ~collisions lost the arm/pillar collision";
  }

  // A NaN transform is refused by tf itself; then back home: the collision returns.
  frames.set("jumping_link", kNaN, 0.0);
  ros::Duration(0.3).sleep();
  EXPECT_TRUE(check().success);
  frames.set("jumping_link", 0.0, 0.0);
  EXPECT_TRUE(waitUntil([&] { return findPair(check().collisions, "body", "jumper"); }, 5.0));
  EXPECT_TRUE(remove({"jumper"}).success);
}

TEST_F(HostileRequests, LongAndUnusualNamesRoundTripExactly) {
  // Longer than max_name_length (256, the default; issue 12): refused naming the limit and value.
  const AddObstacles::Response too_long =
      add({ellipseMsg(std::string(10000, 'n'), "base_link", 0.0, 0.0, 0.1, 0.1)});
  EXPECT_FALSE(too_long.success);
  EXPECT_EQ(too_long.message,
            "obstacles[0].name: expected at most max_name_length = 256 characters, got 10000");
  const std::vector<std::string> names = {std::string(256, 'n'), "line\nbreak", "tab\there",
                                          "\xc3\xbc-umlaut", "slash/and space"};
  for (const std::string& name : names) {
    const AddObstacles::Response added = add({ellipseMsg(name, "base_link", 0.0, 0.0, 0.1, 0.1)});
    ASSERT_TRUE(added.success) << added.message;
    const CheckCollisions::Response r = check({name});
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_TRUE(findPair(r.collisions, "body", name)) << text(pairsOf(r.collisions));
    EXPECT_TRUE(remove({name}).success);
  }
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_hostile_requests");
}
