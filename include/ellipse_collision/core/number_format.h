#pragma once

#include <string>

namespace ellipse_collision::core {

/// A number as it reads back: the shortest text that parses to the same double ("0.1", "20",
/// "1e-09"), or "nan", "inf", "-inf". Every message that quotes a value uses it, so a user sees
/// exactly what was given and can paste it back.
std::string formatNumber(double value);

/// formatNumber(value) appended to `out`, without a string of its own: for writers of many
/// numbers (the obstacle store writes nine per obstacle).
void appendNumber(std::string& out, double value);

}  // namespace ellipse_collision::core
