#include "ellipse_collision/ros/collision_node.h"

#include <diagnostic_msgs/DiagnosticArray.h>

#include <algorithm>
#include <set>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/incident_bag.h"
#include "ellipse_collision/ros/tf_lookup.h"
#include "ellipse_collision/ros/urdf_links.h"

namespace ellipse_collision {
namespace {

/// `node_name`: the private namespace, the node's name (or the nodelet's, in a manager).
app::StoreOptions storeOptions(const NodeConfig& config, const std::string& node_name) {
  app::StoreOptions store;
  store.path = config.obstacle_store ? *config.obstacle_store : defaultObstacleStore(node_name);
  if (!store.path.empty()) ros::param::get("/run_id", store.session);
  return store;
}

void logStartupNote(const app::StartupNote& note) {
  switch (note.level) {
    case app::StartupNote::Level::Error:
      ROS_ERROR_STREAM("ellipse_collision: " << note.text);
      break;
    case app::StartupNote::Level::Warn:
      ROS_WARN_STREAM("ellipse_collision: " << note.text);
      break;
    case app::StartupNote::Level::Info:
      ROS_INFO_STREAM("ellipse_collision: " << note.text);
      break;
  }
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

NodeConfig loadCollisionNodeConfig(const ros::NodeHandle& private_nh) {
  return loadNodeConfig(private_nh, fitUrdfLinksFromParam);
}

CollisionNode::CollisionNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh),
      private_nh_(private_nh),
      config_(loadCollisionNodeConfig(private_nh)),
      tf_buffer_(),
      tf_listener_(tf_buffer_) {
  app::MonitorHooks hooks;
  hooks.time_jumped_back = [this](double seconds) {
    ROS_WARN_STREAM("ellipse_collision: time jumped back by " << core::formatNumber(seconds)
                                                              << " s, clearing the tf buffer");
    tf_buffer_.clear();
  };
  hooks.obstacles_expired = [this](std::size_t count, double age_s) {
    ROS_WARN_STREAM_THROTTLE(
        5.0, "ellipse_collision: dropped "
                 << count << " obstacle(s) from ~obstacles: the last message is "
                 << core::formatNumber(age_s) << " s old, older than obstacle_timeout "
                 << core::formatNumber(monitor_->settings().obstacle_timeout_s) << " s");
  };
  hooks.store_failed = [](const std::string& error) {
    ROS_ERROR_STREAM_THROTTLE(5.0,
                              "ellipse_collision: cannot persist the runtime obstacles: " << error);
  };
  monitor_ = std::make_unique<app::CollisionMonitor>(
      config_.monitor, config_.links, config_.obstacles, config_.limits,
      storeOptions(config_, private_nh_.getNamespace()), std::move(hooks));
  for (const app::StartupNote& note : monitor_->startupNotes()) logStartupNote(note);
  if (monitor_->storeEnabled() && config_.monitor.obstacle_store_period_s > 0.0) {
    store_timer_ = nh_.createWallTimer(ros::WallDuration(config_.monitor.obstacle_store_period_s),
                                       &CollisionNode::onStoreTimer, this);
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
  sources_ = std::make_unique<SourceSubscribers>(nh_, private_nh_, config_, *monitor_, tf_buffer_);
  if (config_.fleet.enabled) {
    fleet_ = std::make_unique<FleetPublisher>(nh_, config_, *monitor_, tf_buffer_);
  }

  // The velocity gate: always advertised (it can be enabled at run time), off by default.
  cmd_vel_pub_ = private_nh_.advertise<geometry_msgs::Twist>("cmd_vel_out", 1);
  gate_state_pub_ = private_nh_.advertise<GateState>("gate_state", 1, /*latch=*/true);
  gate_markers_pub_ =
      private_nh_.advertise<visualization_msgs::MarkerArray>("gate_markers", 1, /*latch=*/true);
  gate_enable_service_ =
      private_nh_.advertiseService("gate/set_enabled", &CollisionNode::onSetGateEnabled, this);
  cmd_vel_sub_ = private_nh_.subscribe("cmd_vel_in", 1, &CollisionNode::onCommand, this,
                                       ros::TransportHints().tcpNoDelay());
  const std::string& odom_topic = monitor_->gate().config().odom_topic;
  if (!odom_topic.empty()) {
    odom_sub_ = nh_.subscribe(odom_topic, 1, &CollisionNode::onOdometry, this,
                              ros::TransportHints().tcpNoDelay());
  }
  // The incident recorder: bags on the writer's thread, finished incidents collected by a timer
  // (an incident's after window ends whether or not commands still come).
  const app::IncidentSettings& incident = config_.monitor.incident;
  if (incident.enabled) {
    incident_writer_ = std::make_unique<IncidentWriter>(
        incident.directory.empty() ? defaultIncidentDirectory() : incident.directory,
        incident.max_files, incident.max_megabytes);
    incident_timer_ =
        private_nh_.createTimer(ros::Duration(0.1), &CollisionNode::onIncidentTimer, this);
  }
  save_incident_service_ =
      private_nh_.advertiseService("save_incident", &CollisionNode::onSaveIncident, this);
  scheduleTimers();
  diagnostics_timer_ =
      private_nh_.createTimer(ros::Duration(1.0), &CollisionNode::onDiagnosticsTimer, this);
  // The servers start from the parameters just read (they read the same keys), so their first
  // call changes nothing.
  check_reconfigure_ =
      std::make_unique<dynamic_reconfigure::Server<CheckParametersConfig>>(private_nh_);
  check_reconfigure_->setCallback([this](CheckParametersConfig& config, std::uint32_t level) {
    onCheckReconfigure(config, level);
  });
  gate_reconfigure_ = std::make_unique<dynamic_reconfigure::Server<GateParametersConfig>>(
      ros::NodeHandle(private_nh_, "gate"));
  gate_reconfigure_->setCallback([this](GateParametersConfig& config, std::uint32_t level) {
    onGateReconfigure(config, level);
  });

  warnIfIdealBase();
  for (const std::string& skipped : config_.urdf_links_skipped) {
    ROS_INFO_STREAM("ellipse_collision: links_from_urdf skipped " << skipped);
  }
  ROS_INFO_STREAM("ellipse_collision: "
                  << config_.links.size() << " links, " << config_.obstacles.size()
                  << " obstacles in '" << config_.monitor.check.fixed_frame << "', "
                  << (config_.monitor.rate_hz > 0.0
                          ? "checking at " + core::formatNumber(config_.monitor.rate_hz) + " Hz"
                          : std::string("checking on service calls only"))
                  << (config_.monitor.check.rules.warning_distance > 0.0
                          ? ", warning within " +
                                core::formatNumber(config_.monitor.check.rules.warning_distance) +
                                " m"
                          : std::string()));
}

void CollisionNode::scheduleTimers() {
  const double rate_hz = monitor_->settings().rate_hz;
  if (rate_hz > 0.0 && check_timer_.isValid()) {
    check_timer_.setPeriod(ros::Duration(1.0 / rate_hz));
    check_timer_.start();
  } else if (rate_hz > 0.0) {
    check_timer_ =
        private_nh_.createTimer(ros::Duration(1.0 / rate_hz), &CollisionNode::onTimer, this);
  } else {
    check_timer_.stop();
  }
  // Checked four times per timeout: the zero goes out at most a quarter timeout late.
  const double timeout_s = monitor_->gate().config().cmd_vel_timeout_s;
  if (timeout_s > 0.0 && gate_watchdog_timer_.isValid()) {
    gate_watchdog_timer_.setPeriod(ros::Duration(timeout_s / 4.0));
    gate_watchdog_timer_.start();
  } else if (timeout_s > 0.0) {
    gate_watchdog_timer_ = private_nh_.createTimer(ros::Duration(timeout_s / 4.0),
                                                   &CollisionNode::onGateWatchdog, this);
  } else {
    gate_watchdog_timer_.stop();
  }
}

void CollisionNode::onCheckReconfigure(CheckParametersConfig& config, std::uint32_t /*level*/) {
  app::TunableSettings tunable = monitor_->tunable();
  const std::optional<app::FieldError> bound = applyCheckParameters(config, &tunable);
  retune(bound, tunable);
  toCheckParameters(monitor_->tunable(), &config);
}

void CollisionNode::onGateReconfigure(GateParametersConfig& config, std::uint32_t /*level*/) {
  app::TunableSettings tunable = monitor_->tunable();
  const std::optional<app::FieldError> bound = applyGateParameters(config, &tunable);
  retune(bound, tunable);
  toGateParameters(monitor_->tunable(), &config);
}

void CollisionNode::retune(const std::optional<app::FieldError>& at_bound,
                           const app::TunableSettings& tunable) {
  const app::TunableSettings before = monitor_->tunable();
  // The settings' own rule first: its words name what is accepted.
  std::optional<app::FieldError> error = app::findInvalidTunable(tunable);
  if (!error) error = at_bound;
  if (!error) error = monitor_->retune(tunable);
  if (error) {
    ROS_ERROR_STREAM("ellipse_collision: reconfigure refused, nothing changed: "
                     << describeConfigError("parameter ~" + error->key, *error)
                     << "; kept: " << app::describeTunable(before));
    return;
  }
  const std::string changes = app::describeTunableChanges(before, monitor_->tunable());
  if (changes.empty()) return;
  scheduleTimers();
  ROS_INFO_STREAM("ellipse_collision: reconfigured: " << changes);
  warnIfIdealBase();
}

void CollisionNode::warnIfIdealBase() const {
  const std::string warning = app::idealBaseWarning(monitor_->gate().config());
  if (!warning.empty()) ROS_WARN_STREAM("ellipse_collision: " << warning);
}

void CollisionNode::onOdometry(const nav_msgs::Odometry::ConstPtr& msg) {
  // The twist of nav_msgs/Odometry is in its child frame: the base's own frame.
  const std::string& robot_frame = monitor_->gate().config().robot_frame;
  if (!msg->child_frame_id.empty() && msg->child_frame_id != robot_frame) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: gate/odom_topic: twist in '"
                                      << msg->child_frame_id << "', not robot_frame '"
                                      << robot_frame << "': ignored");
    return;
  }
  const app::VelocityCommand twist = fromMsg(msg->twist.twist);
  if (!twist.linear.allFinite() || !twist.angular.allFinite()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "ellipse_collision: gate/odom_topic: non-finite twist ignored");
    return;
  }
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  monitor_->gateOdometry(twist, stamp.toSec());
}

