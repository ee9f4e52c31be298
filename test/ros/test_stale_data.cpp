// rostest client: stale and lost data (issue 12; scene: stale_scene.yaml). A tf publisher that dies
// makes its frame stale within max_transform_age plus one check period, `complete` is false and
// /diagnostics WARN then ERROR meanwhile, and the frame is fresh again as soon as it is published;
// a static frame never goes stale; an obstacle stream that stops is dropped after obstacle_timeout
// and the drop is counted in /diagnostics.
#include <diagnostic_msgs/DiagnosticArray.h>

#include <chrono>
#include <map>

#include "../reliability/reliability_utils.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

constexpr double kMaxTransformAgeS = 0.5;  // stale_scene.yaml
constexpr double kPeriodS = 0.1;           // rate 10 Hz
constexpr double kObstacleTimeoutS = 1.0;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::map<std::string, std::string> valuesOf(const diagnostic_msgs::DiagnosticStatus& status) {
  std::map<std::string, std::string> values;
  for (const auto& kv : status.values) values[kv.key] = kv.value;
  return values;
}

bool isOurs(const diagnostic_msgs::DiagnosticArray& a) {
  return !a.status.empty() && a.status[0].name.find("ellipse_collision") != std::string::npos;
}

class StaleData : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(connectServicesAndObstacles(nh_, obstacles_, 10));
  }

  ros::NodeHandle nh_;
  ros::Publisher obstacles_;
};

TEST_F(StaleData, StaticFrameNeverGoesStale) {
  TestFrames frames;
  frames.set("arm_link", 0.0, -5.0);
  // The static transform was sent once at start; long after max_transform_age it is still used.
  ros::Duration(2.0 * kMaxTransformAgeS + 0.5).sleep();
  CheckCollisions::Response r;
  ASSERT_TRUE(waitUntil(
      [&] {
        r = check();
        return r.success && r.complete;
      },
      10.0))
      << r.message;
  EXPECT_TRUE(r.stale_frames.empty());
  EXPECT_TRUE(r.unavailable_frames.empty());
  EXPECT_EQ(r.message, "");
}

