#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/ros/ellipse_spec.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

/// findInvalidField(), then the radii the core is given: radius_x and radius_y grown by
/// spec.padding + global_padding (as paddedEllipse() does) must lie within [kMinRadius,
/// kMaxRadius]. A violation names the radius key, with its own value as `actual`. The node checks
/// every configured entry and every request or topic ellipse with this before using it.
std::optional<FieldError> findInvalidPaddedField(const EllipseSpec& spec, double global_padding,
                                                 const std::string& frame_key = "frame_id");

/// Field by field; no validation (see findInvalidPaddedField()).
EllipseSpec fromMsg(const Ellipse& msg);
Ellipse toMsg(const EllipseSpec& spec);

/// Specs of an EllipseArray; an ellipse with an empty frame_id takes header.frame_id.
std::vector<EllipseSpec> fromMsg(const EllipseArray& msg);

core::CollidingPair fromMsg(const CollisionPair& msg);
CollisionPair toMsg(const core::CollidingPair& pair);
std::vector<CollisionPair> toMsg(const std::vector<core::CollidingPair>& pairs);

/// Points in the fixed frame's plane; z is 0 in messages and ignored when read.
core::NearPair fromMsg(const ClearancePair& msg);
ClearancePair toMsg(const core::NearPair& pair);
std::vector<ClearancePair> toMsg(const std::vector<core::NearPair>& pairs);

}  // namespace ellipse_collision
