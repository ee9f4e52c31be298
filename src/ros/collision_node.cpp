#include "ellipse_collision/ros/collision_node.h"

#include <diagnostic_msgs/DiagnosticArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>

#include "ellipse_collision/app/check_health.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/tf_lookup.h"
#include "ellipse_collision/ros/urdf_links.h"

namespace ellipse_collision {
namespace {

app::CheckSettings makeSettings(const NodeConfig& config) {
  app::CheckSettings settings;
  settings.fixed_frame = config.fixed_frame;
  settings.global_padding_m = config.padding_m;
  settings.rules.self_collision = config.self_collision;
  settings.rules.warning_distance = config.warning_distance_m;
  settings.max_transform_age_s = config.max_transform_age_s;
  for (const auto& pair : config.allowed_pairs) settings.rules.allowed.add(pair.first, pair.second);
  return settings;
}

/// Marker arrays queued per ~markers subscriber (besides the one being written). Short, because a
/// subscriber that cannot keep up (rviz over a slow link, 10,000 moving obstacles) would otherwise
/// hold the node's memory: with 100, 10,000 obstacles streamed at 10 Hz to node_load.py's
/// subscriber took the node to 1.1 GB RSS, with 4 to 144 MB, with 2 to 90 MB (36 MB without a
/// subscriber). What a subscriber loses is made good by the refresh sweep
/// (CollisionMarkers::appendRefresh()). More than one, so that a new subscriber's full array,
/// queued behind the latched one, is not dropped by the next check's changes.
constexpr std::uint32_t kMarkerQueue = 2;

/// The largest share of the refresh sweep one array carries: after a long gap (rate 0 and rare
/// calls, a stalled node) the sweep catches up over ten arrays instead of sending the whole view
/// (130 MB at 100,000 obstacles) in one.
constexpr double kMaxRefreshShare = 0.1;

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
      config_(loadNodeConfig(private_nh, fitUrdfLinksFromParam)),
      settings_(makeSettings(config_)),
      registry_(config_.links, config_.obstacles, config_.limits),
      tf_buffer_(),
      tf_listener_(tf_buffer_) {
  obstacle_store_ = config_.obstacle_store ? *config_.obstacle_store
                                           : defaultObstacleStore(ros::this_node::getName());
  const std::uint64_t service_revision = restoreObstacles();
  persistence_ =
      std::make_unique<app::ObstaclePersistence>(obstacle_store_, session_, service_revision);
  if (persistence_->enabled()) {
    if (config_.obstacle_store_period_s > 0.0) {
      store_timer_ = nh_.createWallTimer(ros::WallDuration(config_.obstacle_store_period_s),
                                         &CollisionNode::onStoreTimer, this);
    }
  }
  collisions_pub_ = private_nh_.advertise<CollisionState>("collisions", 1, /*latch=*/true);
  // The arrays carry changes: a queue of kMarkerQueue arrays per subscriber (roscpp drops the
  // oldest beyond it), and the refresh sweep for what a slow subscriber still loses.
  markers_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>(
      "markers", kMarkerQueue,
      [this](const ros::SingleSubscriberPublisher& subscriber) { onMarkerSubscriber(subscriber); },
      ros::SubscriberStatusCallback(), ros::VoidConstPtr(), /*latch=*/true);
  diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
  check_service_ =
      private_nh_.advertiseService("check_collisions", &CollisionNode::onCheckCollisions, this);
  add_service_ =
      private_nh_.advertiseService("add_obstacles", &CollisionNode::onAddObstacles, this);
  remove_service_ =
      private_nh_.advertiseService("remove_obstacles", &CollisionNode::onRemoveObstacles, this);
  path_service_ = private_nh_.advertiseService("check_path", &CollisionNode::onCheckPath, this);
  obstacles_sub_ = private_nh_.subscribe("obstacles", 10, &CollisionNode::onObstacles, this);

  if (config_.rate_hz > 0.0) {
    check_timer_ = private_nh_.createTimer(ros::Duration(1.0 / config_.rate_hz),
                                           &CollisionNode::onTimer, this);
  }
  diagnostics_timer_ =
      private_nh_.createTimer(ros::Duration(1.0), &CollisionNode::onDiagnosticsTimer, this);

  for (const std::string& skipped : config_.urdf_links_skipped) {
    ROS_INFO_STREAM("ellipse_collision: links_from_urdf skipped " << skipped);
  }
  ROS_INFO_STREAM("ellipse_collision: "
                  << config_.links.size() << " links, " << config_.obstacles.size()
                  << " obstacles in '" << config_.fixed_frame << "', "
                  << (config_.rate_hz > 0.0 ? "checking at " + core::formatNumber(config_.rate_hz) + " Hz"
                                            : std::string("checking on service calls only"))
                  << (config_.warning_distance_m > 0.0
                          ? ", warning within " + core::formatNumber(config_.warning_distance_m) + " m"
                          : std::string()));
}

std::uint64_t CollisionNode::restoreObstacles() {
  if (obstacle_store_.empty()) return 0;
  ros::param::get("/run_id", session_);
  const app::LoadedStore loaded = app::loadObstacleStore(obstacle_store_, session_);
  for (const app::LoadedStore::Note& note : loaded.notes) {
    if (note.failed) {
      ROS_ERROR_STREAM("ellipse_collision: obstacle store " << note.text << ", not restored");
    } else {
      ROS_INFO_STREAM("ellipse_collision: obstacle store " << note.text << ", not restored");
    }
  }
  // Counted on from what this launch wrote, restored or not: a later record must never lose to
  // a stale one of the same launch.
  const std::uint64_t service_revision = loaded.obstacles.service_revision;
  if (!loaded.found) return service_revision;
  const app::StoredObstacles& stored = loaded.obstacles;
  const std::string error = registry_.restore(stored);
  if (!error.empty()) {
    ROS_ERROR_STREAM("ellipse_collision: obstacle store '" << obstacle_store_
                     << "' does not fit the configuration, starting without it: " << error);
    return service_revision;
  }
  ROS_WARN_STREAM("ellipse_collision: restarted: restored " << stored.service.size()
                  << " service obstacle(s) and " << stored.topic.size()
                  << " topic obstacle(s) from '" << obstacle_store_ << "'");
  return service_revision;
}

std::string CollisionNode::persistServiceCall(bool removed_topic_obstacle) {
  const std::string error = persistence_->afterServiceCall(registry_, removed_topic_obstacle);
  logStoreError(error);
  return error;
}

void CollisionNode::persistObstaclesLater() {
  if (!persistence_->enabled()) return;
  persistence_->topicChanged();
  if (config_.obstacle_store_period_s == 0.0) onStoreTimer(ros::WallTimerEvent());
}

void CollisionNode::onStoreTimer(const ros::WallTimerEvent& /*event*/) {
  logStoreError(persistence_->lastError());
  persistence_->writeIfBehind(registry_);
}

void CollisionNode::logStoreError(const std::string& error) const {
  if (error.empty()) return;
  ROS_ERROR_STREAM_THROTTLE(5.0, "ellipse_collision: cannot persist the runtime obstacles: " << error);
}

CollisionNode::~CollisionNode() {
  persistence_->writeIfBehind(registry_);
  // persistence_'s writer writes what is queued before the node's members go.
}

void CollisionNode::handleTimeJumpAndExpiry() {
  const ros::Time now = ros::Time::now();
  if (now < last_now_) {
    // A bag played in a loop, a simulator reset: tf2 would keep answering from the future.
    ROS_WARN_STREAM("ellipse_collision: time jumped back by "
                    << core::formatNumber((last_now_ - now).toSec())
                    << " s, clearing the tf buffer");
    tf_buffer_.clear();
    missing_since_.clear();
    ++time_jumps_;
  }
  last_now_ = now;
  const std::size_t dropped =
      registry_.dropExpiredTopicObstacles(now.toSec(), config_.obstacle_timeout_s);
  if (dropped > 0) {
    dropped_obstacles_ += dropped;
    persistObstaclesLater();
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: dropped "
                                      << dropped << " obstacle(s) from ~obstacles: the last message is "
                                      << core::formatNumber(now.toSec() - registry_.topicStamp())
                                      << " s old, older than obstacle_timeout "
                                      << core::formatNumber(config_.obstacle_timeout_s) << " s");
  }
}

const app::CheckOutcome& CollisionNode::runFullCheck(const ros::Duration& timeout,
                                                     StatePublishing publishing,
                                                     const std::string& min_distance_of) {
  handleTimeJumpAndExpiry();
  const auto start = std::chrono::steady_clock::now();
  app::CheckRequest request;
  request.min_distance_of = min_distance_of;
  const ros::Time now = ros::Time::now();
  app::CheckOutcome outcome = app::runCheck(
      request, registry_, settings_,
      tfLookup(tf_buffer_, config_.fixed_frame, ros::Time(0), timeout), now.toSec(),
      &placement_cache_);
  if (!outcome.error.empty()) {
    // Never publish a failed check as "clear": the topics keep the last good state.
    ROS_ERROR_STREAM_THROTTLE(5.0, "ellipse_collision: check failed: " << outcome.error);
    state_.failure = outcome.error;
    failed_check_ = std::move(outcome);
    return failed_check_;
  }
  predict(outcome, request, ros::Time(0), now);  // times from the state's stamp
  state_.failure.clear();
  state_.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  state_.valid = true;
  state_.stamp = now;
  // The replaced state's placement goes back to the cache: the next check refills it instead of
  // copying every name again.
  core::Scene replaced = std::move(state_.outcome.placed);
  state_.outcome = std::move(outcome);
  placement_cache_.recycle(std::move(replaced));
  const app::CheckOutcome& checked = state_.outcome;
  // Since when each frame has been missing (unavailable or stale), for the diagnostics level.
  std::set<std::string> missing(checked.unavailable_frames.begin(), checked.unavailable_frames.end());
  missing.insert(checked.stale_frames.begin(), checked.stale_frames.end());
  for (auto it = missing_since_.begin(); it != missing_since_.end();) {
    it = missing.count(it->first) ? std::next(it) : missing_since_.erase(it);
  }
  for (const std::string& frame : missing) missing_since_.emplace(frame, now);
  ++full_checks_;
  if (!checked.skipped.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: skipped " << app::joinText(checked.skipped, "; "));
  }
  publishState(config_.rate_hz > 0.0 ? publishing : StatePublishing::Always);
  publishMarkers();
  return checked;
}

namespace {

/// Everything of the state but its stamp: the message's own operator==, so that a field added to
/// CollisionState later is compared too.
bool sameContent(CollisionState& a, const CollisionState& b) {
  const ros::Time stamp = a.header.stamp;
  a.header.stamp = b.header.stamp;
  const bool same = a == b;
  a.header.stamp = stamp;
  return same;
}

}  // namespace

void CollisionNode::publishState(StatePublishing publishing) {
  CollisionState msg;
  msg.header.stamp = state_.stamp;
  msg.header.frame_id = config_.fixed_frame;
  msg.collisions = toMsg(state_.outcome.collisions);
  msg.in_collision = !msg.collisions.empty();
  msg.unavailable_frames = state_.outcome.unavailable_frames;
  msg.warnings = toMsg(state_.outcome.warnings);
  msg.stale_frames = state_.outcome.stale_frames;
  msg.complete = state_.outcome.complete;
  msg.predicted = toMsg(state_.outcome.predicted);
  if (publishing == StatePublishing::OnChange && state_published_ &&
      sameContent(msg, last_state_msg_)) {
    return;
  }
  collisions_pub_.publish(msg);
  last_state_msg_ = std::move(msg);
  state_published_ = true;
}

void CollisionNode::publishMarkers() {
  // Nobody listening: skip the work. onMarkerSubscriber() publishes for the next subscriber.
  if (!state_.valid || markers_pub_.getNumSubscribers() == 0) {
    last_markers_time_ = ros::WallTime();  // no sweep is owed for the time nobody listened
    return;
  }
  std::set<std::string> predicted;
  for (const core::PredictedContact& p : state_.outcome.predicted) {
    predicted.insert({p.name_a, p.name_b});
  }
  // Only what changed since the last array: an unchanged scene publishes nothing.
  visualization_msgs::MarkerArray changes =
      markers_.update(state_.outcome.placed, state_.outcome.collisions, state_.outcome.warnings,
                      config_.fixed_frame, state_.stamp, predicted);
  // Plus a slice of the refresh sweep, by wall time: it heals what a network lost, whatever the
  // ROS clock does.
  const ros::WallTime now = ros::WallTime::now();
  if (config_.marker_refresh_period_s > 0.0 && !last_markers_time_.isZero()) {
    markers_.appendRefresh(changes, std::min(kMaxRefreshShare,
                                             (now - last_markers_time_).toSec() /
                                                 config_.marker_refresh_period_s));
  }
  last_markers_time_ = now;
  if (!changes.markers.empty()) markers_pub_.publish(changes);
}

void CollisionNode::onTimer(const ros::TimerEvent& /*event*/) {
  // No waiting for transforms: a periodic check must not stall on a missing frame.
  runFullCheck(ros::Duration(0), StatePublishing::Always);
}

void CollisionNode::onMarkerSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  // The arrays only carry changes, so the latched one is not the whole view: bring everyone up to
  // date (checks were skipped while nobody listened), then send the newcomer alone everything.
  publishMarkers();
  if (state_.valid) subscriber.publish(markers_.fullArray());
}

