#include "ellipse_collision/ros/collision_node.h"

#include <diagnostic_msgs/DiagnosticArray.h>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/scene_placement.h"
#include "ellipse_collision/ros/tf_lookup.h"

namespace ellipse_collision {
namespace {

std::string entry(const std::string& field, std::size_t index) {
  return field + "[" + std::to_string(index) + "]";
}

std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string joined;
  for (const std::string& part : parts) joined += (joined.empty() ? "" : separator) + part;
  return joined;
}

core::SceneRules makeRules(const NodeConfig& config) {
  core::SceneRules rules;
  rules.self_collision = config.self_collision;
  rules.warning_distance = config.warning_distance_m;
  for (const auto& pair : config.allowed_pairs) rules.allowed.add(pair.first, pair.second);
  return rules;
}

diagnostic_msgs::KeyValue keyValue(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue kv;
  kv.key = key;
  kv.value = value;
  return kv;
}

}  // namespace

CollisionNode::CollisionNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh),
      private_nh_(private_nh),
      config_(loadNodeConfig(private_nh)),
      rules_(makeRules(config_)),
      registry_(config_.links, config_.obstacles),
      tf_buffer_(),
      tf_listener_(tf_buffer_) {
  collisions_pub_ = private_nh_.advertise<CollisionState>("collisions", 1, /*latch=*/true);
  markers_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>(
      "markers", 1,
      [this](const ros::SingleSubscriberPublisher& subscriber) { onMarkerSubscriber(subscriber); },
      ros::SubscriberStatusCallback(), ros::VoidConstPtr(), /*latch=*/true);
  diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
  check_service_ =
      private_nh_.advertiseService("check_collisions", &CollisionNode::onCheckCollisions, this);
  add_service_ =
      private_nh_.advertiseService("add_obstacles", &CollisionNode::onAddObstacles, this);
  remove_service_ =
      private_nh_.advertiseService("remove_obstacles", &CollisionNode::onRemoveObstacles, this);
  obstacles_sub_ = private_nh_.subscribe("obstacles", 10, &CollisionNode::onObstacles, this);

  if (config_.rate_hz > 0.0) {
    check_timer_ = private_nh_.createTimer(ros::Duration(1.0 / config_.rate_hz),
                                           &CollisionNode::onTimer, this);
  }
  diagnostics_timer_ =
      private_nh_.createTimer(ros::Duration(1.0), &CollisionNode::onDiagnosticsTimer, this);

  ROS_INFO_STREAM("ellipse_collision: "
                  << config_.links.size() << " links, " << config_.obstacles.size()
                  << " obstacles in '" << config_.fixed_frame << "', "
                  << (config_.rate_hz > 0.0 ? "checking at " + formatNumber(config_.rate_hz) + " Hz"
                                            : std::string("checking on service calls only"))
                  << (config_.warning_distance_m > 0.0
                          ? ", warning within " + formatNumber(config_.warning_distance_m) + " m"
                          : std::string()));
}

