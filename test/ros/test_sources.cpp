// rostest client: two scan sources in one node (scene: sources_scene.yaml). Each scanner's
// obstacles are named by its source and replaced by its own scans only; when the rear scanner
// stops, the next ~check_collisions answer is incomplete and the gate INCOMPLETE, both naming it,
// while the front scanner's obstacles keep being replaced and the rear's stay; /diagnostics shows
// each source's rate, age and obstacle count. A range source's reading covers the cone's arc and a
// reading at max_range is free; a cloud source's points in its z band become obstacles.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/Range.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <atomic>
#include <cmath>
#include <map>
#include <thread>

#include "node_test_utils.h"
#include "xyz_cloud.h"

namespace ellipse_collision {
namespace test {
namespace {

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

constexpr double kTimeoutS = 0.5;  // sources_scene.yaml

/// A scan in base_link of 61 beams over +-0.3 rad around `heading` [rad], every return at `range`
/// [m]: a short arc of wall.
sensor_msgs::LaserScan wallScan(double heading, double range) {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "base_link";
  scan.header.stamp = ros::Time::now();
  scan.angle_min = static_cast<float>(heading - 0.3);
  scan.angle_increment = 0.01f;
  scan.angle_max = static_cast<float>(scan.angle_min + 60 * scan.angle_increment);
  scan.range_min = 0.05f;
  scan.range_max = 10.0f;
  scan.ranges.assign(61, static_cast<float>(range));
  return scan;
}

/// The names `probe` (a query circle of 0.3 m at (x, 0)) collides with.
std::vector<std::string> touchedBy(const CheckCollisions::Response& response,
                                   const std::string& probe) {
  std::vector<std::string> names;
  for (const CollisionPair& pair : response.collisions) {
    if (pair.name_a == probe) names.push_back(pair.name_b);
    if (pair.name_b == probe) names.push_back(pair.name_a);
  }
  return names;
}

bool allStartWith(const std::vector<std::string>& names, const std::string& prefix) {
  if (names.empty()) return false;
  for (const std::string& name : names) {
    if (name.rfind(prefix, 0) != 0) return false;
  }
  return true;
}

class Sources : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
    connectServices(nh_);
    front_pub_ = nh_.advertise<sensor_msgs::LaserScan>("/front/scan", 5);
    rear_pub_ = nh_.advertise<sensor_msgs::LaserScan>("/rear/scan", 5);
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(nodeTopic("cmd_vel_in"), 5);
    ASSERT_TRUE(waitUntil(
        [&] {
          return front_pub_.getNumSubscribers() > 0 && rear_pub_.getNumSubscribers() > 0 &&
                 cmd_pub_.getNumSubscribers() > 0;
        },
        30.0));
    // Both scanners at 20 Hz, as drivers would, until told to stop.
    publisher_ = std::thread([this] {
      ros::WallRate rate(20.0);
      while (running_) {
        front_pub_.publish(wallScan(0.0, front_range_.load()));
        if (rear_on_) rear_pub_.publish(wallScan(M_PI, 1.5));
        rate.sleep();
      }
    });
  }
  void TearDown() override {
    running_ = false;
    if (publisher_.joinable()) publisher_.join();
  }

  /// A check with probes at the front wall's two places and at the rear wall.
  CheckCollisions::Response probe() {
    return check({}, {ellipseMsg("probe_near", "base_link", 2.0, 0.0, 0.3, 0.3),
                      ellipseMsg("probe_far", "base_link", 2.6, 0.0, 0.3, 0.3),
                      ellipseMsg("probe_rear", "base_link", -1.5, 0.0, 0.3, 0.3)});
  }

  ros::NodeHandle nh_;
  ros::Publisher front_pub_, rear_pub_, cmd_pub_;
  std::atomic<bool> running_{true};
  std::atomic<bool> rear_on_{true};
  std::atomic<double> front_range_{2.0};
  std::thread publisher_;
};

TEST_F(Sources, ASilentScannerMakesAnswersAndTheGateIncompleteNamingIt) {
  Recorder<GateState> gate(nh_, nodeTopic("gate_state"));
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  geometry_msgs::Twist slow;
  slow.linear.x = 0.1;

  // Both scanners publish: every answer complete, each scanner's obstacles under its name.
  CheckCollisions::Response r;
  ASSERT_TRUE(waitUntil(
      [&] {
        r = probe();
        return r.success && r.complete && !touchedBy(r, "probe_near").empty() &&
               !touchedBy(r, "probe_rear").empty();
      },
      10.0))
      << r.message;
  EXPECT_TRUE(allStartWith(touchedBy(r, "probe_near"), "front_scan/"));
  EXPECT_TRUE(allStartWith(touchedBy(r, "probe_rear"), "rear_scan/"));
  EXPECT_TRUE(touchedBy(r, "probe_far").empty());
  cmd_pub_.publish(slow);
  GateState state;
  ASSERT_TRUE(gate.waitForLatest([](const GateState&) { return true; }, 5.0, &state));
  EXPECT_NE(state.action, "INCOMPLETE") << state.reason;

  // The rear scanner stops; the front wall moves back from 2 m to 2.6 m.
  rear_on_ = false;
  front_range_ = 2.6;
  ros::WallDuration(kTimeoutS + 0.3).sleep();
  r = probe();
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_FALSE(r.complete);
  EXPECT_CONTAINS(r.message, "source 'rear_scan' silent for");
  EXPECT_TRUE(allStartWith(touchedBy(r, "probe_far"), "front_scan/"))
      << "the front scanner's obstacles follow its scans";
  EXPECT_TRUE(touchedBy(r, "probe_near").empty()) << "its old ones were replaced";
  EXPECT_TRUE(allStartWith(touchedBy(r, "probe_rear"), "rear_scan/"))
      << "the silent scanner's last obstacles stay";

  const std::size_t before = gate.count();
  cmd_pub_.publish(slow);
  ASSERT_TRUE(waitUntil([&] { return gate.count() > before; }, 5.0));
  state = gate.all().back();
  EXPECT_EQ(state.action, "INCOMPLETE");
  EXPECT_CONTAINS(state.reason, "source 'rear_scan' silent for");
  EXPECT_EQ(state.output.linear.x, 0.0);

  diagnostic_msgs::DiagnosticArray shown;
  ASSERT_TRUE(diagnostics.waitForLatest(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return !a.status.empty() &&
               a.status[0].name.find("ellipse_collision") != std::string::npos &&
               a.status[0].message.find("rear_scan") != std::string::npos;
      },
      5.0, &shown));
  std::map<std::string, std::string> values;
  for (const auto& kv : shown.status[0].values) values[kv.key] = kv.value;
  EXPECT_EQ(shown.status[0].level, diagnostic_msgs::DiagnosticStatus::ERROR);
  EXPECT_GT(std::stod(values.at("source 'rear_scan' age [s]")), kTimeoutS);
  EXPECT_LT(std::stod(values.at("source 'front_scan' age [s]")), kTimeoutS);
  EXPECT_GT(std::stod(values.at("source 'front_scan' rate [Hz]")), 5.0);
  EXPECT_NE(values.at("source 'front_scan' obstacles"), "0");
  EXPECT_EQ(values.at("source 'obstacles' age [s]"), "no message yet");

