#pragma once

#include <cstdint>
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
  /// Service calls (successful ~add_obstacles / ~remove_obstacles) of this session it includes:
  /// orders it against a service record (serviceRecordPath()). 0 in stores written before it.
  std::uint64_t service_revision{0};
};

/// The file beside the store at `store_path` that holds the service obstacles alone: a service
/// call that changed only service obstacles writes that record (the same text form, no topic
/// obstacles) instead of the whole store, so that it does not rewrite a perception stream's
/// 100,000 topic obstacles too.
std::string serviceRecordPath(const std::string& store_path);

/// Folds `record`, read from serviceRecordPath(), into `store`, read from the store itself, when
/// it is of the same session and newer (service_revision): its service obstacles replace the
/// store's, and topic obstacles under the same names are dropped (the registry refuses a service
/// obstacle under a live topic obstacle's name, so such a topic obstacle was gone when the record
/// was written). Returns whether it applied.
bool applyNewerServiceRecord(StoredObstacles& store, const StoredObstacles& record);

/// Whether `text` begins like a store of any version (the file is this package's to write).
bool isObstacleStoreText(const std::string& text);

/// A line-based text form; names and frames are length-prefixed, numbers round-trip exactly.
std::string serializeObstacles(const StoredObstacles& obstacles);

/// Parses serializeObstacles() text into `out`; returns "" or why the text is not a store
/// ("record 3: ..."; an obstacle breaking the field rules findInvalidField() as "record 5 (line 5):
/// service obstacle 'box'.radius_x = nan: expected ..."). `out` is left untouched on failure.
std::string parseObstacles(const std::string& text, StoredObstacles& out);

/// What loadObstacleStore() found.
struct LoadedStore {
  /// The obstacles to restore: the store's if it is of this session, with a newer service record
  /// folded in (applyNewerServiceRecord()).
  StoredObstacles obstacles;
  bool found{false};  ///< anything of this session to restore
  /// Files not used, each with why ("... is corrupt: record 3: ..."); `failed` for an unreadable
  /// or corrupt file (logged as an error), not for a missing one or one of another launch.
  struct Note {
    bool failed;
    std::string text;
  };
  std::vector<Note> notes;
  /// Files at the store's paths that are not obstacle stores (or cannot be read to tell), each
  /// with why: the store must not be written over them (ObstaclePersistence refuses).
  std::vector<std::string> not_ours;
};

/// Reads the store at `path` and its service record (serviceRecordPath()) for launch `session`.
/// Either file may be missing, unreadable, corrupt or of another launch: it is then left out,
/// with a note, and the other is used alone.
LoadedStore loadObstacleStore(const std::string& path, const std::string& session);

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
