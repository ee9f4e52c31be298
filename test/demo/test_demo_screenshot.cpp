// rostest client for demo/launch/demo.launch in a virtual X server (see demo_screenshot.test):
// waits until the demo has been both in collision and clear and its base, driven through the
// velocity gate, has been held by the gate and let go again without ever overlapping an obstacle,
// while its links (the arm guarded by the driver) overlapped obstacles in at most 2 % of the states
// after the first 15 s, freezes it (demo_driver/pause) at a moment
// with a collision (and, if the demo offers one soon, a warning pair), grabs the screen and checks
// that rviz draws every colliding ellipse red, every other one in a warning pair yellow and every
// clear one green, at the pixels the view in demo/rviz/demo.rviz maps it to. The links come from
// the URDF (as the node fits them), the obstacles (the demo configures none in the node) only
// through the simulated scanner and scan_obstacles (the ellipses on the node's ~obstacles).
#include <std_srvs/SetBool.h>
#include <tf2_ros/transform_listener.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/ros/collision_markers.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/ros/tf_lookup.h"
#include "ellipse_collision/ros/urdf_links.h"
#include "node_test_utils.h"
#include "rviz_top_down_view.h"
#include "screen_image.h"

namespace ellipse_collision {
namespace test {
namespace {

// Marker colours are red (0.9, 0.1, 0.1), yellow (0.9, 0.85, 0.1) or green (0.1, 0.8, 0.1), alpha
// 0.6, over a grey background and under the half-transparent grey robot: the dominant channel (red
// and green together for yellow) stays clear of the others by at least ~50 of 255, while red and
// green of yellow stay within ~10 of each other.
constexpr int kHueMargin = 30;
// Pixels this close to an ellipse's outline [px] are skipped: anti-aliasing mixes them.
constexpr double kEdgeMarginPx = 3.0;
// Around every tf frame origin [m]: rviz's TF display draws red, green and blue axes there.
constexpr double kAxesRadiusM = 0.1;
// An ellipse is judged on at least this many pixels that it alone covers, or not at all.
constexpr int kMinPixels = 20;
// Share of an ellipse's pixels that must have its expected hue, and the most the other may have.
constexpr double kMinExpectedShare = 0.5;
constexpr double kMaxOtherShare = 0.1;

enum class Hue { Red, Yellow, Green, Other };

const char* nameOf(Hue hue) {
  switch (hue) {
    case Hue::Red:
      return "red";
    case Hue::Yellow:
      return "yellow";
    case Hue::Green:
      return "green";
    case Hue::Other:
      break;
  }
  return "other";
}

Hue hueOf(const Rgb& colour) {
  const int r = colour[0];
  const int g = colour[1];
  const int b = colour[2];
  if (r - std::max(g, b) >= kHueMargin) return Hue::Red;
  if (g - std::max(r, b) >= kHueMargin) return Hue::Green;
  if (std::min(r, g) - b >= kHueMargin) return Hue::Yellow;
  return Hue::Other;
}

/// ((u / radius_x)^2 + (v / radius_y)^2)^(1/2) for `point` in the ellipse's own axes (u, v) after
/// growing both radii by `grow_m`: <= 1 inside. An ellipse shrunk to nothing (a radius at most
/// -grow_m, as thin scan obstacles are by the edge margin) has no inside: +inf.
double normalisedRadius(const core::Ellipse& e, const Eigen::Vector2d& point, double grow_m) {
  if (e.radius_x + grow_m <= 0.0 || e.radius_y + grow_m <= 0.0) {
    return std::numeric_limits<double>::infinity();
  }
  const Eigen::Vector2d d = point - e.center;
  const double c = std::cos(e.angle);
  const double s = std::sin(e.angle);
  const double u = (c * d.x() + s * d.y()) / (e.radius_x + grow_m);
  const double v = (-s * d.x() + c * d.y()) / (e.radius_y + grow_m);
  return std::sqrt(u * u + v * v);
}

struct HueCount {
  std::map<Hue, int> of;
  int total() const {
    int sum = 0;
    for (const auto& entry : of) sum += entry.second;
    return sum;
  }
  int get(Hue hue) const { return of.count(hue) ? of.at(hue) : 0; }
};

/// The hues of the screen pixels that show `target` and nothing else: inside it by at least the
/// edge margin, outside every other ellipse by the same margin and away from tf axes.
/// Distance [m] from `p` to the segment from `a` to `b`.
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

/// A line drawn over the ellipses (a warning pair's clearance line, an outline of the gate's or
/// the path check's markers, a contact sphere as a segment of length 0, the held arm's text):
/// the pixels within `half_width` of it show the line, not the fill beneath.
struct Segment {
  Eigen::Vector2d a, b;
  double half_width{0.5 * CollisionMarkers::kLineWidth};
};

/// The lines and spheres of marker arrays drawn over the ellipses, in the fixed frame (the
/// markers' frame; their poses only translate).
void addOverlays(const std::vector<visualization_msgs::MarkerArray>& arrays,
                 std::vector<Segment>* overlays) {
  // What rviz shows after applying the arrays in order.
  std::map<std::pair<std::string, int>, visualization_msgs::Marker> shown;
  for (const visualization_msgs::MarkerArray& array : arrays) {
    for (const visualization_msgs::Marker& m : array.markers) {
      if (m.action == visualization_msgs::Marker::DELETEALL) {
        shown.clear();
      } else if (m.action == visualization_msgs::Marker::DELETE) {
        shown.erase({m.ns, m.id});
      } else {
        shown[{m.ns, m.id}] = m;
      }
    }
  }
  {
    for (const auto& [key, m] : shown) {
      const double dx = m.pose.position.x, dy = m.pose.position.y;
      const auto at = [dx, dy](const geometry_msgs::Point& p) {
        Eigen::Vector2d point;
        point << p.x + dx, p.y + dy;
        return point;
      };
      Eigen::Vector2d offset;
      offset << dx, dy;
      if (m.type == visualization_msgs::Marker::SPHERE) {
        overlays->push_back({offset, offset, 0.5 * m.scale.x});
      } else if (m.type == visualization_msgs::Marker::LINE_STRIP) {
        for (std::size_t i = 1; i < m.points.size(); ++i) {
          overlays->push_back({at(m.points[i - 1]), at(m.points[i]), 0.5 * m.scale.x});
        }
      } else if (m.type == visualization_msgs::Marker::LINE_LIST) {
        for (std::size_t i = 1; i < m.points.size(); i += 2) {
          overlays->push_back({at(m.points[i - 1]), at(m.points[i]), 0.5 * m.scale.x});
        }
      } else if (m.type == visualization_msgs::Marker::TEXT_VIEW_FACING) {
        // A line of text centred there, scale.z high: generously, a glyph as wide as it is high.
        const Eigen::Vector2d half_length(0.5 * m.scale.z * m.text.size(), 0.0);
        overlays->push_back({offset - half_length, offset + half_length, m.scale.z});
      }
    }
  }
}

HueCount countHues(const ScreenImage& image, const TopDownView& view, const PanelRect& panel,
                   const core::NamedEllipse& target, const std::vector<core::NamedEllipse>& all,
                   const std::vector<Eigen::Vector2d>& frame_origins,
                   const std::vector<Segment>& clearance_lines) {
  const double margin_m = kEdgeMarginPx / view.scale_px_per_m;
  const double reach_m = core::boundingRadius(target.ellipse);
  const Eigen::Vector2d low =
      toPixel(view, panel, target.ellipse.center + Eigen::Vector2d(-reach_m, reach_m));
  const Eigen::Vector2d high =
      toPixel(view, panel, target.ellipse.center + Eigen::Vector2d(reach_m, -reach_m));
  HueCount count;
  for (int y = std::max(panel.top, int(std::floor(low.y())));
       y <= std::min(panel.bottom, int(std::ceil(high.y()))); ++y) {
    for (int x = std::max(panel.left, int(std::floor(low.x())));
         x <= std::min(panel.right, int(std::ceil(high.x()))); ++x) {
      const Eigen::Vector2d point = toPoint(view, panel, Eigen::Vector2d(x + 0.5, y + 0.5));
      if (normalisedRadius(target.ellipse, point, -margin_m) > 1.0) continue;
      bool covered = false;
      for (const core::NamedEllipse& other : all) {
        if (other.name != target.name && normalisedRadius(other.ellipse, point, margin_m) <= 1.0) {
          covered = true;
        }
      }
      for (const Eigen::Vector2d& origin : frame_origins) {
        if ((point - origin).norm() < kAxesRadiusM) covered = true;
      }
      // Lines and spheres drawn on top (clearance lines, the gate's outlines, the path check's
      // ring), with anti-aliased edges.
      for (const Segment& line : clearance_lines) {
        if (distanceToSegment(point, line.a, line.b) < line.half_width + margin_m) {
          covered = true;
        }
      }
      if (covered) continue;
      ++count.of[hueOf(image.at(x, y))];
    }
  }
  return count;
}

/// What one screenshot shows; `problems` is empty when every judged ellipse has its colour.
struct Verdict {
  std::string report;          ///< one line per ellipse
  std::string problems;        ///< one line per ellipse with the wrong colour
  std::map<Hue, int> checked;  ///< ellipses judged on enough pixels, by expected colour
  int count(Hue hue) const { return checked.count(hue) ? checked.at(hue) : 0; }
};

/// Red in collision, else yellow in a warning pair, else green (CollisionMarkers' rule).
Verdict judge(const ScreenImage& image, const TopDownView& view, const PanelRect& panel,
              const std::vector<core::NamedEllipse>& placed, const std::set<std::string>& colliding,
              const std::set<std::string>& warned,
              const std::vector<Eigen::Vector2d>& frame_origins,
              const std::vector<Segment>& clearance_lines) {
  Verdict verdict;
  for (const core::NamedEllipse& e : placed) {
    const HueCount count = countHues(image, view, panel, e, placed, frame_origins, clearance_lines);
    const Hue expected = colliding.count(e.name) ? Hue::Red
                         : warned.count(e.name)  ? Hue::Yellow
                                                 : Hue::Green;
    const Eigen::Vector2d pixel = toPixel(view, panel, e.ellipse.center);
    std::ostringstream line;
    line << e.name << " (expected " << nameOf(expected) << ") at pixel (" << int(pixel.x()) << ", "
         << int(pixel.y()) << "):";
    for (const Hue hue : {Hue::Red, Hue::Yellow, Hue::Green, Hue::Other}) {
      line << " " << count.get(hue) << " " << nameOf(hue);
    }
    line << "\n";
    verdict.report += line.str();
    if (count.total() < kMinPixels) continue;
    int wrong = 0;  // pixels of another marker colour
    for (const Hue hue : {Hue::Red, Hue::Yellow, Hue::Green}) {
      if (hue != expected) wrong += count.get(hue);
    }
    if (count.get(expected) < kMinExpectedShare * count.total() ||
        wrong > kMaxOtherShare * count.total()) {
      verdict.problems += line.str();
    } else {
      ++verdict.checked[expected];
    }
  }
  return verdict;
}

std::set<std::string> namesIn(const CollisionState& state, bool warnings) {
  std::set<std::string> names;
  if (warnings) {
    for (const ClearancePair& pair : state.warnings) names.insert({pair.name_a, pair.name_b});
  } else {
    for (const CollisionPair& pair : state.collisions) names.insert({pair.name_a, pair.name_b});
  }
  return names;
}

bool setPaused(ros::ServiceClient& client, bool paused) {
  std_srvs::SetBool call;
  call.request.data = paused;
  return client.call(call) && call.response.success;
}

bool complete(const CollisionState& s) { return s.unavailable_frames.empty(); }

/// Which kinds of state the node has reported (only states with every frame known count).
struct SeenKinds {
  explicit SeenKinds(const NodeConfig& config) {
    for (const app::EllipseSpec& spec : config.links) links.insert(spec.name);
  }
  void onState(const CollisionState::ConstPtr& state) {
    if (!complete(*state)) return;
    std::lock_guard<std::mutex> lock(mutex);
    if (!state->in_collision) clear = true;
    if (first.isZero()) first = state->header.stamp;
    const bool count = counting && state->header.stamp >= first + ros::Duration(kStartUpS);
    bool link_hit = false;
    // name_a is the link: Link < Obstacle in a pair's order.
    for (const CollisionPair& pair : state->collisions) {
      if (links.count(pair.name_b)) {
        self = true;
      } else {
        link_hit = true;
        if (count) ++hits_by_link[pair.name_a];
        if (pair.name_a == kGatedBase) {
          base_hits.insert(pair.name_b + " at " + std::to_string(state->header.stamp.toSec()));
        }
      }
    }
    if (count) {
      ++counted;
      if (link_hit) ++link_hit_states;
    }
  }
  bool all() {
    std::lock_guard<std::mutex> lock(mutex);
    return clear && self && counted >= kMinCounted;
  }
  std::string hitsByLink() {
    std::string text;
    for (const auto& [link, n] : hits_by_link) text += " " + link + " " + std::to_string(n);
    return text;
  }

