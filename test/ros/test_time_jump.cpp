// rostest client: simulated time that jumps back (a bag played in a loop; issue 12). The test
// owns /clock and broadcasts arm_link; after the clock jumps back 50 s the node clears its tf
// buffer, logs it, counts it in /diagnostics and keeps answering from the new transforms (tf2 would
// otherwise ignore them as older than its cache and keep the pose from "the future").
#include <diagnostic_msgs/DiagnosticArray.h>
#include <rosgraph_msgs/Clock.h>

#include <atomic>
#include <map>
#include <mutex>
#include <thread>

#include "../reliability/reliability_utils.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

/// Publishes /clock from `start` [s], 10 ms of simulated time every 10 ms of wall time, and
/// jumps to another time on request.
class TestClock {
 public:
  TestClock(ros::NodeHandle& nh, double start_s) : now_s_(start_s) {
    publisher_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    thread_ = std::thread([this] { run(); });
  }
  ~TestClock() {
    running_ = false;
    thread_.join();
  }
  void jumpTo(double s) {
    std::lock_guard<std::mutex> lock(mutex_);
    now_s_ = s;
  }

 private:
  void run() {
    while (running_) {
      rosgraph_msgs::Clock clock;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        now_s_ += 0.01;
        clock.clock = ros::Time(now_s_);
      }
      publisher_.publish(clock);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  std::mutex mutex_;
  double now_s_;
  ros::Publisher publisher_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

TEST(TimeJump, ClockJumpingBackClearsTheTfBufferAndAnswersStayCorrect) {
  ros::NodeHandle nh;
  TestClock clock(nh, 1000.0);
  ASSERT_TRUE(waitUntil([] { return ros::Time::now().toSec() > 1000.0; }, 10.0));
  NodeServiceClient client;
  ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
  client.connectServices(nh);
  Recorder<diagnostic_msgs::DiagnosticArray> diagnostics(nh, "/diagnostics");

  TestFrames frames;
  frames.set("arm_link", 1.0, 0.0);  // arm overlaps the pillar
  CheckCollisions::Response r;
  ASSERT_TRUE(waitUntil(
      [&] {
        r = client.check();
        return r.complete && findPair(r.collisions, "arm", "pillar");
      },
      10.0))
      << r.message;

  // The bag starts over 50 s earlier, with the arm somewhere else.
  clock.jumpTo(950.0);
  frames.set("arm_link", 0.0, -5.0);
  ASSERT_TRUE(waitUntil(
      [&] {
        r = client.check();
        return r.success && r.complete && !findPair(r.collisions, "arm", "pillar");
      },
      10.0))
      << "the arm is still at its pose from before the jump: " << r.message;
  EXPECT_TRUE(r.stale_frames.empty());
  EXPECT_TRUE(diagnostics.waitForAny(
      [](const diagnostic_msgs::DiagnosticArray& a) {
        for (const auto& status : a.status) {
          for (const auto& kv : status.values) {
            if (kv.key == "time jumps back" && kv.value != "0") return true;
          }
        }
        return false;
      },
      10.0));

  // And the arm moving back into the pillar is seen at once.
  frames.set("arm_link", 1.0, 0.0);
  EXPECT_TRUE(waitUntil(
      [&] {
        r = client.check();
        return r.complete && findPair(r.collisions, "arm", "pillar");
      },
      10.0));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_time_jump");
}
