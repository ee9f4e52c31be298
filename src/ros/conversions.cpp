#include "ellipse_collision/ros/conversions.h"

#include "ellipse_collision/app/incident_recorder.h"

namespace ellipse_collision {

app::EllipseSpec fromMsg(const Ellipse& msg) {
  app::EllipseSpec spec;
  spec.name = msg.name;
  spec.frame_id = msg.frame_id;
  spec.x = msg.x;
  spec.y = msg.y;
  spec.angle = msg.angle;
  spec.radius_x = msg.radius_x;
  spec.radius_y = msg.radius_y;
  spec.padding = msg.padding;
  spec.vx = msg.vx;
  spec.vy = msg.vy;
  spec.angular_velocity = msg.angular_velocity;
  if (msg.z != 0.0 || msg.roll != 0.0 || msg.pitch != 0.0 || msg.radius_z != 0.0) {
    spec.ellipsoid = app::EllipsoidPart{msg.z, msg.roll, msg.pitch, msg.radius_z};
  }
  return spec;
}

Ellipse toMsg(const app::EllipseSpec& spec) {
  Ellipse msg;
  msg.name = spec.name;
  msg.frame_id = spec.frame_id;
  msg.x = spec.x;
  msg.y = spec.y;
  msg.angle = spec.angle;
  msg.radius_x = spec.radius_x;
  msg.radius_y = spec.radius_y;
  msg.padding = spec.padding;
  msg.vx = spec.vx;
  msg.vy = spec.vy;
  msg.angular_velocity = spec.angular_velocity;
  if (spec.ellipsoid) {
    msg.z = spec.ellipsoid->z;
    msg.roll = spec.ellipsoid->roll;
    msg.pitch = spec.ellipsoid->pitch;
    msg.radius_z = spec.ellipsoid->radius_z;
  }
  return msg;
}

std::vector<app::EllipseSpec> fromMsg(const EllipseArray& msg) {
  std::vector<app::EllipseSpec> specs;
  specs.reserve(msg.ellipses.size());
  for (const Ellipse& ellipse : msg.ellipses) {
    specs.push_back(fromMsg(ellipse));
    if (specs.back().frame_id.empty()) specs.back().frame_id = msg.header.frame_id;
  }
  return specs;
}

core::CollidingPair fromMsg(const CollisionPair& msg) {
  return core::CollidingPair{msg.name_a, msg.name_b, msg.contact_scale};
}

CollisionPair toMsg(const core::CollidingPair& pair) {
  CollisionPair msg;
  msg.name_a = pair.name_a;
  msg.name_b = pair.name_b;
  msg.contact_scale = pair.contact_scale;
  return msg;
}

std::vector<CollisionPair> toMsg(const std::vector<core::CollidingPair>& pairs) {
  std::vector<CollisionPair> msgs;
  msgs.reserve(pairs.size());
  for (const core::CollidingPair& pair : pairs) msgs.push_back(toMsg(pair));
  return msgs;
}

core::NearPair fromMsg(const ClearancePair& msg) {
  return core::NearPair{msg.name_a,
                  msg.name_b,
                  msg.distance,
                  {msg.point_a.x, msg.point_a.y},
                  {msg.point_b.x, msg.point_b.y}};
}

ClearancePair toMsg(const core::NearPair& pair) {
  ClearancePair msg;
  msg.name_a = pair.name_a;
  msg.name_b = pair.name_b;
  msg.distance = pair.distance;
  msg.point_a.x = pair.point_a.x();
  msg.point_a.y = pair.point_a.y();
  msg.point_a.z = 0.0;
  msg.point_b.x = pair.point_b.x();
  msg.point_b.y = pair.point_b.y();
  msg.point_b.z = 0.0;
  return msg;
}

std::vector<ClearancePair> toMsg(const std::vector<core::NearPair>& pairs) {
  std::vector<ClearancePair> msgs;
  msgs.reserve(pairs.size());
  for (const core::NearPair& pair : pairs) msgs.push_back(toMsg(pair));
  return msgs;
}

app::CheckRequest fromMsg(const CheckCollisions::Request& request) {
  app::CheckRequest check;
  check.names = request.names;
  for (const Ellipse& ellipse : request.query) check.query.push_back(fromMsg(ellipse));
  check.min_distance_of = request.min_distance_of;
  return check;
}

void toMsg(const app::CheckOutcome& outcome, CheckCollisions::Response& response) {
  response.success = true;
  std::vector<std::string> notes;
  if (!outcome.skipped.empty()) notes.push_back("skipped " + app::joinText(outcome.skipped, "; "));
  if (!outcome.nearest_problem.empty()) notes.push_back(outcome.nearest_problem);
  notes.insert(notes.end(), outcome.silent_sources.begin(), outcome.silent_sources.end());
  response.message = app::joinText(notes, "; ");
  response.collisions = toMsg(outcome.collisions);
  response.in_collision = !response.collisions.empty();
  response.unavailable_frames = outcome.unavailable_frames;
  response.warnings = toMsg(outcome.warnings);
  response.has_min_distance = outcome.nearest.has_value();
  if (outcome.nearest) response.nearest = toMsg(*outcome.nearest);
  response.stale_frames = outcome.stale_frames;
  response.complete = outcome.complete;
  response.predicted = toMsg(outcome.predicted);
}

app::PathCheckRequest fromMsg(const CheckPath::Request& request) {
  app::PathCheckRequest path;
  path.path_frame = request.path.header.frame_id;
  path.moving_frame = request.moving_frame;
  path.poses.reserve(request.path.poses.size());
  for (const geometry_msgs::PoseStamped& pose : request.path.poses) {
    app::PathPoseInput in;
    in.frame_id = pose.header.frame_id;
    in.stamp_s = pose.header.stamp.toSec();
    in.x = pose.pose.position.x;
    in.y = pose.pose.position.y;
    in.z = pose.pose.position.z;
    in.qx = pose.pose.orientation.x;
    in.qy = pose.pose.orientation.y;
    in.qz = pose.pose.orientation.z;
    in.qw = pose.pose.orientation.w;
    path.poses.push_back(in);
  }
  return path;
}

void toMsg(const app::PathCheckOutcome& outcome, CheckPath::Response& response) {
  const core::PathCheckResult& r = outcome.result;
  response.success = true;
  std::vector<std::string> notes;
  if (!outcome.skipped.empty()) notes.push_back("skipped " + app::joinText(outcome.skipped, "; "));
  notes.insert(notes.end(), outcome.silent_sources.begin(), outcome.silent_sources.end());
  response.message = app::joinText(notes, "; ");
  response.complete = outcome.complete();
  response.collision_free = r.collision_free;
  response.segment = static_cast<std::uint32_t>(r.segment);
  response.fraction = r.fraction;
  response.time = r.time;
  response.name_a = r.link;
  response.name_b = r.obstacle;
  response.min_clearance = r.has_clearance ? r.min_clearance : 0.0;
  response.min_clearance_pose = static_cast<std::uint32_t>(r.min_clearance_pose);
  response.clearance_name_a = r.clearance_link;
  response.clearance_name_b = r.clearance_obstacle;
  response.unavailable_frames = outcome.unavailable_frames;
}

std::vector<PredictedContact> toMsg(const std::vector<core::PredictedContact>& predicted) {
  std::vector<PredictedContact> msgs;
  msgs.reserve(predicted.size());
  for (const core::PredictedContact& p : predicted) {
    PredictedContact msg;
    msg.name_a = p.name_a;
    msg.name_b = p.name_b;
    msg.time = p.time;
    msgs.push_back(msg);
  }
  return msgs;
}

app::VelocityCommand fromMsg(const geometry_msgs::Twist& msg) {
  app::VelocityCommand command;
  command.linear << msg.linear.x, msg.linear.y, msg.linear.z;
  command.angular << msg.angular.x, msg.angular.y, msg.angular.z;
  return command;
}

app::RangeReading fromMsg(const sensor_msgs::Range& msg) {
  app::RangeReading reading;
  reading.range = msg.range;
  reading.min_range = msg.min_range;
  reading.max_range = msg.max_range;
  reading.field_of_view = msg.field_of_view;
  reading.frame_id = msg.header.frame_id;
  return reading;
}

geometry_msgs::Twist toMsg(const app::VelocityCommand& command) {
  geometry_msgs::Twist msg;
  msg.linear.x = command.linear.x();
  msg.linear.y = command.linear.y();
  msg.linear.z = command.linear.z();
  msg.angular.x = command.angular.x();
  msg.angular.y = command.angular.y();
  msg.angular.z = command.angular.z();
  return msg;
}

GateState toMsg(const app::GateDecision& decision) {
  GateState msg;
  msg.action = app::toString(decision.action);
  msg.scale = decision.scale;
  msg.contact_predicted = decision.contact_predicted;
  msg.time_to_contact = decision.contact_predicted ? decision.time_to_contact_s : 0.0;
  msg.link = decision.link;
  msg.obstacle = decision.obstacle;
  msg.contact_point.x = decision.contact_point.x();
  msg.contact_point.y = decision.contact_point.y();
  msg.input = toMsg(decision.input);
  msg.output = toMsg(decision.output);
  msg.braking_distance = decision.braking_distance_m;
  msg.free_distance = decision.free_distance_m;
  msg.unavoidable = decision.unavoidable;
  msg.impact_speed = decision.impact_speed;
  msg.reason = decision.reason;
  return msg;
}

bool fromMsg(const GateState& msg, app::GateDecision* decision) {
  std::vector<core::GateAction> action;
  if (app::parseIncidentActions({msg.action}, &action)) return false;
  decision->action = action.front();
  decision->scale = msg.scale;
  decision->input = fromMsg(msg.input);
  decision->output = fromMsg(msg.output);
  decision->contact_predicted = msg.contact_predicted;
  decision->time_to_contact_s = msg.time_to_contact;
  decision->link = msg.link;
  decision->obstacle = msg.obstacle;
  decision->contact_point = Eigen::Vector2d(msg.contact_point.x, msg.contact_point.y);
  decision->braking_distance_m = msg.braking_distance;
  decision->free_distance_m = msg.free_distance;
  decision->unavoidable = msg.unavoidable;
  decision->impact_speed = msg.impact_speed;
  decision->reason = msg.reason;
  return true;
}

}  // namespace ellipse_collision