app::TransformLookup CollisionNode::lookup(const ros::Time& stamp,
                                           const ros::Duration& timeout) const {
  return tfLookup(tf_buffer_, config_.monitor.check.fixed_frame, stamp, timeout);
}

app::TransformAtLookup CollisionNode::lookupAt() const {
  return [this](const std::string& frame, double time_s) {
    return tfLookup(tf_buffer_, config_.monitor.check.fixed_frame, ros::Time(time_s),
                    ros::Duration(0))(frame);
  };
}

void CollisionNode::onStoreTimer(const ros::WallTimerEvent& /*event*/) {
  monitor_->writeStoreIfBehind();
}

void CollisionNode::logPredictionNotes(const app::CheckOutcome& outcome) const {
  if (outcome.prediction_notes.empty()) return;
  ROS_WARN_STREAM_THROTTLE(
      5.0, "ellipse_collision: prediction: " << app::joinText(outcome.prediction_notes, "; "));
}

void CollisionNode::publishIfUpdated() {
  if (!monitor_->stateUpdated()) return;
  const app::CheckOutcome& checked = monitor_->state().outcome;
  if (!checked.skipped.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0,
                             "ellipse_collision: skipped " << app::joinText(checked.skipped, "; "));
  }
  logPredictionNotes(checked);
  publishState(monitor_->statePublishing());
  publishMarkers();
}