  /// States of the first seconds (start-up, the arm held until the node answers) do not count.
  static constexpr double kStartUpS = 15.0;
  /// The share is judged on at least this many states (50 s at the demo's 20 Hz).
  static constexpr int kMinCounted = 1000;
  /// The arm guard holds the joints before a link would touch an obstacle, and the gate stops the
  /// base: a link overlaps an obstacle in at most this share of the states (the moving cart may
  /// still run into the robot, a scanned face appear at a link).
  static constexpr double kMaxLinkHitShare = 0.02;

  /// The link the gate's command moves the robot by (demo.yaml gate/robot_frame's link).
  static constexpr const char* kGatedBase = "base_link";
  std::set<std::string> links;
  std::mutex mutex;
  bool clear{false};
  bool self{false};
  std::set<std::string> base_hits;  ///< obstacles base_link overlapped, with the time
  ros::Time first;                  ///< stamp of the first complete state
  bool counting{true};              ///< count states (until the demo is paused)
  int counted{0};                   ///< states after kStartUpS
  int link_hit_states{0};           ///< of those, states with a link in an obstacle
  std::map<std::string, int> hits_by_link;
};

bool moves(const geometry_msgs::Twist& t) {
  return t.linear.x != 0.0 || t.linear.y != 0.0 || t.angular.z != 0.0;
}

/// The velocity gate's decisions for the driver's commands: held (STOP, or SLOW) and, after a
/// hold, let go (ESCAPE, or PASS) with the base moving.
struct GateSequence {
  void onState(const GateState::ConstPtr& state) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!moves(state->input)) return;
    if (state->action == "STOP" || state->action == "SLOW") {
      if (!held) held_reason = state->action + ": " + state->reason;
      held = true;
    } else if (held && (state->action == "ESCAPE" || state->action == "PASS") &&
               moves(state->output)) {
      if (!went_on) went_on_reason = state->action + ": " + state->reason;
      went_on = true;
    }
  }
  bool done() {
    std::lock_guard<std::mutex> lock(mutex);
    return held && went_on;
  }
  std::mutex mutex;
  bool held{false};
  bool went_on{false};
  std::string held_reason, went_on_reason;
};

TEST(DemoInRviz, CollidingEllipsesAreRedNearOnesYellowAndClearOnesGreen) {
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  std::string rviz_config;
  ASSERT_TRUE(private_nh.getParam("rviz_config", rviz_config)) << "~rviz_config not set";
  const std::string screenshot = private_nh.param<std::string>("screenshot", "");
  const TopDownView view = readTopDownView(rviz_config);
  // The link ellipses as the node fits them from the URDF (~links_from_urdf).
  const NodeConfig config =
      loadNodeConfig(ros::NodeHandle("/ellipse_collision"), fitUrdfLinksFromParam);
  ASSERT_FALSE(config.links.empty()) << "no link ellipses from the demo's URDF";

  Recorder<CollisionState> states(nh, nodeTopic("collisions"));
  Recorder<EllipseArray> topic_obstacles(nh, nodeTopic("obstacles"));
  // Drawn over the ellipses: the gate's outlines and contact point, the path check's ring.
  Recorder<visualization_msgs::MarkerArray> gate_markers(nh, nodeTopic("gate_markers"));
  Recorder<visualization_msgs::MarkerArray> path_markers(nh, "/demo_driver/path_check_markers");
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);
  ros::ServiceClient pause = nh.serviceClient<std_srvs::SetBool>("/demo_driver/pause");

