// Fuzz target: the ROS layer's message conversion and the application layer's request handling,
// without a master: a sequence of ~add_obstacles, ~remove_obstacles, ~obstacles and
// ~check_collisions requests built from the input goes through the same functions the node calls
// (fromMsg(), app::validateAttached(), app::EllipseRegistry, app::validateCheckRequest(),
// app::runCheck(), toMsg()), with every frame at the identity except "arm_link", which has none.
//
// Invariants:
//  - fromMsg()/toMsg() keep every field bit for bit (but a planar ellipse's z, roll, pitch and
//    radius_z, zeros of either sign, which come back +0); a message with any of those four not 0
//    is an ellipsoid; an EllipseArray entry without a frame takes the header's frame and no other
//    does;
//  - findInvalidPaddedField() refuses exactly what the documented rule refuses (ellipse_spec.h: finite,
//    radii > 0, padding >= 0, the core's ranges, an ellipsoid's depth fields and radius_z = 0 only
//    without a tilt), and the request error names the entry, the key and the value;
//  - a spec it accepts reaches the core valid: paddedEllipse() (and paddedEllipsoid() of an
//    ellipsoid) passes invalidReason(), so that an accepted obstacle or query is really checked
//    (invalid input never gets to the arithmetic);
//  - every registry change is all-or-nothing, links are never replaced or removed, names stay
//    unique, and what a successful call says it did is what the registry holds afterwards.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "fuzz_input.h"

