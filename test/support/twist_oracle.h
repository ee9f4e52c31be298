#pragma once

// The oracle of a link under a held twist: the arc about the instantaneous centre in quad
// precision (independent of poseAfter()'s sinc form), and the first overlap() along it by a dense
// scan and bisection.
#include <functional>
#include <string>

#include "ellipse_collision/core/path_check.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::core::twist_oracle {

/// `link` (robot frame at t = 0) after `t` [s] of `twist`, in quad precision.
Ellipse oracleLinkAt(const Ellipse& link, const Twist& twist, double t);
/// `o` after `t` [s] of `m`.
Ellipse obstacleAt(const Ellipse& o, const Motion& m, double t);
/// First overlap() along the exact motion: `samples` uniform times, then 60 bisections of the
/// first crossing. -1 when none is seen (a contact shorter than horizon / samples can be missed).
double scannedContact(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                      const Motion& motion, double horizon, int samples = 2000);
/// The first time in [0, end] at which `holds` (a contact) is true: `samples` uniform times, then
/// `bisections` halvings of the first crossing; -1 when none is seen.
double firstScanned(const std::function<bool(double)>& holds, double end, int samples,
                    int bisections);
/// The first contact of any pair of the scene under `twist`, scanned; -1 when none.
double scannedSceneContact(const PathScene& scene, const Twist& twist, double horizon,
                           int samples = 2000);

}  // namespace ellipse_collision::core::twist_oracle
