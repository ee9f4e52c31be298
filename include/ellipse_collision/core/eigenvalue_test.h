#pragma once

// Old name of contact_scale.h, kept only while src/core/velocity_gate.cpp still includes it;
// include "ellipse_collision/core/contact_scale.h" instead.
#include "ellipse_collision/core/contact_scale.h"
