#pragma once

#include <array>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::core {

// How a real base follows a velocity command, and where it comes to rest: the model behind the
// gate's braking rule (doc/velocity_gate.md, "Braking").

/// A base's answer to a command: `reaction_time` late, then shedding speed at bounded rates.
/// All zero: the ideal base, which follows every command at once.
struct BaseDynamics {
  double reaction_time{0.0};         ///< the previous velocity keeps acting this long [s]
  double linear_deceleration{0.0};   ///< [m/s^2]; 0 = sheds linear speed at once
  double angular_deceleration{0.0};  ///< [rad/s^2]; 0 = sheds turn rate at once
  bool ideal() const {
    return reaction_time == 0.0 && linear_deceleration == 0.0 && angular_deceleration == 0.0;
  }
};

/// The rate [1/s] at which the base sheds a uniform scale of `twist` (keeping its arc: a twist
/// scaled down uniformly keeps its centre of rotation): min(a_lin / |(vx, vy)|, a_ang / |wz|) over
/// the parts that move and have a limit; infinity (at once) when none has.
double brakingRate(const Twist& twist, const BaseDynamics& dynamics);

/// The scale s(t) of one twist as the base follows a command: `from` held for `reaction` [s];
/// then `to` acting for `hold` [s] (reached at `rate` [1/s] when lower, at once when higher);
/// then braking to rest at `rate`. The base stays on the twist's arc: at time t it is where the
/// twist at scale 1 puts it after sigma(t) = integral of s (braking changes time along the path,
/// not the path). An infinite rate changes the scale at once.
class ScaleProfile {
 public:
  ScaleProfile(double from, double to, double reaction, double hold, double rate);

  double scaleAt(double t) const;
  /// Twist-time covered by `t` [s at scale 1].
  double sigmaAt(double t) const;
  /// When the base is at rest [s].
  double stopTime() const { return pieces_[kPieces - 1].end; }
  /// Twist-time covered when at rest [s at scale 1].
  double stopSigma() const { return sigmaAt(stopTime()); }
  /// The first t with sigmaAt(t) >= sigma, or infinity when the base stops short of it.
  double timeAtSigma(double sigma) const;
  /// The largest scale on the way [-].
  double maxScale() const;

 private:
  /// s = scale + slope (t - start) on [start, end]; sigma covered before `start`.
  struct Piece {
    double start, end, scale, slope, sigma_before;
  };
  static constexpr int kPieces = 4;  // reaction, ramp, hold, braking
  std::array<Piece, kPieces> pieces_{};
};

/// The first time in [0, profile.stopTime()] at which `link` (robot frame at t = 0), moving on the
/// arc of `twist` as `profile` follows it, comes within `clearance` [m] of `obstacle` moving by
/// `motion` (overlap counts). Certified never late: conservative advancement on distance(), each
/// step the gap over the fastest the pair can close; a pair still apart after 2000 steps is
/// reported at the last certified time. Precondition: invalidTwistContactReason() is empty for
/// the twist at scale profile.maxScale() over profile.stopTime().
FirstContact brakingContact(const Ellipse& link, const Twist& twist, const ScaleProfile& profile,
                            const Ellipse& obstacle, const Motion& motion, double clearance);

}  // namespace ellipse_collision::core