  // The rear scanner resumes: complete again.
  rear_on_ = true;
  ASSERT_TRUE(waitUntil(
      [&] {
        r = probe();
        return r.success && r.complete;
      },
      5.0))
      << r.message;
}

TEST_F(Sources, ARangeReadingCoversItsArcAndACloudItsPointsInTheBand) {
  ros::Publisher sonar = nh_.advertise<sensor_msgs::Range>("/sonar/range", 5);
  ros::Publisher depth = nh_.advertise<sensor_msgs::PointCloud2>("/depth/points", 5);
  ASSERT_TRUE(waitUntil(
      [&] { return sonar.getNumSubscribers() > 0 && depth.getNumSubscribers() > 0; }, 30.0));
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh_, "/diagnostics");
  sensor_msgs::Range reading;
  reading.header.frame_id = "base_link";
  reading.radiation_type = sensor_msgs::Range::ULTRASOUND;
  reading.field_of_view = 0.4f;
  reading.min_range = 0.02f;
  reading.max_range = 4.0f;
  const auto probes = [&] {
    return check({}, {ellipseMsg("probe_ahead", "base_link", 1.0, 0.0, 0.05, 0.05),
                      ellipseMsg("probe_arc_end", "base_link", 1.0 * std::cos(0.2),
                                 1.0 * std::sin(0.2), 0.01, 0.01),
                      ellipseMsg("probe_right", "base_link", 0.0, -2.0, 0.1, 0.1),
                      ellipseMsg("probe_left", "base_link", 0.0, 2.0, 0.1, 0.1)});
  };

  // Something 1 m ahead: one obstacle over the cone's arc, to its ends.
  CheckCollisions::Response r;
  ASSERT_TRUE(waitUntil(
      [&] {
        reading.header.stamp = ros::Time::now();
        reading.range = 1.0f;
        sonar.publish(reading);
        r = probes();
        return r.success && !touchedBy(r, "probe_ahead").empty();
      },
      10.0))
      << r.message;
  EXPECT_EQ(touchedBy(r, "probe_ahead"), std::vector<std::string>{"sonar/range"});
  EXPECT_EQ(touchedBy(r, "probe_arc_end"), std::vector<std::string>{"sonar/range"});
  // Nothing within max_range: free.
  ASSERT_TRUE(waitUntil(
      [&] {
        reading.header.stamp = ros::Time::now();
        reading.range = 4.0f;
        sonar.publish(reading);
        r = probes();
        return r.success && touchedBy(r, "probe_ahead").empty();
      },
      10.0))
      << "a reading at max_range is free";

  // A wall segment 2 m to the right at 0.5 m height, a shelf 2 m to the left at 3 m (above z_max).
  std::vector<Eigen::Vector3f> points;
  for (int i = -10; i <= 10; ++i) {
    points.emplace_back(0.02f * static_cast<float>(i), -2.0f, 0.5f);
    points.emplace_back(0.02f * static_cast<float>(i), 2.0f, 3.0f);
  }
  ASSERT_TRUE(waitUntil(
      [&] {
        depth.publish(test::xyzCloud(points, "base_link", ros::Time::now()));
        r = probes();
        return r.success && !touchedBy(r, "probe_right").empty();
      },
      10.0))
      << r.message;
  EXPECT_TRUE(allStartWith(touchedBy(r, "probe_right"), "depth/"));
  EXPECT_TRUE(touchedBy(r, "probe_left").empty()) << "points above z_max are not obstacles";

  // A cloud without y and z is refused, its source named; the last obstacles stay.
  sensor_msgs::PointCloud2 bad;
  bad.header.frame_id = "base_link";
  sensor_msgs::PointCloud2Modifier(bad).setPointCloud2Fields(1, "x", 1,
                                                             sensor_msgs::PointField::FLOAT32);
  depth.publish(bad);
  EXPECT_TRUE(diagnostics.waitForLatest(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        return !a.status.empty() &&
               a.status[0].message.find("last message refused: source 'depth'") !=
                   std::string::npos;
      },
      5.0));
  EXPECT_TRUE(allStartWith(touchedBy(probes(), "probe_right"), "depth/"));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_sources");
}
