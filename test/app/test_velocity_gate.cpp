// The velocity gate's application layer: gateOnScene() (the scene moved into the robot frame, the
// obstacles pre-filtered, the answer put back into the fixed frame) against core::gateTwist() on
// the whole scene built by hand in the robot frame, and the monitor's rules (disabled, silence,
// incomplete data, obstacles on moving frames). (Its settings and command rules:
// test_gate_config.cpp, test_velocity_command.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/velocity_gate.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

/// A scene placed in the fixed frame: `links` and `obstacles` (in that order, as a check places
/// them).
core::Scene placedScene(const std::vector<core::NamedEllipse>& links,
                        const std::vector<core::NamedEllipse>& obstacles) {
  core::Scene scene;
  for (const auto& link : links) scene.push_back(link.name, core::EllipseRole::Link, link.ellipse);
  for (const auto& o : obstacles) scene.push_back(o.name, core::EllipseRole::Obstacle, o.ellipse);
  return scene;
}

/// `e` (in the fixed frame) seen from a robot at `pose`, by hand.
core::Ellipse inRobotFrame(const core::Ellipse& e, const PlanarPose& pose) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const Eigen::Vector2d d = e.center - pose.position;
  core::Ellipse out = e;
  out.center = {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
  out.angle = e.angle - pose.yaw;
  return out;
}

/// Whether two decisions are the same bit for bit: action, scale, output, contact, limiting
/// pair, outline, braking figures and reason.
void expectSameDecision(const GateDecision& a, const GateDecision& b, const std::string& label) {
  SCOPED_TRACE(label);
  EXPECT_EQ(a.action, b.action);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.output.linear, b.output.linear);
  EXPECT_EQ(a.output.angular, b.output.angular);
  EXPECT_EQ(a.contact_predicted, b.contact_predicted);
  EXPECT_EQ(a.time_to_contact_s, b.time_to_contact_s);
  EXPECT_EQ(a.link, b.link);
  EXPECT_EQ(a.obstacle, b.obstacle);
  EXPECT_EQ(a.contact_point, b.contact_point);
  EXPECT_EQ(a.obstacle_ellipse.center, b.obstacle_ellipse.center);
  EXPECT_EQ(a.obstacle_ellipse.angle, b.obstacle_ellipse.angle);
  ASSERT_EQ(a.outline.size(), b.outline.size());
  for (std::size_t i = 0; i < a.outline.size(); ++i) {
    EXPECT_EQ(a.outline[i].name, b.outline[i].name);
    EXPECT_EQ(a.outline[i].ellipse.center, b.outline[i].ellipse.center);
    EXPECT_EQ(a.outline[i].ellipse.angle, b.outline[i].ellipse.angle);
  }
  EXPECT_EQ(a.braking_distance_m, b.braking_distance_m);
  EXPECT_EQ(a.free_distance_m, b.free_distance_m);
  EXPECT_EQ(a.unavoidable, b.unavoidable);
  EXPECT_EQ(a.impact_speed, b.impact_speed);
  EXPECT_EQ(a.reason, b.reason);
}