namespace {

/// Everything of the state but its stamp: the message's own operator==, so that a field added to
/// CollisionState later is compared too. `a`'s stamp is borrowed for the comparison and put back.
bool sameContentButStamp(CollisionState& a, const CollisionState& b) {
  const ros::Time stamp = a.header.stamp;
  a.header.stamp = b.header.stamp;
  const bool same = a == b;
  a.header.stamp = stamp;
  return same;
}

}  // namespace

void CollisionNode::publishState(app::StatePublishing publishing) {
  const app::MonitorState& state = monitor_->state();
  CollisionState msg;
  msg.header.stamp = ros::Time(state.stamp_s);
  msg.header.frame_id = config_.monitor.check.fixed_frame;
  msg.collisions = toMsg(state.outcome.collisions);
  msg.in_collision = !msg.collisions.empty();
  msg.unavailable_frames = state.outcome.unavailable_frames;
  msg.warnings = toMsg(state.outcome.warnings);
  msg.stale_frames = state.outcome.stale_frames;
  msg.complete = state.outcome.complete;
  msg.predicted = toMsg(state.outcome.predicted);
  if (publishing == app::StatePublishing::OnChange && state_published_ &&
      sameContentButStamp(msg, last_state_msg_)) {
    return;
  }
  collisions_pub_.publish(msg);
  last_state_msg_ = std::move(msg);
  state_published_ = true;
}

