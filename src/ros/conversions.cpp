#include "ellipse_collision/ros/conversions.h"

namespace ellipse_collision {

std::optional<FieldError> findInvalidPaddedField(const EllipseSpec& spec, double global_padding,
                                                 const std::string& frame_key) {
  if (auto invalid = findInvalidField(spec, frame_key)) return invalid;
  // The same sums as paddedEllipse(), so that what passes here passes the core's invalidReason().
  const core::Ellipse padded = paddedEllipse(spec, global_padding);
  const struct {
    const char* key;
    double value;
    double padded;
  } radii[] = {{"radius_x", spec.radius_x, padded.radius_x},
               {"radius_y", spec.radius_y, padded.radius_y}};
  for (const auto& radius : radii) {
    if (!(radius.padded >= core::kMinRadius && radius.padded <= core::kMaxRadius)) {
      return FieldError{radius.key,
                        "a number whose padded radius (" + std::string(radius.key) + " + padding " +
                            formatNumber(spec.padding) + " + global padding " +
                            formatNumber(global_padding) + " = " + formatNumber(radius.padded) +
                            ") lies within [" + formatNumber(core::kMinRadius) + ", " +
                            formatNumber(core::kMaxRadius) + "]",
                        formatNumber(radius.value)};
    }
  }
  return std::nullopt;
}

EllipseSpec fromMsg(const Ellipse& msg) {
  EllipseSpec spec;
  spec.name = msg.name;
  spec.frame_id = msg.frame_id;
  spec.x = msg.x;
  spec.y = msg.y;
  spec.angle = msg.angle;
  spec.radius_x = msg.radius_x;
  spec.radius_y = msg.radius_y;
  spec.padding = msg.padding;
  return spec;
}

Ellipse toMsg(const EllipseSpec& spec) {
  Ellipse msg;
  msg.name = spec.name;
  msg.frame_id = spec.frame_id;
  msg.x = spec.x;
  msg.y = spec.y;
  msg.angle = spec.angle;
  msg.radius_x = spec.radius_x;
  msg.radius_y = spec.radius_y;
  msg.padding = spec.padding;
  return msg;
}

std::vector<EllipseSpec> fromMsg(const EllipseArray& msg) {
  std::vector<EllipseSpec> specs;
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

}  // namespace ellipse_collision
