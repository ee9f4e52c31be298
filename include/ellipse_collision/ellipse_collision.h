#pragma once

// Umbrella header of the ROS-free core (namespace ellipse_collision::core): ellipses, the
// collision tests and distance between two of them, scenes of many, frames, and the helpers every
// layer shares. The README's "The core library" table lists every function.
#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/enclosing_ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/frame_projection.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/motion_line_parser.h"
#include "ellipse_collision/core/number_fields.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/pair_line_parser.h"
#include "ellipse_collision/core/point_clusters.h"
#include "ellipse_collision/core/polygonal_early_out.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/core/shape_outline.h"
#include "ellipse_collision/core/unique_names.h"
#include "ellipse_collision/core/velocity_gate.h"