void CollisionNode::onObstacles(const EllipseArray::ConstPtr& msg) {
  const std::vector<app::EllipseSpec> specs = fromMsg(*msg);
  std::string error = app::validateAttached(
      specs, "ellipses", settings_,
      tfLookup(tf_buffer_, config_.fixed_frame, ros::Time(0), ros::Duration(config_.tf_timeout_s)));
  if (error.empty()) {
    error = registry_.replaceTopicObstacles(specs, "ellipses", msg->header.stamp.toSec());
    if (error.empty()) persistObstaclesLater();
  }
  last_obstacles_error_ = error;
  if (!error.empty()) {
    ROS_WARN_STREAM_THROTTLE(
        5.0,
        "ellipse_collision: refused ~obstacles message, previous topic obstacles kept: " << error);
  }
}

bool CollisionNode::onCheckCollisions(CheckCollisions::Request& request,
                                      CheckCollisions::Response& response) {
  const app::CheckRequest check = fromMsg(request);
  response.success = false;
  response.message = app::validateCheckRequest(check, registry_, settings_.global_padding_m);
  if (!response.message.empty()) return true;

  // A full check at the latest time is what the topics show: record it, publish the state when
  // it changed (with rate = 0, every time: then this is the only way the topics are updated).
  const ros::Duration timeout(config_.tf_timeout_s);
  const bool full_check = request.names.empty() && request.query.empty() && request.stamp.isZero();
  if (!full_check) handleTimeJumpAndExpiry();
  // Freshness is measured against now for latest-transform checks, else the requested stamp.
  const double reference_s = (request.stamp.isZero() ? ros::Time::now() : request.stamp).toSec();
  // A full check's outcome stays in state_ (no copy); a partial one lives here.
  app::CheckOutcome partial;
  if (!full_check) {
    partial = app::runCheck(check, registry_, settings_,
                            tfLookup(tf_buffer_, config_.fixed_frame, request.stamp, timeout),
                            reference_s);
    if (partial.error.empty()) predict(partial, check, request.stamp);
  }
  const app::CheckOutcome& outcome =
      full_check ? runFullCheck(timeout, StatePublishing::OnChange, check.min_distance_of)
                 : partial;
  if (!outcome.error.empty()) {
    ROS_ERROR_STREAM_COND(outcome.error.rfind("internal error", 0) == 0,
                          "ellipse_collision: " << outcome.error);
    response.message = outcome.error;
    return true;
  }
  toMsg(outcome, response);
  return true;
}

