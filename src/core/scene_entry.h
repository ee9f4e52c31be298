#pragma once

#include <cstddef>
#include <string>

#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core::detail {

/// How a refusal names an entry of a scene's list: "ellipses[3] ('rock')". Built only for an
/// error: per entry it would cost more than the whole check.
inline std::string entryLabel(const char* list, std::size_t index, const NamedEllipse& entry) {
  return std::string(list) + "[" + std::to_string(index) + "] ('" + entry.name + "')";
}

/// The refusal of an entry whose ellipse is invalid: "ellipses[3] ('rock'): radius_x = -1 must
/// be > 0". The one wording of every scene-level entry point.
inline std::string invalidEntryReason(const char* list, std::size_t index,
                                      const NamedEllipse& entry) {
  return entryLabel(list, index, entry) + ": " + invalidReason(entry.ellipse);
}

}  // namespace ellipse_collision::core::detail