void CollisionNode::publishMarkers() {
  const app::MonitorState& state = monitor_->state();
  // Nobody listening: skip the work. onMarkerSubscriber() publishes for the next subscriber.
  if (!state.valid || markers_pub_.getNumSubscribers() == 0) {
    last_markers_time_ = ros::WallTime();  // no sweep is owed for the time nobody listened
    return;
  }
  std::set<std::string> predicted;
  for (const core::PredictedContact& p : state.outcome.predicted) {
    predicted.insert({p.name_a, p.name_b});
  }
  // Only what changed since the last array: an unchanged scene publishes nothing.
  visualization_msgs::MarkerArray changes =
      markers_.update(state.outcome.placed, state.outcome.collisions, state.outcome.warnings,
                      config_.monitor.check.fixed_frame, ros::Time(state.stamp_s), predicted);
  // Plus a slice of the refresh sweep, by wall time: it heals what a network lost, whatever the
  // ROS clock does.
  const ros::WallTime now = ros::WallTime::now();
  if (config_.marker_refresh_period_s > 0.0 && !last_markers_time_.isZero()) {
    markers_.appendRefresh(
        changes, std::min(kMaxRefreshShare,
                          (now - last_markers_time_).toSec() / config_.marker_refresh_period_s));
  }
  last_markers_time_ = now;
  if (!changes.markers.empty()) markers_pub_.publish(changes);
}

void CollisionNode::onTimer(const ros::TimerEvent& /*event*/) {
  // No waiting for transforms: a periodic check must not stall on a missing frame.
  const app::CheckOutcome& outcome = monitor_->periodicCheck(
      ros::Time::now().toSec(), lookup(ros::Time(0), ros::Duration(0)), lookupAt());
  if (!outcome.error.empty()) {
    // Never published as "clear": the topics keep the last good state.
    ROS_ERROR_STREAM_THROTTLE(5.0, "ellipse_collision: check failed: " << outcome.error);
  }
  publishIfUpdated();
}

void CollisionNode::onMarkerSubscriber(const ros::SingleSubscriberPublisher& subscriber) {
  // The arrays only carry changes, so the latched one is not the whole view: bring everyone up to
  // date (checks were skipped while nobody listened), then send the newcomer alone everything.
  publishMarkers();
  if (monitor_->state().valid) subscriber.publish(markers_.fullArray());
}

