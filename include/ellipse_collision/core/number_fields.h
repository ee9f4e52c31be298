#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ellipse_collision::core {

/// What parseNumberFields() found on a line.
enum class NumberFields { Skip, Numbers, Error };

/// The line format of check_ellipses (parsePairLine(), parseMotionLine()), read once: fields
/// separated by runs of spaces and tabs, a trailing '\r' ignored, a line whose first non-blank
/// character is '#' a comment (Skip), a blank line Skip. Exactly `count` fields, each read with
/// std::from_chars (C syntax whatever the locale, one optional leading '+') into values[i];
/// otherwise Error with `error` naming the field by number and names[i]: `expected 10 fields, got
/// 9`, `field 3 (rx1) is not a number: "abc"` (quoted, cut to 40 characters, control bytes
/// escaped), `field 1 (cx1) is out of the range of a double: "1e999"`. "nan" and "inf" parse: the
/// caller's value rules refuse them.
NumberFields parseNumberFields(std::string_view line, const char* const* names, std::size_t count,
                               double* values, std::string& error);

}  // namespace ellipse_collision::core
