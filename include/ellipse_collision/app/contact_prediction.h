#pragma once

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/transform_lookup.h"

namespace ellipse_collision::app {

/// The window of the finite difference that estimates a frame's velocity from tf [s]: the pose at
/// the frame's latest transform against the pose kVelocityWindowS earlier. Short enough to follow
/// a robot that brakes, long enough to span several tf messages at the usual 10-100 Hz.
constexpr double kVelocityWindowS = 0.1;

/// The time-to-contact step of a check, after runCheck() succeeded: the motion in the fixed frame
/// of every placed stored ellipse (its frame's motion by a finite difference over
/// kVelocityWindowS ending at the frame's latest stamp, through `at`, plus its own vx, vy,
/// angular_velocity turned into the fixed frame; timeless frames do not move), each ellipse moved
/// on by its motion from its frame's stamp to `reference_s` (the check's stamp; at most
/// kMaxPredictionLagS), then core::predictContacts() over `horizon_s` with the request's name
/// filter, so that times count from `reference_s`. Pairs in outcome.collisions are not repeated; a
/// pair apart at the check's poses that touches by `reference_s` is reported at time 0. A frame
/// whose earlier pose is unknown moves by the ellipse's own velocity only, noted in
/// prediction_notes. Query ellipses are not predicted. Fills outcome.predicted and
/// outcome.prediction_notes.
/// The check's own transforms (outcome.frames) and placed ellipses are reused: no frame is looked
/// up again at its latest stamp and no ellipse projected again at it.
void predictAfterCheck(CheckOutcome& outcome, const CheckRequest& request,
                       const EllipseRegistry& registry, const CheckSettings& settings,
                       const TransformAtLookup& at, double horizon_s, double reference_s);

/// The longest a pose is moved on to the check's stamp [s]: a frame whose latest transform is
/// older than this (without max_transform_age) is moved by this much only.
constexpr double kMaxPredictionLagS = 1.0;

}  // namespace ellipse_collision::app
