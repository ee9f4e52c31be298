// Service round trip (issue 7): a C++ client calls the running node's ~check_collisions over
// loopback TCP, one call after another, with 100 and 1,000 ellipses stored, and reports the
// latency percentiles and the calls per second. scripts/benchmark.sh starts a roscore on a free
// port and the node (bench/service_roundtrip.yaml), runs this, and stops both.
//
//   bench_service_roundtrip [--calls N] [--sizes 100,1000] [--node /ellipse_collision]
//
// The stored ellipses are the node's links plus obstacles added through ~add_obstacles in the
// fixed frame (no tf needed), spread over a 20 m x 20 m floor around the links so that each check
// finds a few collisions and warnings; they are removed again before the next size. Each call asks
// for the whole scene (no names, query or stamp) through a persistent connection, as a client
// calling at a high rate would; a second, shorter series opens a new connection per call.
// The ROS floor (issue 16): with --trigger NAME the same number of calls, over a persistent
// connection, to an empty std_srvs/Trigger service (this program with --serve-trigger NAME, in a
// process of its own), in alternating blocks with the ~check_collisions calls so that both share
// the machine's noise; the p50 ratio is printed.
#include <ros/ros.h>
#include <std_srvs/Trigger.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "ellipse_collision/ros/messages.h"

namespace ellipse_collision {
namespace {

struct Options {
  int calls{10000};
  std::vector<int> sizes{100, 1000};
  std::string node{"/ellipse_collision"};
  std::string trigger;        ///< the floor service to compare against, if not empty
  std::string serve_trigger;  ///< serve an empty Trigger service under this name instead
};

bool parseOptions(int argc, char** argv, Options* options) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--calls") {
      options->calls = std::atoi(value.c_str());
    } else if (key == "--trigger") {
      options->trigger = value;
    } else if (key == "--serve-trigger") {
      options->serve_trigger = value;
    } else if (key == "--node") {
      options->node = value;
    } else if (key == "--sizes") {
      options->sizes.clear();
      std::stringstream list(value);
      for (std::string size; std::getline(list, size, ',');) {
        options->sizes.push_back(std::atoi(size.c_str()));
      }
    } else {
      return false;
    }
  }
  return argc % 2 == 1 && options->calls > 0 && !options->sizes.empty();
}

/// Latency statistics of one series of calls.
struct Series {
  std::vector<double> latencies_us;
  double wall_s{0.0};
  std::size_t collisions{0};  ///< reported by the last call
  std::size_t warnings{0};
  int failures{0};  ///< calls that failed (counted only where tolerated)
};

double percentile(std::vector<double> values, double fraction) {
  const auto k = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

/// `calls` calls through `client`; false (with a message) on the first failed call, unless
/// `tolerate_failures`: a new connection per call now and then fails to connect (seen once or
/// twice per thousand on a loaded machine), which is counted and reported instead.
bool runTriggerSeries(ros::ServiceClient* client, int calls, Series* series) {
  std_srvs::Trigger trigger;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) {
    const auto before = std::chrono::steady_clock::now();
    if (!ros::ok() || !client->call(trigger)) {
      std::fprintf(stderr, "Trigger call %d failed\n", i);
      return false;
    }
    series->latencies_us.push_back(std::chrono::duration<double, std::micro>(
                                       std::chrono::steady_clock::now() - before)
                                       .count());
  }
  series->wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

bool runSeries(ros::ServiceClient* client, int calls, bool tolerate_failures, Series* series) {
  CheckCollisions check;  // the whole scene, latest transforms
  series->latencies_us.reserve(static_cast<std::size_t>(calls));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) {
    if (!ros::ok()) {  // Ctrl-C: roscpp's handler asks for shutdown, calls would go on regardless
      std::fprintf(stderr, "interrupted\n");
      return false;
    }
    const auto before = std::chrono::steady_clock::now();
    if (!client->call(check) || !check.response.success) {
      if (tolerate_failures && check.response.message.empty()) {
        ++series->failures;
        continue;
      }
      std::fprintf(stderr, "call %d failed: %s\n", i, check.response.message.c_str());
      return false;
    }
    const auto after = std::chrono::steady_clock::now();
    series->latencies_us.push_back(
        std::chrono::duration<double, std::micro>(after - before).count());
  }
  series->wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  series->collisions = check.response.collisions.size();
  series->warnings = check.response.warnings.size();
  return true;
}

void print(const char* connection, int stored, const Series& series) {
  std::printf("%8d %-11s %7zu %6d %9.0f %9.0f %9.0f %10.0f %10zu %8zu\n", stored, connection,
              series.latencies_us.size(), series.failures, percentile(series.latencies_us, 0.5),
              percentile(series.latencies_us, 0.99),
              *std::max_element(series.latencies_us.begin(), series.latencies_us.end()),
              static_cast<double>(series.latencies_us.size()) / series.wall_s, series.collisions,
              series.warnings);
}

/// Obstacles on the fixed frame, scattered over the floor, named bench_0, bench_1, ...
std::vector<Ellipse> obstacles(int count, const std::string& frame) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> position(-10.0, 10.0), radius(0.05, 0.4), angle(-3.1, 3.1);
  std::vector<Ellipse> result;
  for (int i = 0; i < count; ++i) {
    Ellipse msg;
    msg.name = "bench_" + std::to_string(i);
    msg.frame_id = frame;
    msg.x = position(rng);
    msg.y = position(rng);
    msg.angle = angle(rng);
    msg.radius_x = radius(rng);
    msg.radius_y = msg.radius_x * 0.5;
    msg.padding = 0.0;
    result.push_back(msg);
  }
  return result;
}

