#pragma once

// Umbrella header of the ROS-free core: ellipses and the collision tests between them.
#include "ellipse_collision/ellipse.h"
#include "ellipse_collision/broadphase.h"
#include "ellipse_collision/distance.h"
#include "ellipse_collision/eigenvalue_test.h"
#include "ellipse_collision/overlap.h"
#include "ellipse_collision/pair_line_parser.h"
#include "ellipse_collision/polygonal_test.h"
#include "ellipse_collision/prepared_ellipse.h"