bool CollisionNode::onAddObstacles(AddObstacles::Request& request,
                                   AddObstacles::Response& response) {
  std::vector<app::EllipseSpec> specs;
  for (const Ellipse& msg : request.obstacles) specs.push_back(fromMsg(msg));
  std::string error = app::validateAttached(
      specs, "obstacles", settings_,
      tfLookup(tf_buffer_, config_.fixed_frame, ros::Time(0), ros::Duration(config_.tf_timeout_s)));
  if (error.empty()) error = registry_.addObstacles(specs, "obstacles");
  // Durable before success: a node killed right after the answer restores them.
  if (error.empty()) {
    const std::string store_error = persistServiceCall(/*removed_topic_obstacle=*/false);
    if (!store_error.empty()) error = "added in memory but not persisted: " + store_error;
  }
  response.success = error.empty();
  response.message =
      error.empty() ? "added " + std::to_string(specs.size()) + " obstacle(s)" : error;
  return true;
}

bool CollisionNode::onRemoveObstacles(RemoveObstacles::Request& request,
                                      RemoveObstacles::Response& response) {
  const bool removes_topic_obstacle = registry_.anyTopicObstacle(request.names);
  std::string error = registry_.removeObstacles(request.names, "names");
  if (error.empty()) {
    const std::string store_error = persistServiceCall(removes_topic_obstacle);
    if (!store_error.empty()) error = "removed in memory but not persisted: " + store_error;
  }
  response.success = error.empty();
  response.message =
      error.empty() ? "removed " + std::to_string(request.names.size()) + " obstacle(s)" : error;
  return true;
}