  // The demo runs: its state has been clear, and links have collided with each other, all with
  // every frame known. The base drives through the velocity gate: the gate has held a command
  // (STOP or SLOW) and later let the base go on (ESCAPE or PASS), and all the while the base
  // never overlapped an obstacle.
  SeenKinds seen(config);
  ros::Subscriber seen_subscriber =
      nh.subscribe(nodeTopic("collisions"), 100, &SeenKinds::onState, &seen);
  GateSequence gate;
  ros::Subscriber gate_subscriber =
      nh.subscribe(nodeTopic("gate_state"), 100, &GateSequence::onState, &gate);
  waitUntil([&] { return seen.all() && gate.done(); }, 100.0);
  EXPECT_TRUE(seen.self) << "no self-collision";
  ASSERT_TRUE(seen.clear) << "the demo was never clear";
  {
    std::lock_guard<std::mutex> lock(seen.mutex);
    seen.counting = false;
    EXPECT_GE(seen.counted, SeenKinds::kMinCounted);
    EXPECT_LE(seen.link_hit_states, SeenKinds::kMaxLinkHitShare * seen.counted)
        << "links overlapped obstacles in " << seen.link_hit_states << " of " << seen.counted
        << " states (pairs by link:" << seen.hitsByLink() << ")";
    ROS_INFO_STREAM("demo: links overlapped obstacles in "
                    << seen.link_hit_states << " of " << seen.counted
                    << " states (pairs by link:" << seen.hitsByLink() << ")");
  }
  {
    std::lock_guard<std::mutex> lock(gate.mutex);
    EXPECT_TRUE(gate.held) << "the gate never stopped or slowed the base";
    EXPECT_TRUE(gate.went_on) << "after " << gate.held_reason
                              << ", the gate never let the base go on";
    ROS_INFO_STREAM("demo gate: held (" << gate.held_reason << "), then went on ("
                                        << gate.went_on_reason << ")");
  }
  ASSERT_TRUE(pause.waitForExistence(ros::Duration(30.0)));