namespace ellipse_collision::fuzz {
namespace {

const char* const kNames[] = {"", "body", "arm", "crate", "box", "q", "box/2", "a b", "\xff\xfe"};
const char* const kFrames[] = {"", "base_link", "odom", "/odom", "arm_link", " ", "a\nb"};
constexpr int kMaxEntries = 6;

template <std::size_t N>
std::string pick(FuzzInput& input, const char* const (&table)[N]) {
  const int index = input.integer(0, N);  // N: a made-up string instead
  if (index < static_cast<int>(N)) return table[index];
  std::string text(static_cast<std::size_t>(input.integer(0, 12)), 'x');
  for (char& c : text) c = static_cast<char>(input.byte());
  return text;
}

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

bool sameSpec(const app::EllipseSpec& a, const app::EllipseSpec& b) {
  const bool same_part =
      a.ellipsoid.has_value() == b.ellipsoid.has_value() &&
      (!a.ellipsoid ||
       (sameBits(a.ellipsoid->z, b.ellipsoid->z) && sameBits(a.ellipsoid->roll, b.ellipsoid->roll) &&
        sameBits(a.ellipsoid->pitch, b.ellipsoid->pitch) &&
        sameBits(a.ellipsoid->radius_z, b.ellipsoid->radius_z)));
  return a.name == b.name && a.frame_id == b.frame_id && sameBits(a.x, b.x) && sameBits(a.y, b.y) &&
         sameBits(a.angle, b.angle) && sameBits(a.radius_x, b.radius_x) &&
         sameBits(a.radius_y, b.radius_y) && sameBits(a.padding, b.padding) && same_part;
}

/// Whether `spec` is stored under its name, from `source`, exactly as given.
bool storedAsGiven(const app::EllipseRegistry& registry, const app::EllipseSpec& spec,
                   app::EllipseSource source) {
  const auto found = registry.entries().find(spec.name);
  return found != registry.entries().end() && found->second.source == source &&
         sameSpec(found->second.spec, spec);
}

bool sameMsg(const Ellipse& a, const Ellipse& b) {
  // A planar ellipse's depth fields: all zero, of either sign.
  const auto same_depth = [](double x, double y) { return sameBits(x, y) || (x == 0.0 && y == 0.0); };
  return a.name == b.name && a.frame_id == b.frame_id && sameBits(a.x, b.x) && sameBits(a.y, b.y) &&
         sameBits(a.angle, b.angle) && sameBits(a.radius_x, b.radius_x) &&
         sameBits(a.radius_y, b.radius_y) && sameBits(a.padding, b.padding) &&
         same_depth(a.z, b.z) && same_depth(a.roll, b.roll) && same_depth(a.pitch, b.pitch) &&
         same_depth(a.radius_z, b.radius_z);
}

Ellipse readMsg(FuzzInput& input) {
  Ellipse msg;
  msg.name = pick(input, kNames);
  msg.frame_id = pick(input, kFrames);
  msg.x = input.number();
  msg.y = input.number();
  msg.angle = input.number();
  msg.radius_x = input.number();
  msg.radius_y = input.number();
  msg.padding = input.flag() ? 0.0 : input.number();
  // Half planar (the four left at 0), half with each of the four a number or 0.
  if (input.flag()) {
    for (double* depth : {&msg.z, &msg.roll, &msg.pitch, &msg.radius_z}) {
      *depth = input.flag() ? 0.0 : input.number();
    }
  }
  return msg;
}

/// The rule of ellipse_spec.h and conversions.h restated: which key findInvalidPaddedField() must
/// name, or "". The padded sums are formed in the same order as paddedEllipse().
std::string expectedInvalidKey(const app::EllipseSpec& s, double global_padding) {
  const auto coordinate_bad = [](double v) {
    return !std::isfinite(v) || std::fabs(v) > core::kMaxCoordinate;
  };
  const auto radius_bad = [](double v) {
    return !(std::isfinite(v) && v > 0.0) || v < core::kMinRadius || v > core::kMaxRadius;
  };
  if (s.name.empty()) return "name";
  if (s.frame_id.empty() || s.frame_id.front() == '/') return "frame_id";
  if (coordinate_bad(s.x)) return "x";
  if (coordinate_bad(s.y)) return "y";
  if (!std::isfinite(s.angle)) return "angle";
  if (radius_bad(s.radius_x)) return "radius_x";
  if (radius_bad(s.radius_y)) return "radius_y";
  if (s.ellipsoid) {
    const app::EllipsoidPart& d = *s.ellipsoid;
    if (coordinate_bad(d.z)) return "z";
    if (!std::isfinite(d.roll)) return "roll";
    if (!std::isfinite(d.pitch)) return "pitch";
    if (d.radius_z == 0.0 && d.z != 0.0) return "z";
    if (d.radius_z == 0.0 && d.roll != 0.0) return "roll";
    if (d.radius_z == 0.0 && d.pitch != 0.0) return "pitch";
    if (radius_bad(d.radius_z)) return "radius_z";
  }
  if (!(std::isfinite(s.padding) && s.padding >= 0.0) || s.padding > core::kMaxRadius) return "padding";
  const double padded_x = s.radius_x + s.padding + global_padding;
  const double padded_y = s.radius_y + s.padding + global_padding;
  if (!(padded_x >= core::kMinRadius && padded_x <= core::kMaxRadius)) return "radius_x";
  if (!(padded_y >= core::kMinRadius && padded_y <= core::kMaxRadius)) return "radius_y";
  if (s.ellipsoid) {
    const double padded_z = s.ellipsoid->radius_z + s.padding + global_padding;
    if (!(padded_z >= core::kMinRadius && padded_z <= core::kMaxRadius)) return "radius_z";
  }
  return "";
}

/// Checks the field rules of every entry against the documented rule; returns the first entry's
/// rendered error, "" when all are accepted (the real decision is the application layer's, which
/// must agree).
std::string validate(const std::vector<Ellipse>& msgs, const std::vector<app::EllipseSpec>& specs,
                     const std::string& field, double global_padding) {
  for (std::size_t i = 0; i < specs.size(); ++i) {
    FUZZ_REQUIRE(sameSpec(specs[i], fromMsg(msgs[i])) && sameMsg(toMsg(specs[i]), msgs[i]),
                 "msg -> spec -> msg changed a field of " + field + "[" + std::to_string(i) + "]");

    const auto invalid = app::findInvalidPaddedField(specs[i], global_padding);
    const std::string expected_key = expectedInvalidKey(specs[i], global_padding);
    FUZZ_REQUIRE((invalid ? invalid->key : "") == expected_key,
                 "findInvalidPaddedField named '" + (invalid ? invalid->key : std::string()) +
                     "', the documented rule '" + expected_key + "' for " + field + "[" +
                     std::to_string(i) + "]");
    if (invalid) {
      const std::string where = field + "[" + std::to_string(i) + "]";
      const std::string message = app::describeFieldError(where, *invalid);
      FUZZ_REQUIRE(message.rfind(where + "." + invalid->key + " = ", 0) == 0 &&
                       message.find(": expected ") != std::string::npos && !invalid->actual.empty(),
                   "request error does not name entry, key, value and expectation: " + message);
      return message;
    }
    // Accepted means checkable: the padded ellipse is one the core takes (before any transform).
    const core::Ellipse padded = app::paddedEllipse(specs[i], global_padding);
    FUZZ_REQUIRE(core::invalidReason(padded).empty(),
                 field + "[" + std::to_string(i) +
                     "] passed request validation but the core refuses it: " +
                     core::invalidReason(padded) + " (spec " + describe(padded) + ")");
    if (specs[i].ellipsoid) {
      const std::string refused = core::invalidReason(app::paddedEllipsoid(specs[i], global_padding));
      FUZZ_REQUIRE(refused.empty(), field + "[" + std::to_string(i) +
                                        "] passed request validation but the core refuses its "
                                        "ellipsoid: " + refused);
    }
  }
  return {};
}

using Snapshot = std::map<std::string, std::pair<app::EllipseSource, app::EllipseSpec>>;

Snapshot snapshot(const app::EllipseRegistry& registry) {
  Snapshot copy;
  for (const auto& [name, stored] : registry.entries()) copy[name] = {stored.source, stored.spec};
  return copy;
}

bool sameSnapshot(const Snapshot& a, const Snapshot& b) {
  if (a.size() != b.size()) return false;
  for (auto x = a.begin(), y = b.begin(); x != a.end(); ++x, ++y) {
    if (x->first != y->first || x->second.first != y->second.first ||
        !sameSpec(x->second.second, y->second.second)) {
      return false;
    }
  }
  return true;
}

/// Every frame is the fixed frame's twin, except arm_link, which tf has never heard of.
app::FrameTransform identityLookup(const std::string& frame) {
  app::FrameTransform transform;
  transform.ok = frame != "arm_link";
  if (!transform.ok) transform.error = "frame 'arm_link' does not exist";
  return transform;
}

app::EllipseSpec configured(const char* name, const char* frame, double x) {
  app::EllipseSpec spec;
  spec.name = name;
  spec.frame_id = frame;
  spec.x = x;
  spec.radius_x = 0.5;
  spec.radius_y = 0.25;
  return spec;
}

}  // namespace
}  // namespace ellipse_collision::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellipse_collision;
  using namespace ellipse_collision::fuzz;
  FuzzInput input(data, size);
  app::EllipseRegistry registry(
      {configured("body", "base_link", 0.0), configured("arm", "arm_link", 1.0)},
      {configured("crate", "odom", 2.0)});
  app::CheckSettings settings;
  settings.global_padding_m = input.flag() ? 0.0 : 0.02;
  const double global_padding = settings.global_padding_m;
  const app::TransformLookup lookup = identityLookup;

  for (int operation = 0; operation < 8 && input.remaining() > 0; ++operation) {
    const Snapshot before = snapshot(registry);
    const int kind = input.integer(0, 3);
    std::vector<Ellipse> msgs(static_cast<std::size_t>(input.integer(0, kMaxEntries)));
    for (Ellipse& msg : msgs) msg = readMsg(input);

    if (kind == 0) {  // ~add_obstacles
      std::vector<app::EllipseSpec> specs;
      for (const Ellipse& msg : msgs) specs.push_back(fromMsg(msg));
      const std::string field_error = validate(msgs, specs, "obstacles", global_padding);
      std::string error = app::validateAttached(specs, "obstacles", settings, lookup);
      FUZZ_REQUIRE(field_error.empty() ? error.empty() || error.find(".frame_id = 'arm_link'") !=
                                                              std::string::npos
                                       : error == field_error,
                   "validateAttached answered '" + error + "', the field rules '" + field_error + "'");
      if (error.empty()) error = registry.addObstacles(specs, "obstacles");
      if (!error.empty()) {
        FUZZ_REQUIRE(sameSnapshot(before, snapshot(registry)), "refused add changed the registry");
        FUZZ_REQUIRE(error.rfind("obstacles[", 0) == 0, "add error names no entry: " + error);
      } else {
        for (const app::EllipseSpec& spec : specs) {
          FUZZ_REQUIRE(storedAsGiven(registry, spec, app::EllipseSource::ServiceObstacle),
                       "added obstacle '" + spec.name + "' is not stored as given");
          FUZZ_REQUIRE(!before.count(spec.name) ||
                           before.at(spec.name).first == app::EllipseSource::ConfiguredObstacle ||
                           before.at(spec.name).first == app::EllipseSource::ServiceObstacle,
                       "add replaced a link or topic obstacle '" + spec.name + "'");
        }
      }
    } else if (kind == 1) {  // ~remove_obstacles
      std::vector<std::string> names;
      for (const Ellipse& msg : msgs) names.push_back(msg.name);
      const std::string error = registry.removeObstacles(names, "names");
      if (!error.empty()) {
        FUZZ_REQUIRE(sameSnapshot(before, snapshot(registry)),
                     "refused remove changed the registry");
        FUZZ_REQUIRE(error.rfind("names[", 0) == 0, "remove error names no entry: " + error);
      } else {
        for (const std::string& name : names) {
          FUZZ_REQUIRE(before.count(name) &&
                           before.at(name).first != app::EllipseSource::ConfiguredLink &&
                           !registry.contains(name),
                       "remove of '" + name + "' succeeded wrongly");
        }
        FUZZ_REQUIRE(before.size() == registry.entries().size() + names.size(),
                     "remove took away more or fewer entries than named");
      }
    } else if (kind == 2) {  // ~obstacles topic: EllipseArray with a header frame
      EllipseArray array;
      array.header.frame_id = pick(input, kFrames);
      array.ellipses = msgs;
      const std::vector<app::EllipseSpec> specs = fromMsg(array);
      FUZZ_REQUIRE(specs.size() == msgs.size(), "fromMsg(EllipseArray) lost entries");
      for (std::size_t i = 0; i < specs.size(); ++i) {
        const std::string& frame =
            msgs[i].frame_id.empty() ? array.header.frame_id : msgs[i].frame_id;
        FUZZ_REQUIRE(specs[i].frame_id == frame, "frame_id not inherited as documented");
      }
      std::vector<Ellipse> resolved = msgs;
      for (std::size_t i = 0; i < specs.size(); ++i) resolved[i].frame_id = specs[i].frame_id;
      const std::string field_error = validate(resolved, specs, "ellipses", global_padding);
      std::string error = app::validateAttached(specs, "ellipses", settings, lookup);
      FUZZ_REQUIRE(field_error.empty() || error == field_error,
                   "validateAttached answered '" + error + "', the field rules '" + field_error + "'");
      if (error.empty()) error = registry.replaceTopicObstacles(specs, "ellipses");
      if (!error.empty()) {
        FUZZ_REQUIRE(sameSnapshot(before, snapshot(registry)),
                     "refused topic message changed the registry");
      } else {
        FUZZ_REQUIRE(registry.count(app::EllipseSource::TopicObstacle) == specs.size(),
                     "topic obstacles are not exactly the last message's");
        // Each obstacle of the message as given (in place or new), every other entry as it was.
        for (const app::EllipseSpec& spec : specs) {
          FUZZ_REQUIRE(storedAsGiven(registry, spec, app::EllipseSource::TopicObstacle),
                       "topic obstacle '" + spec.name + "' is not stored as given");
        }
        for (const auto& [name, entry] : before) {
          if (entry.first == app::EllipseSource::TopicObstacle) continue;
          FUZZ_REQUIRE(storedAsGiven(registry, entry.second, entry.first),
                       "a topic message changed '" + name + "', not a topic obstacle");
        }
      }
    } else {  // ~check_collisions: names, query and min_distance_of, validated then checked
      CheckCollisions::Request request;
      request.query = msgs;
      for (int n = input.integer(0, 3); n > 0; --n) request.names.push_back(pick(input, kNames));
      if (input.flag()) request.min_distance_of = pick(input, kNames);
      const app::CheckRequest check = fromMsg(request);
      FUZZ_REQUIRE(check.query.size() == msgs.size() && check.names == request.names &&
                       check.min_distance_of == request.min_distance_of,
                   "fromMsg(CheckCollisions::Request) lost a field");
      const std::string field_error = validate(msgs, check.query, "query", global_padding);
      const std::string error = app::validateCheckRequest(check, registry, global_padding);
      // Name rules are checked entry by entry with the fields, so an earlier entry's name may be
      // reported first; a field error must refuse the request all the same.
      FUZZ_REQUIRE(field_error.empty() || !error.empty(),
                   "validateCheckRequest accepted a request with '" + field_error + "'");
      if (error.empty()) {
        const app::CheckOutcome outcome = app::runCheck(check, registry, settings, lookup);
        const bool query_in_arm_link =
            std::any_of(check.query.begin(), check.query.end(),
                        [](const app::EllipseSpec& q) { return q.frame_id == "arm_link"; });
        // An ellipsoid's shadow is certified by growing it (core::shadowOnPlane()): with radii
        // near kMaxRadius it can leave the core's range even at the identity, and a needle of
        // axis ratio beyond 7e16 cannot be certified; the query is then refused naming it, as one
        // seen edge-on is.
        const bool shadow_out_of_range =
            outcome.error_kind == app::ErrorKind::InvalidRequest &&
            outcome.error.rfind("query[", 0) == 0 &&
            (outcome.error.find("': its shadow is out of range (") != std::string::npos ||
             outcome.error.find("': its shadow is too thin to certify (") != std::string::npos);
        FUZZ_REQUIRE(!shadow_out_of_range ||
                         std::any_of(check.query.begin(), check.query.end(),
                                     [](const app::EllipseSpec& q) { return q.ellipsoid; }),
                     "a planar query refused for its shadow: '" + outcome.error + "'");
        FUZZ_REQUIRE(outcome.error.empty() != (query_in_arm_link || shadow_out_of_range),
                     "runCheck of a validated request: '" + outcome.error + "'");
        FUZZ_REQUIRE(outcome.error.rfind("internal error", 0) != 0,
                     "the core refused a validated scene: " + outcome.error);
        CheckCollisions::Response response;
        if (outcome.error.empty()) toMsg(outcome, response);
        for (const core::CollidingPair& pair : outcome.collisions) {
          const core::CollidingPair back = fromMsg(toMsg(pair));
          FUZZ_REQUIRE(back.name_a == pair.name_a && back.name_b == pair.name_b &&
                           sameBits(back.contact_scale, pair.contact_scale),
                       "CollisionPair round trip changed a field");
        }
        FUZZ_REQUIRE(response.collisions.size() == outcome.collisions.size() &&
                         response.in_collision == !outcome.collisions.empty(),
                     "the response lost collisions");
      }
    }
    FUZZ_REQUIRE(registry.count(app::EllipseSource::ConfiguredLink) == 2 && registry.contains("body") &&
                     registry.contains("arm"),
                 "a configured link was removed or replaced");
  }
  return 0;
}
