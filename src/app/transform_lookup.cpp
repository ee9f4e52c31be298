#include "ellipse_collision/app/transform_lookup.h"

namespace ellipse_collision::app {

double ageOf(const FrameTransform& transform, const Freshness& freshness) {
  return transform.stamp_s == 0.0 ? 0.0 : freshness.reference_s - transform.stamp_s;
}

bool isStale(const FrameTransform& transform, const Freshness& freshness) {
  return transform.ok && freshness.max_age_s > 0.0 && transform.stamp_s != 0.0 &&
         ageOf(transform, freshness) > freshness.max_age_s;
}

}  // namespace ellipse_collision::app