void CollisionNode::predict(app::CheckOutcome& outcome, const app::CheckRequest& request,
                            const ros::Time& stamp, const ros::Time& reference) {
  if (!(config_.prediction_horizon_s > 0.0)) return;
  const tf2_ros::Buffer& buffer = tf_buffer_;
  const std::string fixed_frame = config_.fixed_frame;
  const double reference_s = (!reference.isZero() ? reference
                              : stamp.isZero()    ? ros::Time::now()
                                                  : stamp)
                                 .toSec();
  app::predictContacts(
      outcome, request, registry_, settings_,
      tfLookup(tf_buffer_, config_.fixed_frame, stamp, ros::Duration(0)),
      [&buffer, fixed_frame](const std::string& frame, double time_s) {
        return tfLookup(buffer, fixed_frame, ros::Time(time_s), ros::Duration(0))(frame);
      },
      config_.prediction_horizon_s, reference_s);
  if (!outcome.prediction_notes.empty()) {
    ROS_WARN_STREAM_THROTTLE(
        5.0, "ellipse_collision: prediction: " << app::joinText(outcome.prediction_notes, "; "));
  }
}

bool CollisionNode::onCheckPath(CheckPath::Request& request, CheckPath::Response& response) {
  app::PathCheckRequest path = fromMsg(request);
  if (path.path_frame.empty()) path.path_frame = config_.fixed_frame;
  if (path.moving_frame.empty()) path.moving_frame = config_.robot_frame;
  response.success = false;
  response.message = app::validatePathRequest(path);
  if (!response.message.empty()) return true;
  handleTimeJumpAndExpiry();
  const ros::Duration timeout(config_.tf_timeout_s);
  const app::PathCheckOutcome outcome = app::runPathCheck(
      path, registry_, settings_, tfLookup(tf_buffer_, path.moving_frame, ros::Time(0), timeout),
      tfLookup(tf_buffer_, path.path_frame, ros::Time(0), timeout), ros::Time::now().toSec());
  if (!outcome.error.empty()) {
    response.message = outcome.error;
    return true;
  }
  toMsg(outcome, response);
  return true;
}