std::optional<diagnostic_msgs::DiagnosticStatus> CollisionNode::fleetStatus(double now_s) const {
  if (!fleet_ && !sources_->hasRobots()) return std::nullopt;
  diagnostic_msgs::DiagnosticStatus status;
  status.name = private_nh_.getNamespace() + ": fleet";
  status.hardware_id = config_.fleet.frame;
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  if (fleet_) {
    FleetPublisher::Status published = fleet_->status();
    if (published.failing) status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = published.message;
    for (const auto& [key, value] : published.values) status.values.push_back(keyValue(key, value));
  } else {
    status.message = "not publishing (fleet/enabled: false)";
  }
  for (const auto& [key, value] : sources_->robotsValues(now_s)) {
    status.values.push_back(keyValue(key, value));
  }
  return status;
}

bool CollisionNode::onCheckCollisions(CheckCollisions::Request& request,
                                      CheckCollisions::Response& response) {
  response.success = false;
  const app::CheckOutcome& outcome = monitor_->serviceCheck(
      fromMsg(request), request.stamp.toSec(), ros::Time::now().toSec(),
      lookup(request.stamp, ros::Duration(config_.tf_timeout_s)), lookupAt());
  if (!outcome.error.empty()) {
    ROS_ERROR_STREAM_COND(outcome.error_kind == app::ErrorKind::Internal,
                          "ellipse_collision: " << outcome.error);
    response.message = outcome.error;
    return true;
  }
  if (monitor_->stateUpdated()) {
    publishIfUpdated();
  } else {
    logPredictionNotes(outcome);
  }
  toMsg(outcome, response);
  return true;
}

bool CollisionNode::onAddObstacles(AddObstacles::Request& request,
                                   AddObstacles::Response& response) {
  std::vector<app::EllipseSpec> specs;
  for (const Ellipse& msg : request.obstacles) specs.push_back(fromMsg(msg));
  const app::ChangeAnswer answer =
      monitor_->addObstacles(specs, lookup(ros::Time(0), ros::Duration(config_.tf_timeout_s)));
  response.success = answer.success();
  response.message = answer.message;
  return true;
}

bool CollisionNode::onRemoveObstacles(RemoveObstacles::Request& request,
                                      RemoveObstacles::Response& response) {
  const app::ChangeAnswer answer = monitor_->removeObstacles(request.names);
  response.success = answer.success();
  response.message = answer.message;
  return true;
}

bool CollisionNode::onCheckPath(CheckPath::Request& request, CheckPath::Response& response) {
  const ros::Duration timeout(config_.tf_timeout_s);
  const app::PathCheckOutcome outcome = monitor_->checkPath(
      fromMsg(request), ros::Time::now().toSec(), [this, &timeout](const std::string& target) {
        return tfLookup(tf_buffer_, target, ros::Time(0), timeout);
      });
  response.success = false;
  if (!outcome.error.empty()) {
    response.message = outcome.error;
    return true;
  }
  toMsg(outcome, response);
  return true;
}

void CollisionNode::onCommand(const geometry_msgs::Twist::ConstPtr& msg) {
  const ros::Time now = ros::Time::now();
  // No waiting for transforms: a command is gated on what tf has now.
  const app::GateDecision decision = monitor_->gateCommand(
      fromMsg(*msg), now.toSec(), lookup(ros::Time(0), ros::Duration(0)), lookupAt());
  publishGate(decision, now);
  publishIfUpdated();
}

void CollisionNode::onGateWatchdog(const ros::TimerEvent& /*event*/) {
  const ros::Time now = ros::Time::now();
  if (const auto decision = monitor_->gateWatchdog(now.toSec())) publishGate(*decision, now);
}

bool CollisionNode::onSetGateEnabled(std_srvs::SetBool::Request& request,
                                     std_srvs::SetBool::Response& response) {
  monitor_->setGateEnabled(request.data);
  response.success = true;
  response.message = request.data ? "gate enabled" : "gate disabled: commands pass unchanged";
  ROS_INFO_STREAM("ellipse_collision: " << response.message);
  return true;
}

