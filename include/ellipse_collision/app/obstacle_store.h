#pragma once

#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"

namespace ellipse_collision::app {

/// The runtime obstacles a restarted node must get back: those added through ~add_obstacles and
/// the last ~obstacles message with its stamp, tagged with the session (roslaunch's /run_id) that
/// wrote them, so that a node respawned within the same launch restores them and a fresh launch
/// does not inherit obstacles from an earlier one.
struct StoredObstacles {
  std::string session;
  std::vector<EllipseSpec> service;
  std::vector<EllipseSpec> topic;
  double topic_stamp_s{0.0};  ///< [s], the stamp of the last ~obstacles message (0 = none)
};

/// A line-based text form; names and frames are length-prefixed, numbers round-trip exactly.
std::string serializeObstacles(const StoredObstacles& obstacles);

/// Parses serializeObstacles() text into `out`; returns "" or why the text is not a store
/// ("line 3: ..."). `out` is left untouched on failure.
std::string parseObstacles(const std::string& text, StoredObstacles& out);

/// Writes `text` to `path` so that a crash at any moment leaves either the old or the new file:
/// a temporary file in the same directory, fsync, rename over `path`, fsync of the directory.
/// Returns "" or the failing step with errno's text.
std::string writeFileAtomically(const std::string& path, const std::string& text);

/// Creates the directories above `path` that do not exist (mode 0755); "" or why not.
std::string makeParentDirectories(const std::string& path);

/// Reads the whole file; false (and `error`) if it cannot be opened. A missing file is
/// `missing = true` and not an error.
bool readWholeFile(const std::string& path, std::string& text, bool& missing, std::string& error);

}  // namespace ellipse_collision::app
