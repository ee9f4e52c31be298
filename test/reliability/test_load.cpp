// rostest client: load test (scene: reliability_scene.yaml). Client threads call
// ~check_collisions back to back while obstacles stream on ~obstacles; every call must succeed
// with an answer consistent with one of the streamed states, and the node's resident memory must
// stay flat. Private parameters (load.test passes them from its args):
//   ~duration [s] (default 60), ~threads (4), ~stream_rate [Hz] (50), ~warmup [s] (5),
//   ~max_rss_growth [KiB] (8192): allowed growth of the node's VmRSS from the end of the warm-up
//   to the end of the run;
//   ~persistent (true): one connection per client thread. Without it every call opens a new
//   connection and asks the master first: at ~1,700 calls/s that leaves ~30,000 sockets in
//   TIME_WAIT, the whole ephemeral port range, and an occasional connect() fails in the client's
//   kernel rather than in the node.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "../ros/node_test_utils.h"
#include "reliability_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

using Pairs = std::set<std::pair<std::string, std::string>>;
constexpr int kStreamed = 5;

Pairs pairsOf(const std::vector<CollisionPair>& collisions) {
  Pairs pairs;
  for (const CollisionPair& p : collisions) pairs.emplace(p.name_a, p.name_b);
  return pairs;
}

Pairs unite(Pairs a, const Pairs& b) {
  a.insert(b.begin(), b.end());
  return a;
}

/// The two states the stream alternates between: all streamed obstacles on `body`, or all far.
std::vector<Ellipse> streamedState(bool on_body) {
  std::vector<Ellipse> ellipses;
  for (int i = 0; i < kStreamed; ++i) {
    const std::string name = "stream_" + std::to_string(i);
    ellipses.push_back(on_body ? ellipseMsg(name, "", -0.2 + 0.1 * i, 0.0, 0.05, 0.05)
                               : ellipseMsg(name, "", 20.0 + i, 20.0, 0.05, 0.05));
  }
  return ellipses;
}

struct Tally {
  std::atomic<long> calls{0};
  std::atomic<long> failed{0};
  std::atomic<long> inconsistent{0};
  std::mutex mutex;
  std::string first_problem;

  void problem(std::atomic<long>& counter, const std::string& what) {
    ++counter;
    std::lock_guard<std::mutex> lock(mutex);
    if (first_problem.empty()) first_problem = what;
  }
};