  // Freeze it while something collides, in the first attempts only at a moment that also has a
  // warning pair. A check stamped well after the pause saw the frozen pose; if the collision ended
  // just before the pause, run on and try again.
  CollisionState frozen;
  bool frozen_in_collision = false;
  for (int attempt = 0; attempt < 10 && !frozen_in_collision; ++attempt) {
    const bool want_warning = attempt < 3;
    const bool seen = states.waitForLatest(
        [want_warning](const auto& s) {
          return complete(s) && s.in_collision && (!want_warning || !s.warnings.empty());
        },
        want_warning ? 10.0 : 40.0);
    if (!seen && want_warning) continue;  // settle for a collision alone
    ASSERT_TRUE(seen) << "the demo was not in collision for 40 s";
    ASSERT_TRUE(setPaused(pause, true));
    const ros::Time paused_at = ros::Time::now();
    ASSERT_TRUE(states.waitForLatest(
        [&](const auto& s) { return s.header.stamp > paused_at + ros::Duration(0.5); }, 10.0,
        &frozen));
    frozen_in_collision = complete(frozen) && frozen.in_collision;
    if (!frozen_in_collision) {
      ASSERT_TRUE(setPaused(pause, false));
    }
  }
  ASSERT_TRUE(frozen_in_collision) << "could not pause the demo during a collision";
  const std::set<std::string> colliding = namesIn(frozen, false);
  const std::set<std::string> warned = namesIn(frozen, true);