TEST_F(StaleData, DyingTfPublisherMakesItsFrameStaleUntilItResumes) {
  Recorder<CollisionState> states(nh_, nodeTopic("collisions"));
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  TestFrames frames;
  frames.set("arm_link", 1.0, 0.0);  // arm overlaps the pillar
  ASSERT_TRUE(states.waitForLatest(
      [](const CollisionState& s) { return s.complete && findPair(s.collisions, "arm", "pillar"); },
      10.0));

  frames.stop("arm_link");
  const auto stopped = std::chrono::steady_clock::now();
  CollisionState state;
  ASSERT_TRUE(states.waitForLatest(
      [](const CollisionState& s) {
        return s.stale_frames == std::vector<std::string>{"arm_link"};
      },
      5.0, &state));
  const double latency_s = secondsSince(stopped);
  std::printf("stale detection latency: %.3f s (max_transform_age %.1f s, period %.1f s)\n",
              latency_s, kMaxTransformAgeS, kPeriodS);
  // Within max_transform_age plus one period (and a little for the test's own scheduling).
  EXPECT_LT(latency_s, kMaxTransformAgeS + kPeriodS + 0.15);
  EXPECT_GT(latency_s, kMaxTransformAgeS - 0.05);
  EXPECT_FALSE(state.complete);
  EXPECT_FALSE(findPair(state.collisions, "arm", "pillar")) << "not checked at the old pose";
  EXPECT_TRUE(state.unavailable_frames.empty());

  // The service says the same for latest-transform checks.
  CheckCollisions::Response r = check();
  EXPECT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.stale_frames, std::vector<std::string>{"arm_link"});
  EXPECT_FALSE(r.complete);
  EXPECT_CONTAINS(r.message, "arm: frame 'arm_link' stale");
  // A query in the stale frame is refused rather than placed at the old pose.
  r = check({}, {ellipseMsg("probe", "arm_link", 0.0, 0.0, 0.1, 0.1)});
  EXPECT_FALSE(r.success);
  EXPECT_CONTAINS(r.message, "query[0].frame_id = 'arm_link'");
  EXPECT_CONTAINS(r.message, "older than max_transform_age 0.5 s");

  // WARN while incomplete, ERROR once the frame has been stale for more than 1 s.
  diagnostic_msgs::DiagnosticArray array;
  ASSERT_TRUE(diagnostics.waitForLatest(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return isOurs(a) && a.status[0].level == diagnostic_msgs::DiagnosticStatus::ERROR;
      },
      5.0, &array));
  std::map<std::string, std::string> values = valuesOf(array.status[0]);
  EXPECT_EQ(values["stale frames"], "arm_link");
  EXPECT_EQ(values["complete"], "false");
  EXPECT_CONTAINS(values["missing for [s]"], "arm_link: ");
  EXPECT_TRUE(diagnostics.waitForAny(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return isOurs(a) && a.status[0].level == diagnostic_msgs::DiagnosticStatus::WARN &&
               valuesOf(a.status[0])["stale frames"] == "arm_link";
      },
      0.0))
      << "the first report after the frame went stale is WARN";

  // Published again: fresh again at the next check.
  frames.set("arm_link", 1.0, 0.0);
  const auto resumed = std::chrono::steady_clock::now();
  ASSERT_TRUE(states.waitForLatest(
      [](const CollisionState& s) { return s.complete && findPair(s.collisions, "arm", "pillar"); },
      5.0));
  const double recovery_s = secondsSince(resumed);
  std::printf("fresh again after: %.3f s\n", recovery_s);
  EXPECT_LT(recovery_s, 2.0 * kPeriodS + 0.15);
  EXPECT_TRUE(check().complete);
  ASSERT_TRUE(diagnostics.waitForLatest(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return isOurs(a) && valuesOf(a.status[0])["complete"] == "true";
      },
      5.0, &array));
  EXPECT_EQ(array.status[0].level, diagnostic_msgs::DiagnosticStatus::OK) << array.status[0].message;
}

TEST_F(StaleData, StoppedObstacleStreamIsDroppedAfterTheTimeout) {
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  TestFrames frames;
  frames.set("arm_link", 0.0, -5.0);
  // A perception node publishing a rock on the body, then stopping.
  ASSERT_TRUE(waitUntil(
      [&] {
        publishObstacles(obstacles_, "base_link", {ellipseMsg("rock", "", 0.0, 0.0, 0.1, 0.1)});
        return findPair(check().collisions, "body", "rock");
      },
      10.0));
  const auto last_message = std::chrono::steady_clock::now();
  ASSERT_TRUE(waitUntil([&] { return !isStored("rock"); }, 5.0));
  const double dropped_after_s = secondsSince(last_message);
  std::printf("stopped obstacle stream dropped after: %.3f s (obstacle_timeout %.1f s)\n",
              dropped_after_s, kObstacleTimeoutS);
  EXPECT_GT(dropped_after_s, kObstacleTimeoutS - 0.1);
  EXPECT_LT(dropped_after_s, kObstacleTimeoutS + kPeriodS + 0.3);
  EXPECT_FALSE(findPair(check().collisions, "body", "rock"));
  EXPECT_TRUE(diagnostics.waitForLatest(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return isOurs(a) && valuesOf(a.status[0])["dropped obstacles (obstacle_timeout)"] != "0";
      },
      5.0));

  // A message that is already too old when it arrives is dropped at the next check.
  EllipseArray old;
  old.header.frame_id = "base_link";
  old.header.stamp = ros::Time::now() - ros::Duration(5.0);
  old.ellipses = {ellipseMsg("old_rock", "", 0.0, 0.0, 0.1, 0.1)};
  obstacles_.publish(old);
  ros::Duration(0.5).sleep();
  EXPECT_FALSE(isStored("old_rock"));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_stale_data");
}