void CollisionNode::onDiagnosticsTimer(const ros::TimerEvent& /*event*/) {
  diagnostic_msgs::DiagnosticStatus status;
  status.name = ros::this_node::getName() + ": collision check";
  status.hardware_id = config_.fixed_frame;
  app::CheckHealthInputs inputs;
  inputs.outcome = state_.valid ? &state_.outcome : nullptr;
  inputs.check_failure = state_.failure;
  const ros::Time now = ros::Time::now();
  for (const auto& [frame, since] : missing_since_) {
    inputs.missing_for_s.emplace_back(frame, (now - since).toSec());
  }
  inputs.obstacles_error = last_obstacles_error_;
  inputs.store_error = persistence_->lastError();
  const app::CheckHealth health = app::assessCheckHealth(inputs);
  status.level = health.level == app::CheckHealth::Level::Error ? diagnostic_msgs::DiagnosticStatus::ERROR
                 : health.level == app::CheckHealth::Level::Warn
                     ? diagnostic_msgs::DiagnosticStatus::WARN
                     : diagnostic_msgs::DiagnosticStatus::OK;
  status.message = health.message;

  status.values.push_back(
      keyValue("links", std::to_string(registry_.count(app::EllipseSource::ConfiguredLink))));
  status.values.push_back(
      keyValue("obstacles (configured)",
               std::to_string(registry_.count(app::EllipseSource::ConfiguredObstacle))));
  status.values.push_back(keyValue(
      "obstacles (service)", std::to_string(registry_.count(app::EllipseSource::ServiceObstacle))));
  status.values.push_back(
      keyValue("obstacles (topic)", std::to_string(registry_.count(app::EllipseSource::TopicObstacle))));
  status.values.push_back(
      keyValue("unavailable frames", app::joinText(state_.outcome.unavailable_frames, ", ")));
  status.values.push_back(keyValue("collisions", std::to_string(state_.outcome.collisions.size())));
  status.values.push_back(keyValue("warnings", std::to_string(state_.outcome.warnings.size())));
  status.values.push_back(keyValue("full checks", std::to_string(full_checks_)));
  status.values.push_back(
      keyValue("last check duration [ms]", core::formatNumber(1e3 * state_.duration_s)));
  status.values.push_back(keyValue("complete", state_.valid && state_.outcome.complete ? "true" : "false"));
  status.values.push_back(keyValue("stale frames", app::joinText(state_.outcome.stale_frames, ", ")));
  status.values.push_back(keyValue("missing for [s]", app::joinText(health.missing_for, ", ")));
  status.values.push_back(
      keyValue("dropped obstacles (obstacle_timeout)", std::to_string(dropped_obstacles_)));
  status.values.push_back(keyValue("time jumps back", std::to_string(time_jumps_)));
  status.values.push_back(
      keyValue("prediction horizon [s]", core::formatNumber(config_.prediction_horizon_s)));
  status.values.push_back(
      keyValue("smallest time to contact [s]",
               state_.outcome.predicted.empty()
                   ? std::string("none")
                   : core::formatNumber(state_.outcome.predicted.front().time)));
  status.values.push_back(
      keyValue("predicted contacts", std::to_string(state_.outcome.predicted.size())));
  status.values.push_back(
      keyValue("prediction notes", app::joinText(state_.outcome.prediction_notes, "; ")));

  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

}  // namespace ellipse_collision
