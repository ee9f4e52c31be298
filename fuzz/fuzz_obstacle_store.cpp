// Fuzz target: parseObstacles(), the reader of the obstacle store a restarted node trusts, fed
// arbitrary bytes (a file cut short by a full disk, edited by hand, or written by another program).
//
// Invariants:
//  - refused text leaves the output untouched, with one error that is "empty file", "truncated:
//    no 'end' record" or starts with "record <n>: ";
//  - accepted text written back by serializeObstacles() reads back to the very same store (every
//    number to the same bits, a NaN as a NaN), and that text is a fixed point: writing the second
//    reading gives the same bytes.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "ellipse_collision/app/obstacle_store.h"

namespace {

using ellipse_collision::app::EllipseSpec;
using ellipse_collision::app::StoredObstacles;

bool sameNumber(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameSpec(const EllipseSpec& a, const EllipseSpec& b) {
  return a.name == b.name && a.frame_id == b.frame_id && sameNumber(a.x, b.x) &&
         sameNumber(a.y, b.y) && sameNumber(a.angle, b.angle) &&
         sameNumber(a.radius_x, b.radius_x) && sameNumber(a.radius_y, b.radius_y) &&
         sameNumber(a.padding, b.padding) && sameNumber(a.vx, b.vx) && sameNumber(a.vy, b.vy) &&
         sameNumber(a.angular_velocity, b.angular_velocity) &&
         a.ellipsoid.has_value() == b.ellipsoid.has_value() &&
         (!a.ellipsoid || (sameNumber(a.ellipsoid->z, b.ellipsoid->z) &&
                           sameNumber(a.ellipsoid->roll, b.ellipsoid->roll) &&
                           sameNumber(a.ellipsoid->pitch, b.ellipsoid->pitch) &&
                           sameNumber(a.ellipsoid->radius_z, b.ellipsoid->radius_z)));
}

bool sameStore(const StoredObstacles& a, const StoredObstacles& b) {
  if (a.session != b.session || !sameNumber(a.topic_stamp_s, b.topic_stamp_s) ||
      a.service_revision != b.service_revision ||
      a.service.size() != b.service.size() || a.topic.size() != b.topic.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.service.size(); ++i) {
    if (!sameSpec(a.service[i], b.service[i])) return false;
  }
  for (std::size_t i = 0; i < a.topic.size(); ++i) {
    if (!sameSpec(a.topic[i], b.topic[i])) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellipse_collision::app;
  const std::string text(reinterpret_cast<const char*>(data), size);
  StoredObstacles read;
  read.session = "untouched";
  const std::string error = parseObstacles(text, read);
  if (!error.empty()) {
    if (read.session != "untouched" || !read.service.empty() || !read.topic.empty()) std::abort();
    if (error != "empty file" && error != "truncated: no 'end' record" &&
        error.rfind("record ", 0) != 0) {
      std::abort();
    }
    return 0;
  }
  // The field rules are the store's gate too: nothing accepted breaks them.
  for (const auto* specs : {&read.service, &read.topic}) {
    for (const EllipseSpec& spec : *specs) {
      if (findInvalidField(spec)) std::abort();
    }
  }
  const std::string written = serializeObstacles(read);
  StoredObstacles again;
  if (!parseObstacles(written, again).empty()) std::abort();
  if (!sameStore(read, again)) std::abort();
  if (serializeObstacles(again) != written) std::abort();
  return 0;
}