CollisionNode::CheckOutcome CollisionNode::check(const ros::Time& time,
                                                 const ros::Duration& timeout,
                                                 const std::set<std::string>& only_names,
                                                 const std::vector<EllipseSpec>& query,
                                                 const std::string& min_distance_of) {
  CheckOutcome outcome;
  ScenePlacement placement(tf_buffer_, config_.fixed_frame, config_.padding_m, time, timeout);

  std::vector<core::NamedEllipse> scene;
  for (std::size_t i = 0; i < query.size(); ++i) {
    const ScenePlacement::Placement placed = placement.place(query[i], core::EllipseRole::Query);
    if (placed.status == ScenePlacement::Status::FrameUnavailable) {
      outcome.error = entry("query", i) + ".frame_id = '" + query[i].frame_id +
                      "': expected a frame with a transform to '" + config_.fixed_frame +
                      "', got none (" + placed.error + ")";
      return outcome;
    }
    if (placed.status == ScenePlacement::Status::Degenerate) {
      outcome.error = entry("query", i) + ": " + placed.error;
      return outcome;
    }
    scene.push_back(placed.ellipse);
  }

  std::set<std::string> unavailable;
  for (const auto& named : registry_.entries()) {
    const StoredEllipse& stored = named.second;
    const ScenePlacement::Placement placed = placement.place(stored.spec, stored.role());
    switch (placed.status) {
      case ScenePlacement::Status::Placed:
        scene.push_back(placed.ellipse);
        outcome.placed.push_back(placed.ellipse);
        break;
      case ScenePlacement::Status::FrameUnavailable:
        unavailable.insert(stored.spec.frame_id);
        outcome.skipped.push_back(named.first + ": frame '" + stored.spec.frame_id +
                                  "' unavailable");
        break;
      case ScenePlacement::Status::Degenerate:
        outcome.skipped.push_back(placed.error);
        break;
    }
  }
  outcome.unavailable_frames.assign(unavailable.begin(), unavailable.end());

  core::SceneCheckResult result = core::checkScene(scene, rules_, only_names);
  if (!result.ok()) {
    // Requests are validated before they get here, so this is a bug worth shouting about.
    ROS_ERROR_STREAM("ellipse_collision: scene refused by the core: " << result.error);
    outcome.error = "internal error: " + result.error;
    return outcome;
  }
  outcome.collisions = std::move(result.collisions);
  outcome.warnings = std::move(result.warnings);

  if (min_distance_of.empty()) return outcome;
  const std::string where = "min_distance_of = '" + min_distance_of + "': ";
  const bool placed = std::any_of(scene.begin(), scene.end(),
                                  [&](const core::NamedEllipse& e) { return e.name == min_distance_of; });
  if (!placed) {
    outcome.nearest_problem = where + "not measured, the ellipse could not be placed";
    return outcome;
  }
  const core::NearestResult nearest = core::nearestTo(scene, rules_, min_distance_of);
  if (!nearest.ok()) {
    ROS_ERROR_STREAM("ellipse_collision: nearest refused by the core: " << nearest.error);
    outcome.error = "internal error: " + nearest.error;
  } else if (!nearest.found) {
    outcome.nearest_problem = where + "no placed ellipse that the pair rules measure it against";
  } else {
    outcome.nearest = nearest.nearest;
  }
  return outcome;
}

CollisionNode::CheckOutcome CollisionNode::runFullCheck(const ros::Duration& timeout,
                                                        const std::string& min_distance_of) {
  const auto start = std::chrono::steady_clock::now();
  CheckOutcome outcome = check(ros::Time(0), timeout, {}, {}, min_distance_of);
  if (!outcome.error.empty()) {
    // Never publish a failed check as "clear": the topics keep the last good state.
    ROS_ERROR_STREAM_THROTTLE(5.0, "ellipse_collision: check failed: " << outcome.error);
    state_.failure = outcome.error;
    return outcome;
  }
  state_.failure.clear();
  state_.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  state_.valid = true;
  state_.stamp = ros::Time::now();
  state_.outcome = outcome;
  ++full_checks_;
  if (!outcome.skipped.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: skipped " << join(outcome.skipped, "; "));
  }
  publishState();
  publishMarkers();
  return outcome;
}

void CollisionNode::publishState() {
  CollisionState msg;
  msg.header.stamp = state_.stamp;
  msg.header.frame_id = config_.fixed_frame;
  msg.collisions = toMsg(state_.outcome.collisions);
  msg.in_collision = !msg.collisions.empty();
  msg.unavailable_frames = state_.outcome.unavailable_frames;
  msg.warnings = toMsg(state_.outcome.warnings);
  collisions_pub_.publish(msg);
}

void CollisionNode::publishMarkers() {
  // Nobody listening: skip the work. onMarkerSubscriber() publishes for the next subscriber.
  if (!state_.valid || markers_pub_.getNumSubscribers() == 0) return;
  markers_pub_.publish(markers_.update(state_.outcome.placed, state_.outcome.collisions,
                                       state_.outcome.warnings, config_.fixed_frame, state_.stamp));
}

