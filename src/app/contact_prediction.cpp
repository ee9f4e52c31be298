#include "ellipse_collision/app/contact_prediction.h"

#include <algorithm>
#include <cmath>
#include <set>
#include "ellipse_collision/core/frame_projection.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/path_motion.h"

namespace ellipse_collision::app {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// The motion in the fixed frame of a stored ellipse's frame, by the finite difference of its
/// projected pose over kVelocityWindowS (`now`: as the check placed it at `latest`); a zero
/// motion and a note when it cannot be estimated.
core::Motion frameMotion(const EllipseSpec& spec, double global_padding, const core::Ellipse& now,
                         const FrameTransform& latest, const TransformAtLookup& at,
                         std::vector<std::string>& notes) {
  if (latest.stamp_s == 0.0) return {};  // timeless: a static chain or the fixed frame itself
  const FrameTransform earlier = at(spec.frame_id, latest.stamp_s - kVelocityWindowS);
  if (!earlier.ok) {
    notes.push_back(spec.name + ": velocity of frame '" + spec.frame_id + "' unknown (" +
                    earlier.error + ")");
    return {};
  }
  const core::ProjectionResult then =
      placeInPlane(spec, global_padding, earlier.fixed_from_frame);
  if (!then.ok()) return {};
  core::Motion motion;
  motion.velocity = (now.center - then.ellipse.center) / kVelocityWindowS;
  // Projected angles are taken modulo pi (an ellipse is symmetric): the shortest difference.
  motion.angular_velocity =
      std::remainder(now.angle - then.ellipse.angle, kPi) / kVelocityWindowS;
  return motion;
}

}  // namespace

void predictAfterCheck(CheckOutcome& outcome, const CheckRequest& request,
                       const EllipseRegistry& registry, const CheckSettings& settings,
                       const TransformAtLookup& at, double horizon_s, double reference_s) {
  if (!(horizon_s > 0.0)) return;
  std::vector<core::Motion> motions;
  motions.reserve(outcome.placed.size());
  std::vector<core::NamedEllipse> now = outcome.placed.entries();  // moved on to reference_s
  const FrameTransform missing;  // never the case for a placed ellipse: its frame was looked up
  for (core::NamedEllipse& placed : now) {
    const EllipseSpec& spec = registry.entries().at(placed.name).spec;
    const auto found = outcome.frames.find(spec.frame_id);
    const FrameTransform& frame = found != outcome.frames.end() ? found->second : missing;
    // The placed ellipse is the projection at this very transform (tf may have received a newer
    // one since): the finite difference and the lag start from it.
    core::Motion motion = frame.ok ? frameMotion(spec, settings.global_padding_m, placed.ellipse,
                                                 frame, at, outcome.prediction_notes)
                                   : core::Motion{};
    const core::Motion own = ownMotion(spec, frame.fixed_from_frame);
    motion.velocity += own.velocity;
    motion.angular_velocity += own.angular_velocity;
    motions.push_back(motion);
    if (frame.ok && frame.stamp_s > 0.0) {
      const double lag = std::clamp(reference_s - frame.stamp_s, 0.0, kMaxPredictionLagS);
      const core::Ellipse on = core::movedBy(placed.ellipse, motion, lag);
      if (core::invalidReason(on).empty()) placed.ellipse = on;
    }
  }
  std::set<std::pair<std::string, std::string>> colliding;
  for (const core::CollidingPair& pair : outcome.collisions)
    colliding.insert({pair.name_a, pair.name_b});
  const std::set<std::string> only_names(request.names.begin(), request.names.end());
  core::PredictionResult result =
      core::predictContacts(now, motions, settings.rules, only_names, horizon_s, &colliding);
  outcome.predicted = std::move(result.predicted);
  for (std::string& refused : result.refused) {
    outcome.prediction_notes.push_back("not predicted: " + refused);
  }
}

}  // namespace ellipse_collision::app