  // Where every ellipse is now, from tf, the configuration and scan_obstacles' last message.
  app::FramePlacer placement(
      tfLookup(tf_buffer, config.monitor.check.fixed_frame, ros::Time(0), ros::Duration(1.0)),
      config.monitor.check.global_padding_m);
  std::vector<core::NamedEllipse> placed;
  std::vector<Eigen::Vector2d> frame_origins;
  auto place = [&](const app::EllipseSpec& spec, core::EllipseRole role) {
    const app::FramePlacer::Placement p = placement.place(spec, role);
    ASSERT_EQ(p.status, app::FramePlacer::Status::Placed) << spec.name << ": " << p.error;
    placed.push_back(p.ellipse);
  };
  for (const app::EllipseSpec& spec : config.links) {
    place(spec, core::EllipseRole::Link);
    const geometry_msgs::TransformStamped t =
        tf_buffer.lookupTransform(config.monitor.check.fixed_frame, spec.frame_id, ros::Time(0));
    frame_origins.emplace_back(t.transform.translation.x, t.transform.translation.y);
  }
  frame_origins.emplace_back(0.0, 0.0);  // the fixed frame's own axes
  for (const app::EllipseSpec& spec : config.obstacles) place(spec, core::EllipseRole::Obstacle);
  const std::vector<EllipseArray> streamed = topic_obstacles.all();
  ASSERT_FALSE(streamed.empty()) << "no message on " << nodeTopic("obstacles");
  {
    // The scanner's frame draws its axes too.
    const geometry_msgs::TransformStamped t = tf_buffer.lookupTransform(
        config.monitor.check.fixed_frame, streamed.back().header.frame_id, ros::Time(0));
    frame_origins.emplace_back(t.transform.translation.x, t.transform.translation.y);
  }
  std::vector<Segment> clearance_lines;
  for (const ClearancePair& pair : frozen.warnings) {
    clearance_lines.push_back({{pair.point_a.x, pair.point_a.y}, {pair.point_b.x, pair.point_b.y}});
  }
  for (const app::EllipseSpec& spec : fromMsg(streamed.back())) place(spec, core::EllipseRole::Obstacle);
  if (HasFatalFailure()) return;
  // The frozen state is about this geometry: checking it here finds the same colliding ellipses.
  core::SceneRules rules;
  rules.self_collision = config.monitor.check.rules.self_collision;
  rules.warning_distance = config.monitor.check.rules.warning_distance;
  rules.allowed = config.monitor.check.rules.allowed;
  const core::SceneCheckResult check = core::checkScene(placed, rules);
  ASSERT_TRUE(check.ok()) << check.error;
  CollisionState here;
  here.collisions = toMsg(check.collisions);
  here.warnings = toMsg(check.warnings);
  ASSERT_EQ(namesIn(here, false), colliding) << "the demo did not stay still while paused";
  ASSERT_EQ(namesIn(here, true), warned) << "the demo did not stay still while paused";