TEST(GateOnScene, MatchesTheCoreOnTheWholeSceneSeenFromTheRobot) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), size(0.05, 0.4);
  GateConfig config;
  config.timing.horizon = 3.0;
  config.timing.time_before_collision = 1.5;
  int slowed_or_stopped = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const PlanarPose pose{{5.0 * unit(rng), 5.0 * unit(rng)}, 3.1 * unit(rng)};
    std::vector<core::NamedEllipse> links, obstacles;
    std::vector<PlacedMotion> moving;  // by placed index, links first
    core::PathScene by_hand;
    for (int i = 0; i < 3; ++i) {
      // Links given in the robot frame, placed into the fixed frame for the check.
      const core::Ellipse in_robot{
          {0.3 * unit(rng), 0.2 * unit(rng)}, size(rng), size(rng), unit(rng)};
      core::Ellipse placed = in_robot;
      const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
      placed.center =
          pose.position + Eigen::Vector2d(c * in_robot.center.x() - s * in_robot.center.y(),
                                          s * in_robot.center.x() + c * in_robot.center.y());
      placed.angle += pose.yaw;
      links.push_back({"link_" + std::to_string(i), core::EllipseRole::Link, placed});
      by_hand.links.push_back(
          {links.back().name, core::EllipseRole::Link, inRobotFrame(placed, pose)});
    }
    for (int i = 0; i < 40; ++i) {
      const core::Ellipse e{pose.position + Eigen::Vector2d(8.0 * unit(rng), 8.0 * unit(rng)),
                            size(rng), size(rng), unit(rng)};
      obstacles.push_back({"obstacle_" + std::to_string(i), core::EllipseRole::Obstacle, e});
      core::Motion motion;
      if (i % 4 == 0) motion.velocity = {0.5 * unit(rng), 0.5 * unit(rng)};
      if (i % 4 == 0) moving.push_back({links.size() + obstacles.size() - 1, motion});
      core::Motion turned = motion;
      const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
      turned.velocity = {c * motion.velocity.x() + s * motion.velocity.y(),
                         -s * motion.velocity.x() + c * motion.velocity.y()};
      by_hand.obstacles.push_back(
          {obstacles.back().name, core::EllipseRole::Obstacle, inRobotFrame(e, pose)});
      by_hand.obstacle_motions.push_back(turned);
    }
    VelocityCommand command;
    command.linear.x() = 1.5 * unit(rng);
    command.linear.y() = 0.3 * unit(rng);
    command.angular.z() = 0.8 * unit(rng);
    const core::Scene placed = placedScene(links, obstacles);
    const GateDecision decision =
        gateOnScene(command, placed, moving, pose, core::AllowedPairs(), config);
    // The obstacles' grid gives the scan's answer, for the ideal base and with the braking rule.
    const core::IndexedObstacles grid(obstacles);
    expectSameDecision(
        gateOnScene(command, placed, moving, pose, core::AllowedPairs(), config, {}, &grid),
        decision, "trial " + std::to_string(trial) + " through the grid");
    GateConfig braking = config;
    braking.base = {0.1, 0.8, 2.0};
    const core::BaseState base{braking.base, {0.4, 0.0, 0.2}, 0.05};
    expectSameDecision(
        gateOnScene(command, placed, moving, pose, core::AllowedPairs(), braking, base, &grid),
        gateOnScene(command, placed, moving, pose, core::AllowedPairs(), braking, base),
        "trial " + std::to_string(trial) + " braking, through the grid");
    const core::GateResult expected = core::gateTwist(
        by_hand, {command.linear.x(), command.linear.y(), command.angular.z()}, config.timing);
    ASSERT_TRUE(expected.ok()) << expected.error;
    EXPECT_EQ(decision.action, expected.action)
        << "trial " << trial << ": " << decision.reason << " / " << expected.reason;
    EXPECT_NEAR(decision.scale, expected.scale, 1e-12) << "trial " << trial;
    EXPECT_NEAR(decision.output.linear.x(), expected.scale * command.linear.x(), 1e-12);
    const core::GateContact& shown = expected.contact.found ? expected.contact : expected.limiting;
    EXPECT_EQ(decision.contact_predicted, shown.found) << "trial " << trial;
    if (shown.found && decision.contact_predicted) {
      EXPECT_EQ(decision.obstacle, shown.obstacle);
      EXPECT_NEAR(decision.time_to_contact_s, shown.time, 1e-9);
      // The contact point back in the fixed frame.
      const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
      const Eigen::Vector2d fixed =
          pose.position + Eigen::Vector2d(c * shown.point.x() - s * shown.point.y(),
                                          s * shown.point.x() + c * shown.point.y());
      EXPECT_LT((decision.contact_point - fixed).norm(), 1e-9);
    }
    slowed_or_stopped += decision.action != GateAction::Pass;
  }
  EXPECT_GT(slowed_or_stopped, 30) << "the random scenes test more than passing commands";
}

TEST(GateOnScene, TheOutlineIsTheRobotAtTheContactInTheFixedFrame) {
  // The robot at (1, 2) facing +y; a post 2 m ahead of it, at (1, 4); 1 m/s ahead.
  const PlanarPose pose{{1.0, 2.0}, M_PI / 2};
  const core::Ellipse link{{1.0, 2.0}, 0.3, 0.3, 0.0};
  const core::Ellipse post{{1.0, 4.0}, 0.2, 0.2, 0.0};
  GateConfig config;
  config.timing.horizon = 3.0;
  config.timing.time_before_collision = 0.5;
  config.timing.stop_time = 0.2;
  VelocityCommand command;
  command.linear.x() = 1.0;
  const GateDecision decision =
      gateOnScene(command,
                  placedScene({{"body", core::EllipseRole::Link, link}},
                              {{"post", core::EllipseRole::Obstacle, post}}),
                  {}, pose, core::AllowedPairs(), config);
  EXPECT_EQ(decision.action, GateAction::Pass) << decision.reason;
  ASSERT_TRUE(decision.contact_predicted);
  EXPECT_NEAR(decision.time_to_contact_s, 1.5, 1e-9);
  EXPECT_LT((decision.contact_point - Eigen::Vector2d(1.0, 3.8)).norm(), 1e-6);
  ASSERT_EQ(decision.outline.size(), 1u);
  EXPECT_LT((decision.outline[0].ellipse.center - Eigen::Vector2d(1.0, 3.5)).norm(), 1e-9);
  EXPECT_LT((decision.obstacle_ellipse.center - post.center).norm(), 1e-12);
}

