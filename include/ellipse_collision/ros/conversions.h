#pragma once

#include <geometry_msgs/Twist.h>
#include <sensor_msgs/Range.h>

#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/path_request.h"
#include "ellipse_collision/app/range_obstacle.h"
#include "ellipse_collision/app/velocity_gate.h"
#include "ellipse_collision/core/contact_prediction.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/ros/messages.h"

namespace ellipse_collision {

/// Field by field; no validation (see app::findInvalidPaddedField()). A message whose z, roll,
/// pitch and radius_z are all 0 (the defaults) is a planar spec; any other has the ellipsoid part,
/// a bad one (radius_z <= 0, a tilt without radius_z) for the validation to refuse. toMsg()
/// writes a planar spec's four as 0, so fromMsg(toMsg(spec)) == spec for every valid spec.
app::EllipseSpec fromMsg(const Ellipse& msg);
Ellipse toMsg(const app::EllipseSpec& spec);

/// Specs of an EllipseArray; an ellipse with an empty frame_id takes header.frame_id.
std::vector<app::EllipseSpec> fromMsg(const EllipseArray& msg);

core::CollidingPair fromMsg(const CollisionPair& msg);
CollisionPair toMsg(const core::CollidingPair& pair);
std::vector<CollisionPair> toMsg(const std::vector<core::CollidingPair>& pairs);

/// Points in the fixed frame's plane; z is 0 in messages and ignored when read.
core::NearPair fromMsg(const ClearancePair& msg);
ClearancePair toMsg(const core::NearPair& pair);
std::vector<ClearancePair> toMsg(const std::vector<core::NearPair>& pairs);

/// The request's fields as the application layer takes them (stamp is the ROS layer's: it picks
/// the transforms); no validation (see app::validateCheckRequest()).
app::CheckRequest fromMsg(const CheckCollisions::Request& request);

/// A successful check's answer: success, the notes (skipped ellipses, why min_distance_of was not
/// measured) as the message, the pairs, unavailable frames and the nearest partner.
void toMsg(const app::CheckOutcome& outcome, CheckCollisions::Response& response);

/// The path request's fields as the application layer takes them (poses' stamps in seconds); no
/// validation (see app::validatePathRequest()). Empty frames are left empty.
app::PathCheckRequest fromMsg(const CheckPath::Request& request);

/// A successful path check's answer: success, the skipped ellipses as the message, the first
/// contact, the minimum clearance and the unavailable frames.
void toMsg(const app::PathCheckOutcome& outcome, CheckPath::Response& response);

std::vector<PredictedContact> toMsg(const std::vector<core::PredictedContact>& predicted);

/// Component by component; no validation (see app::findInvalidCommand()).
app::VelocityCommand fromMsg(const geometry_msgs::Twist& msg);

/// A ranger's reading as it is (radiation_type is not used: sonar and IR alike).
app::RangeReading fromMsg(const sensor_msgs::Range& msg);
geometry_msgs::Twist toMsg(const app::VelocityCommand& command);

/// The gate's decision as ~gate_state shows it (header left to the caller).
GateState toMsg(const app::GateDecision& decision);
/// The inverse of toMsg(GateDecision) (a time_to_contact without a predicted contact reads as
/// written, 0); false, and `decision` unchanged, when `msg.action` names no gate action.
bool fromMsg(const GateState& msg, app::GateDecision* decision);

}  // namespace ellipse_collision
