#pragma once

// The package's generated messages and services, in one include for the ROS layer. The generated
// types live in namespace ellipse_collision (ellipse_collision::Ellipse is the message); the
// ROS-free core and application layer live in ellipse_collision::core and ellipse_collision::app,
// so the names never clash.
#include <ellipse_collision/AddObstacles.h>
#include <ellipse_collision/CheckCollisions.h>
#include <ellipse_collision/CheckPath.h>
#include <ellipse_collision/ClearancePair.h>
#include <ellipse_collision/CollisionPair.h>
#include <ellipse_collision/CollisionState.h>
#include <ellipse_collision/Ellipse.h>
#include <ellipse_collision/EllipseArray.h>
#include <ellipse_collision/GateState.h>
#include <ellipse_collision/PredictedContact.h>
#include <ellipse_collision/RemoveObstacles.h>