/// Frames of the monitor tests: map, base_link at `base` (x only), timeless unless stamped.
struct Frames {
  double base_x{0.0};
  double base_stamp{0.0};
  bool base_known{true};
  TransformLookup latest() const {
    return [this](const std::string& frame) {
      FrameTransform t;
      if (frame == "map") {
        t.ok = true;
      } else if (frame == "base_link" && base_known) {
        t.ok = true;
        t.fixed_from_frame.translation().x() = base_x;
        t.stamp_s = base_stamp;
      } else {
        t.error = "frame '" + frame + "' does not exist";
      }
      return t;
    };
  }
  TransformAtLookup at() const {
    return [this](const std::string& frame, double) { return latest()(frame); };
  }
};

MonitorSettings gateSettings() {
  MonitorSettings settings;
  settings.check.fixed_frame = "map";
  settings.check.max_transform_age_s = 0.5;
  settings.gate.enabled = true;
  settings.gate.timing.horizon = 3.0;
  settings.gate.timing.time_before_collision = 1.0;
  settings.gate.timing.stop_time = 0.3;
  return settings;
}

VelocityCommand forward(double vx) {
  VelocityCommand command;
  command.linear.x() = vx;
  return command;
}

TEST(MonitorGate, DisabledPassesUnchangedAndTheWatchdogSendsOneZero) {
  CollisionMonitor monitor(gateSettings(), {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  Frames frames;
  EXPECT_EQ(monitor.gateCommand(forward(1.0), 1.0, frames.latest(), frames.at()).action,
            GateAction::Pass);
  EXPECT_FALSE(monitor.gateWatchdog(1.3));
  const auto zero = monitor.gateWatchdog(1.6);
  ASSERT_TRUE(zero);
  EXPECT_EQ(zero->action, GateAction::Timeout);
  EXPECT_EQ(zero->output.linear.x(), 0.0);
  EXPECT_FALSE(monitor.gateWatchdog(2.5)) << "one zero, not a stream";
  monitor.gateCommand(forward(1.0), 3.0, frames.latest(), frames.at());
  EXPECT_TRUE(monitor.gateWatchdog(3.6)) << "again after the next command";

  monitor.setGateEnabled(false);
  VelocityCommand odd = forward(NAN);
  const GateDecision disabled = monitor.gateCommand(odd, 4.0, frames.latest(), frames.at());
  EXPECT_EQ(disabled.action, GateAction::Disabled);
  EXPECT_TRUE(std::isnan(disabled.output.linear.x())) << "unchanged, whatever it is";
  EXPECT_FALSE(monitor.gateWatchdog(10.0)) << "no silence rule while disabled";
  const auto values = monitor.health(10.0).values;
  const std::map<std::string, std::string> shown(values.begin(), values.end());
  EXPECT_EQ(shown.at("gate"), "disabled");
  EXPECT_EQ(shown.at("gate stops"), "2") << "the two zeros of the silence rule";
}

TEST(MonitorGate, IncompleteDataStopsUnlessPassIsAskedAndTheRobotFrameIsAlwaysNeeded) {
  // A link on a frame nobody publishes: incomplete.
  for (const OnIncomplete policy : {OnIncomplete::Stop, OnIncomplete::Pass}) {
    MonitorSettings settings = gateSettings();
    settings.gate.on_incomplete = policy;
    CollisionMonitor monitor(
        settings,
        {circle("body", "base_link", 0, 0, 0.3), circle("gripper", "arm_link", 0.5, 0, 0.1)}, {},
        {}, {});
    Frames frames;
    const GateDecision decision =
        monitor.gateCommand(forward(1.0), 1.0, frames.latest(), frames.at());
    EXPECT_EQ(decision.action,
              policy == OnIncomplete::Stop ? GateAction::Incomplete : GateAction::Pass);
    EXPECT_NE(decision.reason.find("frames unavailable: arm_link"), std::string::npos)
        << decision.reason;
    frames.base_known = false;
    const GateDecision lost = monitor.gateCommand(forward(1.0), 1.1, frames.latest(), frames.at());
    EXPECT_EQ(lost.action, GateAction::Incomplete) << "no robot pose, whatever the policy";
    EXPECT_NE(lost.reason.find("robot_frame 'base_link'"), std::string::npos) << lost.reason;
  }
}

TEST(MonitorGate, ExpiredPerceptionStopsUntilTheNextMessage) {
  MonitorSettings settings = gateSettings();
  settings.obstacle_timeout_s = 0.5;
  CollisionMonitor monitor(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  Frames frames;
  ASSERT_EQ(
      monitor.replaceTopicObstacles({circle("rock", "map", 5.0, 0.0, 0.2)}, 1.0, frames.latest()),
      "");
  EXPECT_EQ(monitor.gateCommand(forward(0.5), 1.2, frames.latest(), frames.at()).action,
            GateAction::Pass);
  const GateDecision blind = monitor.gateCommand(forward(0.5), 2.0, frames.latest(), frames.at());
  EXPECT_EQ(blind.action, GateAction::Incomplete);
  EXPECT_NE(blind.reason.find("obstacle_timeout"), std::string::npos) << blind.reason;
  ASSERT_EQ(
      monitor.replaceTopicObstacles({circle("rock", "map", 5.0, 0.0, 0.2)}, 2.1, frames.latest()),
      "");
  EXPECT_EQ(monitor.gateCommand(forward(0.5), 2.2, frames.latest(), frames.at()).action,
            GateAction::Pass);
}

TEST(MonitorGate, AnObstacleOnTheRobotsOwnFrameStandsAndAnOwnVelocityCounts) {
  // A scan obstacle attached to base_link, 1 m ahead: the gate must not let it travel along.
  CollisionMonitor monitor(gateSettings(), {circle("body", "base_link", 0, 0, 0.3)},
                           {circle("scanned", "base_link", 1.2, 0.0, 0.1)}, {}, {});
  Frames frames;
  const GateDecision toward = monitor.gateCommand(forward(1.0), 1.0, frames.latest(), frames.at());
  EXPECT_EQ(toward.action, GateAction::Slow) << toward.reason;
  EXPECT_EQ(toward.obstacle, "scanned");
  EXPECT_NEAR(toward.time_to_contact_s, 1.0, 0.02) << "0.8 m of gap, slowed so it takes 1 s";

  // A box 2 m ahead (gap) coming at 1 m/s (its own velocity, in map) against a standing one: at
  // 2 m/s the standing box is met in 1 s (= time_before_collision: full speed), the coming one
  // sooner, so the command is slowed to 0.5 (2 m / (2 k + 1) m/s >= 1 s).
  EllipseSpec coming = circle("box", "map", 2.5, 0.0, 0.2);
  coming.vx = -1.0;
  CollisionMonitor with_moving(gateSettings(), {circle("body", "base_link", 0, 0, 0.3)}, {coming},
                               {}, {});
  CollisionMonitor with_standing(gateSettings(), {circle("body", "base_link", 0, 0, 0.3)},
                                 {circle("box", "map", 2.5, 0.0, 0.2)}, {}, {});
  const double moving_scale =
      with_moving.gateCommand(forward(2.0), 1.0, frames.latest(), frames.at()).scale;
  const double standing_scale =
      with_standing.gateCommand(forward(2.0), 1.0, frames.latest(), frames.at()).scale;
  EXPECT_LT(moving_scale, standing_scale - 0.2)
      << "moving " << moving_scale << ", standing " << standing_scale;
}

TEST(MonitorGate, TheKeptGridAnswersAsTheScanAcrossObstacleChanges) {
  // A robot driving and turning among 400 obstacles in map, one walking toward it and 20 on a
  // parked cart. Every command is judged by the monitor, which looks the obstacles near the robot
  // up in the grid it keeps while they stand, and by gateOnScene() scanning the very scene the
  // monitor placed: the same decision bit for bit, while a box is put ahead and taken away
  // (service), the topic obstacles are replaced and cleared, and the cart drives in front of the
  // robot. Each change shows in the very next decision: a grid kept from before it would miss
  // the box.
  std::vector<EllipseSpec> obstacles;
  for (int i = 0; i < 400; ++i) {
    const double x = -10.0 + (i % 20), y = -10.0 + (i / 20) + 0.3 * (i % 3);
    if (std::hypot(x, y) > 4.0)
      obstacles.push_back(circle("rock" + std::to_string(i), "map", x, y, 0.1 + 0.02 * (i % 7)));
  }
  EllipseSpec walker = circle("walker", "map", 4.0, 0.4, 0.2);
  walker.vx = -0.3;
  obstacles.push_back(walker);
  for (int i = 0; i < 20; ++i) {
    obstacles.push_back(
        circle("crate" + std::to_string(i), "cart", 0.1 * (i % 5), 0.15 * (i / 5) - 0.3, 0.08));
  }
  CollisionMonitor monitor(
      gateSettings(),
      {circle("body", "base_link", 0, 0, 0.3), circle("nose", "base_link", 0.4, 0, 0.1)}, obstacles,
      {}, {});
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d cart = Eigen::Isometry3d::Identity();
  cart.translation() << 30.0, 30.0, 0.0;
  const TransformLookup latest = [&](const std::string& frame) {
    FrameTransform t;
    t.ok = frame == "map" || frame == "base_link" || frame == "cart";
    if (frame == "base_link") t.fixed_from_frame = base;
    if (frame == "cart") t.fixed_from_frame = cart;
    if (!t.ok) t.error = "frame '" + frame + "' does not exist";
    return t;
  };
  const TransformAtLookup at = [&](const std::string& frame, double) { return latest(frame); };
  VelocityCommand command = forward(1.0);
  command.angular.z() = 0.2;
  std::size_t through_grid = 0, slowed = 0;
  for (int k = 0; k < 160; ++k) {
    const double now = 1.0 + 0.05 * k;
    base = Eigen::Translation3d(0.01 * k, 0.005 * k, 0.0) *
           Eigen::AngleAxisd(0.01 * k, Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d ahead = base * Eigen::Vector3d(1.2, 0.0, 0.0);
    const Eigen::Vector3d further = base * Eigen::Vector3d(1.6, 0.0, 0.0);
    if (k == 40) {
      ASSERT_TRUE(monitor.addObstacles({circle("box", "map", ahead.x(), ahead.y(), 0.2)}, latest)
                      .success());
    }
    if (k == 80) {
      ASSERT_TRUE(monitor.removeObstacles({"box"}).success());
    }
    if (k == 100) {
      ASSERT_EQ(monitor.replaceTopicObstacles(
                    {circle("scan0", "map", further.x(), further.y(), 0.15)}, now, latest),
                "");
    }
    if (k == 110) {
      ASSERT_EQ(monitor.replaceTopicObstacles({}, now, latest), "");
    }
    if (k == 120) cart.translation() << further.x(), further.y(), 0.0;
    const GateDecision decision = monitor.gateCommand(command, now, latest, at);

    const CheckOutcome& checked = monitor.state().outcome;
    through_grid += checked.standing != nullptr;
    PlanarPose pose;  // as the monitor reads the robot frame
    pose.position = base.translation().head<2>();
    pose.yaw = std::atan2(base.linear()(1, 0), base.linear()(0, 0));
    std::vector<PlacedMotion> moving;
    for (std::size_t i = 0; i < checked.placed.size(); ++i) {
      if (checked.placed.name(i) == "walker") moving.push_back({i, {{-0.3, 0.0}, 0.0}});
    }
    const GateDecision scanned = gateOnScene(command, checked.placed, moving, pose,
                                             core::AllowedPairs(), monitor.gate().config());
    expectSameDecision(decision, scanned, "command " + std::to_string(k));
    slowed += decision.action != GateAction::Pass;
    if (k == 40) {
      EXPECT_EQ(decision.obstacle, "box");
    }
    if (k == 79) {
      EXPECT_NE(checked.standing, nullptr) << "gridded again, with the box";
    }
    if (k == 80) {
      EXPECT_NE(decision.obstacle, "box");
    }
    if (k == 100) {
      EXPECT_EQ(decision.obstacle, "scan0");
    }
    if (k == 110) {
      EXPECT_NE(decision.obstacle, "scan0");
    }
    if (k == 120) {
      EXPECT_EQ(decision.obstacle.rfind("crate", 0), 0u) << decision.obstacle;
    }
  }
  // The grid served most commands (it is built once the obstacles stood for a while).
  EXPECT_GT(through_grid, 60u);
  EXPECT_GT(slowed, 30u) << "the comparison must see slowed and stopped commands";
}

}  // namespace
}  // namespace ellipse_collision::app