void CollisionNode::publishGate(const app::GateDecision& decision, const ros::Time& stamp) {
  // The command first: what the robot waits for.
  cmd_vel_pub_.publish(toMsg(decision.output));
  GateState state = toMsg(decision);
  state.header.stamp = stamp;
  state.header.frame_id = config_.monitor.check.fixed_frame;
  gate_state_pub_.publish(state);
  if (gate_markers_pub_.getNumSubscribers() > 0) {
    gate_markers_pub_.publish(
        gate_markers_.update(decision, config_.monitor.check.fixed_frame, stamp));
  }
  if (app::stops(decision.action)) {
    ROS_WARN_STREAM_THROTTLE(2.0,
                             "ellipse_collision: gate " << state.action << ": " << decision.reason);
  }
}

std::string CollisionNode::writeIncidents(const ros::Time& now) {
  std::string path;
  for (app::Incident& incident : monitor_->takeIncidents(now.toSec())) {
    std::string settings =
        incidentSettingsYaml(incident, monitor_->gate().config(), monitor_->settings().check);
    path = incident_writer_->write(std::move(incident), std::move(settings),
                                   config_.monitor.check.fixed_frame);
  }
  return path;
}

void CollisionNode::onIncidentTimer(const ros::TimerEvent& /*event*/) {
  writeIncidents(ros::Time::now());
}

bool CollisionNode::onSaveIncident(std_srvs::Trigger::Request& /*request*/,
                                   std_srvs::Trigger::Response& response) {
  const ros::Time now = ros::Time::now();
  if (!incident_writer_ || !monitor_->requestIncident(now.toSec())) {
    response.success = false;
    response.message = "the incident recorder is off (incident/enabled: false)";
    return true;
  }
  response.success = true;
  response.message = "writing " + writeIncidents(now);
  return true;
}

diagnostic_msgs::DiagnosticStatus CollisionNode::incidentStatus() const {
  const IncidentWriter::Status written = incident_writer_->status();
  const app::IncidentRecorder& recorder = monitor_->incidents();
  diagnostic_msgs::DiagnosticStatus status;
  status.name = private_nh_.getNamespace() + ": incident recorder";
  status.hardware_id = config_.monitor.check.fixed_frame;
  if (!written.last_error.empty()) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    status.message = written.last_error + " (check the disk, or set incident/directory)";
  } else {
    status.level = diagnostic_msgs::DiagnosticStatus::OK;
    status.message = written.written == 0 ? "recording, no incident yet"
                                          : "recording, last incident " + written.last_file;
  }
  status.values.push_back(keyValue("directory", incident_writer_->directory()));
  status.values.push_back(keyValue("written", std::to_string(written.written)));
  status.values.push_back(keyValue("failed", std::to_string(written.failed)));
  status.values.push_back(
      keyValue("held back by min_interval", std::to_string(recorder.suppressed())));
  status.values.push_back(
      keyValue("buffered decisions", std::to_string(recorder.bufferedDecisions())));
  status.values.push_back(
      keyValue("buffered obstacles", std::to_string(recorder.storedObstacles())));
  return status;
}

void CollisionNode::onDiagnosticsTimer(const ros::TimerEvent& /*event*/) {
  const app::CollisionMonitor::Health report = monitor_->health(ros::Time::now().toSec());
  diagnostic_msgs::DiagnosticStatus status;
  status.name = private_nh_.getNamespace() + ": collision check";
  status.hardware_id = config_.monitor.check.fixed_frame;
  status.level = report.health.level == app::CheckHealth::Level::Error
                     ? diagnostic_msgs::DiagnosticStatus::ERROR
                 : report.health.level == app::CheckHealth::Level::Warn
                     ? diagnostic_msgs::DiagnosticStatus::WARN
                     : diagnostic_msgs::DiagnosticStatus::OK;
  status.message = report.health.message;
  for (const auto& [key, value] : report.values) status.values.push_back(keyValue(key, value));
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(status);
  if (auto fleet = fleetStatus(ros::Time::now().toSec())) array.status.push_back(std::move(*fleet));
  if (incident_writer_) array.status.push_back(incidentStatus());
  diagnostics_pub_.publish(array);
}

}  // namespace ellipse_collision