int run(const Options& options) {
  ros::NodeHandle nh;
  const std::string check_name = options.node + "/check_collisions";
  const std::string add_name = options.node + "/add_obstacles";
  const std::string remove_name = options.node + "/remove_obstacles";
  std::vector<std::string> services{check_name, add_name, remove_name};
  if (!options.trigger.empty()) services.push_back(options.trigger);
  for (const std::string& name : services) {
    if (!ros::service::waitForService(name, ros::Duration(30.0))) {
      std::fprintf(stderr, "service %s not available\n", name.c_str());
      return 1;
    }
  }
  std::string fixed_frame, links_param = options.node + "/links";
  XmlRpc::XmlRpcValue links;
  if (!nh.getParam(options.node + "/fixed_frame", fixed_frame) ||
      !nh.getParam(links_param, links) || links.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    std::fprintf(stderr, "%s/fixed_frame or %s not set\n", options.node.c_str(),
                 links_param.c_str());
    return 1;
  }
  const int link_count = links.size();

  std::printf("Service round trip: %s, one call after another on loopback\n", check_name.c_str());
  std::printf("%8s %-11s %7s %6s %9s %9s %9s %10s %10s %8s\n", "ellipses", "connection", "calls",
              "failed", "p50 us", "p99 us", "max us", "calls/s", "collisions", "warnings");
  bool ok = true;
  for (const int stored : options.sizes) {
    AddObstacles add;
    add.request.obstacles = obstacles(std::max(0, stored - link_count), fixed_frame);
    if (!ros::service::call(add_name, add) || !add.response.success) {
      std::fprintf(stderr, "add_obstacles failed: %s\n", add.response.message.c_str());
      return 1;
    }
    ros::ServiceClient persistent = nh.serviceClient<CheckCollisions>(check_name, true);
    Series warm_up, kept, fresh;
    ok = runSeries(&persistent, std::min(options.calls, 100), false, &warm_up);
    if (ok && !options.trigger.empty()) {
      // Alternating blocks of ten: the check and the floor share the machine's noise.
      ros::ServiceClient floor = nh.serviceClient<std_srvs::Trigger>(options.trigger, true);
      Series floor_series, floor_warm_up;
      ok = runTriggerSeries(&floor, std::min(options.calls, 100), &floor_warm_up);
      double check_wall_s = 0.0;
      for (int done = 0; ok && done < options.calls; done += 10) {
        const int block = std::min(10, options.calls - done);
        Series part;
        ok = runSeries(&persistent, block, false, &part) &&
             runTriggerSeries(&floor, block, &floor_series);
        kept.latencies_us.insert(kept.latencies_us.end(), part.latencies_us.begin(),
                                 part.latencies_us.end());
        check_wall_s += part.wall_s;
        kept.collisions = part.collisions;
        kept.warnings = part.warnings;
      }
      kept.wall_s = check_wall_s;
      if (ok) {
        print("persistent", stored, kept);
        floor_series.collisions = floor_series.warnings = 0;
        print("Trigger", 0, floor_series);
        std::printf("%8d p50 ratio ~check_collisions / empty Trigger: %.2f (goal <= 1.5)\n",
                    stored,
                    percentile(kept.latencies_us, 0.5) / percentile(floor_series.latencies_us, 0.5));
      }
    } else {
      ok = ok && runSeries(&persistent, options.calls, false, &kept);
      if (ok) print("persistent", stored, kept);
    }
    ros::ServiceClient per_call = nh.serviceClient<CheckCollisions>(check_name, false);
    ok = ok && runSeries(&per_call, std::max(1, options.calls / 10), true, &fresh) &&
         !fresh.latencies_us.empty();
    if (ok) print("per call", stored, fresh);

    RemoveObstacles remove;
    for (const Ellipse& obstacle : add.request.obstacles) {
      remove.request.names.push_back(obstacle.name);
    }
    if (!ros::service::call(remove_name, remove) || !remove.response.success) {
      std::fprintf(stderr, "remove_obstacles failed: %s\n", remove.response.message.c_str());
      return 1;
    }
    if (!ok) return 1;
  }
  return 0;
}

}  // namespace

/// The floor's whole work: say yes.
bool answerTrigger(std_srvs::Trigger::Request& /*request*/, std_srvs::Trigger::Response& response) {
  response.success = true;
  return true;
}

}  // namespace ellipse_collision

int main(int argc, char** argv) {
  ros::init(argc, argv, "bench_service_roundtrip", ros::init_options::AnonymousName);
  ellipse_collision::Options options;
  if (!ellipse_collision::parseOptions(argc, argv, &options)) {
    std::fprintf(stderr,
                 "usage: %s [--calls N] [--sizes 100,1000] [--node /ellipse_collision] "
                 "[--trigger /floor] | --serve-trigger /floor\n",
                 argv[0]);
    return 2;
  }
  if (!options.serve_trigger.empty()) {
    // The ROS floor: a service that does nothing, answered by roscpp alone.
    ros::NodeHandle nh;
    const ros::ServiceServer server =
        nh.advertiseService(options.serve_trigger, ellipse_collision::answerTrigger);
    ros::spin();
    return 0;
  }
  return ellipse_collision::run(options);
}
