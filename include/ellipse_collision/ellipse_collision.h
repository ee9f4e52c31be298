#pragma once

// Umbrella header of the ROS-free core: ellipses and the collision tests between them.
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/eigenvalue_test.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/pair_line_parser.h"
#include "ellipse_collision/core/polygonal_test.h"
#include "ellipse_collision/core/prepared_ellipse.h"