  // rviz renders in software and may be a few frames behind the markers: look a few times.
  Verdict verdict;
  PanelRect panel;
  ScreenImage image;
  for (int attempt = 0; attempt < 10; ++attempt) {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    image = ScreenImage::grab();
    const auto& bg = view.background;
    panel = image.findArea({Rgb::value_type(bg[0]), Rgb::value_type(bg[1]), Rgb::value_type(bg[2])},
                           100);
    if (panel.width() < 200 || panel.height() < 200) continue;  // rviz not up yet
    // Every overlay sent so far may still be drawn (rviz lags): none of their pixels is judged.
    std::vector<Segment> overlays = clearance_lines;
    addOverlays(gate_markers.all(), &overlays);
    addOverlays(path_markers.all(), &overlays);
    verdict = judge(image, view, panel, placed, colliding, warned, frame_origins, overlays);
    if (verdict.problems.empty() && verdict.count(Hue::Red) > 0 && verdict.count(Hue::Green) > 0) {
      break;
    }
  }
  if (!screenshot.empty()) image.savePpm(screenshot);

  std::ostringstream where;
  where << "render panel x " << panel.left << ".." << panel.right << ", y " << panel.top << ".."
        << panel.bottom << "; screenshot: " << (screenshot.empty() ? "(not saved)" : screenshot)
        << "\n"
        << verdict.report;
  ASSERT_GE(panel.width(), 200) << "no rviz render panel on the screen\n" << where.str();
  EXPECT_EQ(verdict.problems, "") << where.str();
  EXPECT_GT(verdict.count(Hue::Red), 0) << "no colliding ellipse visible enough to judge\n"
                                        << where.str();
  EXPECT_GT(verdict.count(Hue::Green), 0) << "no clear ellipse visible enough to judge\n"
                                          << where.str();
  ROS_INFO_STREAM("demo screenshot: " << where.str());
  EXPECT_TRUE(setPaused(pause, false));
  std::lock_guard<std::mutex> lock(seen.mutex);
  std::string hits;
  for (const std::string& hit : seen.base_hits) hits += hit + "\n";
  EXPECT_EQ(hits, "") << SeenKinds::kGatedBase << " overlapped obstacles through the gate";
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_demo_screenshot");
}