std::string CollisionNode::validateAttached(const std::vector<EllipseSpec>& specs,
                                            const std::string& field) {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (const auto invalid = findInvalidPaddedField(specs[i], config_.padding_m)) {
      return describeRequestError(entry(field, i), *invalid);
    }
  }
  for (std::size_t i = 0; i < specs.size(); ++i) {
    Eigen::Isometry3d unused;
    std::string error;
    if (!lookupTransformSafe(tf_buffer_, config_.fixed_frame, specs[i].frame_id, ros::Time(0),
                             ros::Duration(config_.tf_timeout_s), unused, &error)) {
      return entry(field, i) + ".frame_id = '" + specs[i].frame_id +
             "': expected a known tf frame with a transform to '" + config_.fixed_frame +
             "', got none (" + error + ")";
    }
  }
  return {};
}

void CollisionNode::onTimer(const ros::TimerEvent& /*event*/) {
  // No waiting for transforms: a periodic check must not stall on a missing frame.
  runFullCheck(ros::Duration(0));
}

void CollisionNode::onMarkerSubscriber(const ros::SingleSubscriberPublisher& /*subscriber*/) {
  // The latched array may predate checks that were skipped while nobody listened: refresh it.
  publishMarkers();
}

void CollisionNode::onObstacles(const EllipseArray::ConstPtr& msg) {
  const std::vector<EllipseSpec> specs = fromMsg(*msg);
  std::string error = validateAttached(specs, "ellipses");
  if (error.empty()) error = registry_.replaceTopicObstacles(specs, "ellipses");
  last_obstacles_error_ = error;
  if (!error.empty()) {
    ROS_WARN_STREAM_THROTTLE(
        5.0,
        "ellipse_collision: refused ~obstacles message, previous topic obstacles kept: " << error);
  }
}

bool CollisionNode::onCheckCollisions(CheckCollisions::Request& request,
                                      CheckCollisions::Response& response) {
  response.success = false;
  std::vector<EllipseSpec> query;
  std::set<std::string> query_names;
  for (std::size_t i = 0; i < request.query.size(); ++i) {
    query.push_back(fromMsg(request.query[i]));
    if (const auto invalid = findInvalidPaddedField(query.back(), config_.padding_m)) {
      response.message = describeRequestError(entry("query", i), *invalid);
      return true;
    }
    const std::string& name = query.back().name;
    if (registry_.contains(name) || !query_names.insert(name).second) {
      response.message = entry("query", i) + ".name = '" + name + "': expected a name used by " +
                         "no link, obstacle or other query, got a duplicate";
      return true;
    }
  }
  std::set<std::string> only_names;
  for (std::size_t i = 0; i < request.names.size(); ++i) {
    const std::string& name = request.names[i];
    const std::string where = entry("names", i) + " = '" + name + "': expected ";
    if (name.empty()) {
      response.message = where + "a non-empty name";
      return true;
    }
    if (!registry_.contains(name) && !query_names.count(name)) {
      response.message = where + "the name of a link, obstacle or query, got an unknown name";
      return true;
    }
    if (!only_names.insert(name).second) {
      response.message = where + "each name once, got a duplicate";
      return true;
    }
  }
  const std::string& min_distance_of = request.min_distance_of;
  if (!min_distance_of.empty() && !registry_.contains(min_distance_of) &&
      !query_names.count(min_distance_of)) {
    response.message = "min_distance_of = '" + min_distance_of +
                       "': expected the name of a link, obstacle or query (or empty), got an " +
                       "unknown name";
    return true;
  }

  // A full check at the latest time is what the topics show: record and publish it too (with
  // rate = 0 this is the only way they are updated).
  const ros::Duration timeout(config_.tf_timeout_s);
  const bool full_check = request.names.empty() && request.query.empty() && request.stamp.isZero();
  const CheckOutcome outcome =
      full_check ? runFullCheck(timeout, min_distance_of)
                 : check(request.stamp, timeout, only_names, query, min_distance_of);
  if (!outcome.error.empty()) {
    response.message = outcome.error;
    return true;
  }
  response.success = true;
  std::vector<std::string> notes;
  if (!outcome.skipped.empty()) notes.push_back("skipped " + join(outcome.skipped, "; "));
  if (!outcome.nearest_problem.empty()) notes.push_back(outcome.nearest_problem);
  response.message = join(notes, "; ");
  response.collisions = toMsg(outcome.collisions);
  response.in_collision = !response.collisions.empty();
  response.unavailable_frames = outcome.unavailable_frames;
  response.warnings = toMsg(outcome.warnings);
  response.has_min_distance = outcome.nearest.has_value();
  if (outcome.nearest) response.nearest = toMsg(*outcome.nearest);
  return true;
}

