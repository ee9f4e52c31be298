// rostest client: a storm of ~add_obstacles / ~remove_obstacles calls and ~obstacles messages, each
// with names never used before, for ~duration seconds (default 60; issue 12). The node's resident
// memory after a 5 s warm-up and at the end differ by less than 2 MiB, and requests and messages
// beyond max_obstacles (1000 here) or max_name_length (64) are refused naming the limit and value.
#include <atomic>
#include <cstdio>
#include <thread>

#include "../ros/node_test_utils.h"
#include "reliability_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

constexpr long kMaxGrowthKiB = 2048;

class Storm : public ::testing::Test, protected NodeServiceClient {
 protected:
  void SetUp() override {
    // Persistent, as a client calling hundreds of times a second connects: the storm is of new
    // names, not of connections (NodeServiceClient::connectServices()).
    ASSERT_TRUE(connectServicesAndObstacles(nh_, obstacles_, 100, /*persistent=*/true));
  }
  ros::NodeHandle nh_;
  ros::Publisher obstacles_;
};

std::vector<Ellipse> batch(const std::string& prefix, std::size_t first, std::size_t count) {
  std::vector<Ellipse> ellipses;
  for (std::size_t i = first; i < first + count; ++i) {
    ellipses.push_back(ellipseMsg(prefix + std::to_string(i), "base_link", 20.0, 20.0, 0.1, 0.1));
  }
  return ellipses;
}

TEST_F(Storm, LimitsAreRefusedNamingTheLimitAndTheValue) {
  AddObstacles::Response added = add(batch("too_many_", 0, 1001));
  EXPECT_FALSE(added.success);
  EXPECT_EQ(added.message,
            "obstacles: expected at most max_obstacles = 1000 runtime obstacles (service and topic) "
            "in total, got 1001");
  added = add({ellipseMsg(std::string(65, 'n'), "base_link", 0.0, 0.0, 0.1, 0.1)});
  EXPECT_FALSE(added.success);
  EXPECT_EQ(added.message, "obstacles[0].name: expected at most max_name_length = 64 characters, got 65");
  EXPECT_TRUE(add(batch("full_", 0, 1000)).success);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < 1000; ++i) names.push_back("full_" + std::to_string(i));
  EXPECT_TRUE(remove(names).success);
  EXPECT_FALSE(isStored("too_many_0"));
}

TEST_F(Storm, ResidentMemoryStaysFlatUnderNewNamesEveryTime) {
  ros::NodeHandle private_nh("~");
  const double duration = private_nh.param("duration", 60.0);
  const int pid = nodePid("/ellipse_collision");
  ASSERT_GT(pid, 0);

  std::atomic<bool> running{true};
  std::atomic<long> messages{0};
  // A perception stream at 50 Hz with 20 new names per message.
  std::thread stream([&] {
    std::size_t n = 0;
    while (running) {
      publishObstacles(obstacles_, "base_link", batch("seen_" + std::to_string(n++) + "_", 0, 20));
      ++messages;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  long rss_warm = -1, rss_max = -1;
  long calls = 0, failures = 0;
  std::size_t round = 0;
  while (elapsed() < duration) {
    const std::string prefix = "storm_" + std::to_string(round++) + "_";
    std::vector<Ellipse> ellipses = batch(prefix, 0, 50);
    std::vector<std::string> names;
    for (const Ellipse& e : ellipses) names.push_back(e.name);
    failures += add(ellipses).success ? 0 : 1;
    failures += remove(names).success ? 0 : 1;
    calls += 2;
    const long rss = residentKiB(pid);
    if (rss_warm < 0 && elapsed() > 5.0) rss_warm = rss;
    rss_max = std::max(rss_max, rss);
  }
  running = false;
  stream.join();
  const long rss_end = residentKiB(pid);
  std::printf("storm: %.0f s, %ld service calls, %ld obstacle messages, RSS after warm-up %ld KiB, "
              "at the end %ld KiB, max %ld KiB\n",
              duration, calls, messages.load(), rss_warm, rss_end, rss_max);
  EXPECT_EQ(failures, 0);
  ASSERT_GT(rss_warm, 0);
  EXPECT_LT(rss_end - rss_warm, kMaxGrowthKiB);
  EXPECT_TRUE(check().success) << "still answering";
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_storm");
}
