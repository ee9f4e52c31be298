#pragma once

// The one place the ROS layer includes the package's generated messages and services.
//
// The generated message ellipse_collision/Ellipse declares `typedef Ellipse_<...> Ellipse` in
// namespace ellipse_collision, which clashes with the core's `struct ellipse_collision::Ellipse`.
// The message's typedef is therefore renamed to EllipseMsg while its header is read; every other
// generated name (Ellipse_, EllipsePtr, EllipseArray, ...) keeps its generated spelling. Include
// this header instead of any generated one, so that the rename happens before anything else reads
// the message header (its include guard then keeps it from being read a second time).
#include <ros/ros.h>

#include "ellipse_collision/ellipse.h"

#ifdef Ellipse
#error "Ellipse is already a macro"
#endif
#define Ellipse EllipseMsg
#include <ellipse_collision/Ellipse.h>
#undef Ellipse

#include <ellipse_collision/AddObstacles.h>
#include <ellipse_collision/CheckCollisions.h>
#include <ellipse_collision/ClearancePair.h>
#include <ellipse_collision/CollisionPair.h>
#include <ellipse_collision/CollisionState.h>
#include <ellipse_collision/EllipseArray.h>
#include <ellipse_collision/RemoveObstacles.h>