TEST(Load, ConcurrentChecksWhileObstaclesStreamAllSucceedConsistentlyWithFlatMemory) {
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  const double duration = private_nh.param("duration", 60.0);
  const int threads = private_nh.param("threads", 4);
  const double stream_rate = private_nh.param("stream_rate", 50.0);
  const double warmup = private_nh.param("warmup", 5.0);
  const long max_growth_kib = private_nh.param("max_rss_growth", 8192);
  const bool persistent = private_nh.param("persistent", true);

  ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
  const int pid = nodePid("/ellipse_collision");
  ASSERT_GT(pid, 0) << "cannot find the node's process";
  ros::Publisher obstacles = nh.advertise<EllipseArray>(nodeTopic("obstacles"), 100);
  ASSERT_TRUE(waitUntil([&] { return obstacles.getNumSubscribers() > 0; }, 30.0));
  // Published states are consumed too: the node must keep up with its own topics under load.
  Recorder<CollisionState> states(nh, nodeTopic("collisions"));

  const Pairs fixed = {{"arm", "pillar"}};
  Pairs streamed_on_body;
  for (int i = 0; i < kStreamed; ++i)
    streamed_on_body.emplace("body", "stream_" + std::to_string(i));
  const std::vector<Pairs> full_answers = {fixed, unite(fixed, streamed_on_body)};

  std::atomic<bool> running{true};
  std::atomic<long> published{0};
  std::thread stream([&] {
    ros::Rate rate(stream_rate);
    bool on_body = false;
    while (running) {
      EllipseArray msg;
      msg.header.frame_id = "base_link";
      msg.header.stamp = ros::Time::now();
      msg.ellipses = streamedState(on_body = !on_body);
      obstacles.publish(msg);
      ++published;
      rate.sleep();
    }
  });

  Tally tally;
  std::vector<std::thread> clients;
  for (int t = 0; t < threads; ++t) {
    clients.emplace_back([&, t] {
      const auto connect = [&] {
        return nh.serviceClient<CheckCollisions>(nodeTopic("check_collisions"), persistent);
      };
      ros::ServiceClient client = connect();
      const std::string probe = "probe_" + std::to_string(t);
      // On the pillar's centre, inside the arm: collides with both.
      const Pairs probe_pairs = {{probe, "arm"}, {probe, "pillar"}};
      for (long i = 0; running; ++i) {
        CheckCollisions srv;
        const int kind = static_cast<int>(i % 3);
        if (kind == 1) srv.request.query = {ellipseMsg(probe, "base_link", 1.3, 0.0, 0.05, 0.05)};
        if (kind == 2) srv.request.names = {"arm"};
        ++tally.calls;
        if (!client.call(srv)) {
          tally.problem(tally.failed, "call failed (kind " + std::to_string(kind) + ")");
          client = connect();  // a broken persistent connection stays broken
          continue;
        }
        if (!srv.response.success || !srv.response.unavailable_frames.empty()) {
          tally.problem(tally.failed, "success = false: " + srv.response.message);
          continue;
        }
        const Pairs got = pairsOf(srv.response.collisions);
        bool consistent = false;
        if (kind == 2) {
          consistent = got == fixed;
        } else {
          for (const Pairs& full : full_answers) {
            consistent |= got == (kind == 1 ? unite(full, probe_pairs) : full);
          }
        }
        for (const CollisionPair& p : srv.response.collisions) {
          if (p.name_a == "arm" && p.name_b == "pillar")
            consistent &= std::abs(p.contact_scale - 0.6) < 1e-9;
        }
        if (!consistent) {
          std::string text;
          for (const auto& p : got) text += "(" + p.first + ", " + p.second + ") ";
          tally.problem(tally.inconsistent, "kind " + std::to_string(kind) + " answered " + text);
        }
      }
    });
  }

  // Memory: the first sample after the warm-up against the last one.
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  long rss_start = -1, rss_end = -1, rss_max = -1;
  long calls_at_warmup = 0;
  double warmup_end = 0.0;
  while (elapsed() < duration) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const long rss = residentKiB(pid);
    ASSERT_GT(rss, 0) << "the node's process is gone";
    if (rss_start < 0 && elapsed() >= std::min(warmup, duration / 2)) {
      rss_start = rss;
      calls_at_warmup = tally.calls;
      warmup_end = elapsed();
    }
    rss_end = rss;
    rss_max = std::max(rss_max, rss);
  }
  running = false;
  for (std::thread& client : clients) client.join();
  stream.join();
  const double measured = elapsed() - warmup_end;

  const double calls_per_second = (tally.calls - calls_at_warmup) / measured;
  std::printf(
      "load: %d threads (%s connections), %.0f s: %ld calls (%.1f calls/s after warm-up), %ld "
      "failed, %ld "
      "inconsistent; %ld obstacle messages streamed; node VmRSS %ld KiB after warm-up, %ld KiB at "
      "the end (max %ld KiB, growth %ld KiB); %zu ~collisions messages received\n",
      threads, persistent ? "persistent" : "one per call", duration, tally.calls.load(),
      calls_per_second, tally.failed.load(), tally.inconsistent.load(), published.load(), rss_start,
      rss_end, rss_max, rss_end - rss_start, states.count());
  RecordProperty("calls", std::to_string(tally.calls.load()));
  RecordProperty("calls_per_second", std::to_string(calls_per_second));
  RecordProperty("rss_start_kib", std::to_string(rss_start));
  RecordProperty("rss_end_kib", std::to_string(rss_end));

  EXPECT_GT(tally.calls, 0);
  EXPECT_EQ(tally.failed, 0) << "first problem: " << tally.first_problem;
  EXPECT_EQ(tally.inconsistent, 0) << "first problem: " << tally.first_problem;
  EXPECT_GT(states.count(), 0u);
  EXPECT_LE(rss_end - rss_start, max_growth_kib)
      << "resident memory grew from " << rss_start << " KiB to " << rss_end << " KiB";

  // Afterwards: the stream cleared, a normal request gets the scene's answer.
  EllipseArray empty;
  empty.header.frame_id = "base_link";
  obstacles.publish(empty);
  CheckCollisions srv;
  EXPECT_TRUE(waitUntil(
      [&] {
        return ros::service::call(nodeTopic("check_collisions"), srv) && srv.response.success &&
               pairsOf(srv.response.collisions) == fixed;
      },
      10.0));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_load");
}