bool CollisionNode::onAddObstacles(AddObstacles::Request& request,
                                   AddObstacles::Response& response) {
  std::vector<EllipseSpec> specs;
  for (const Ellipse& msg : request.obstacles) specs.push_back(fromMsg(msg));
  std::string error = validateAttached(specs, "obstacles");
  if (error.empty()) error = registry_.addObstacles(specs, "obstacles");
  response.success = error.empty();
  response.message =
      error.empty() ? "added " + std::to_string(specs.size()) + " obstacle(s)" : error;
  return true;
}

bool CollisionNode::onRemoveObstacles(RemoveObstacles::Request& request,
                                      RemoveObstacles::Response& response) {
  const std::string error = registry_.removeObstacles(request.names, "names");
  response.success = error.empty();
  response.message =
      error.empty() ? "removed " + std::to_string(request.names.size()) + " obstacle(s)" : error;
  return true;
}

void CollisionNode::onDiagnosticsTimer(const ros::TimerEvent& /*event*/) {
  diagnostic_msgs::DiagnosticStatus status;
  status.name = ros::this_node::getName() + ": collision check";
  status.hardware_id = config_.fixed_frame;
  std::vector<std::string> problems;
  if (!state_.valid) problems.push_back("no check yet");
  if (!state_.outcome.unavailable_frames.empty()) {
    problems.push_back("frames unavailable: " + join(state_.outcome.unavailable_frames, ", "));
  }
  if (!state_.outcome.skipped.empty()) {
    problems.push_back("skipped: " + join(state_.outcome.skipped, "; "));
  }
  if (!last_obstacles_error_.empty()) {
    problems.push_back("last ~obstacles message refused: " + last_obstacles_error_);
  }
  if (!state_.failure.empty()) problems.push_back("last check failed: " + state_.failure);
  const bool only_waiting = !state_.valid && problems.size() == 1;
  status.level = !state_.failure.empty()            ? diagnostic_msgs::DiagnosticStatus::ERROR
                 : problems.empty() || only_waiting ? diagnostic_msgs::DiagnosticStatus::OK
                                                    : diagnostic_msgs::DiagnosticStatus::WARN;
  status.message = !problems.empty()                    ? join(problems, "; ")
                   : !state_.outcome.collisions.empty() ? "in collision"
                   : !state_.outcome.warnings.empty()   ? "closer than the warning distance"
                                                        : "clear";

  status.values.push_back(
      keyValue("links", std::to_string(registry_.count(EllipseSource::ConfiguredLink))));
  status.values.push_back(
      keyValue("obstacles (configured)",
               std::to_string(registry_.count(EllipseSource::ConfiguredObstacle))));
  status.values.push_back(keyValue(
      "obstacles (service)", std::to_string(registry_.count(EllipseSource::ServiceObstacle))));
  status.values.push_back(
      keyValue("obstacles (topic)", std::to_string(registry_.count(EllipseSource::TopicObstacle))));
  status.values.push_back(
      keyValue("unavailable frames", join(state_.outcome.unavailable_frames, ", ")));
  status.values.push_back(keyValue("collisions", std::to_string(state_.outcome.collisions.size())));
  status.values.push_back(keyValue("warnings", std::to_string(state_.outcome.warnings.size())));
  status.values.push_back(keyValue("full checks", std::to_string(full_checks_)));
  status.values.push_back(
      keyValue("last check duration [ms]", formatNumber(1e3 * state_.duration_s)));

  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

}  // namespace ellipse_collision
