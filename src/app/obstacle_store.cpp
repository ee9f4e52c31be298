#include "ellipse_collision/app/obstacle_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "ellipse_collision/core/number_fields.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {
namespace {

/// What every version of the store begins with: a file without it is not the store's to write.
constexpr const char* kHeaderStem = "ellipse_collision obstacle store ";
/// Version 1 holds planar records; version 2 may also hold an ellipsoid's 13-number records,
/// which a version-1 reader refuses. A store is written as version 1 when it holds no
/// ellipsoid, so that an older node can still read it, and as 2 otherwise, so that an older node
/// refuses it at its first line (naming the version) rather than at a record. Both read the same.
constexpr int kPlanarVersion = 1;
constexpr int kNewestVersion = 2;

std::string headerOf(int version) { return kHeaderStem + std::to_string(version); }

void appendText(std::string& out, const std::string& s) {
  out += std::to_string(s.size());
  out += ':';
  out += s;
}

// Appended to one string with the shortest round-trip numbers: 10,000 obstacles are written in a
// few milliseconds (snprintf's "%.17g" into a stream took 37 ms).
void appendSpec(std::string& out, const char* kind, const EllipseSpec& spec) {
  out += kind;
  out += ' ';
  appendText(out, spec.name);
  out += ' ';
  appendText(out, spec.frame_id);
  for (const double value : {spec.x, spec.y, spec.angle, spec.radius_x, spec.radius_y,
                             spec.padding, spec.vx, spec.vy, spec.angular_velocity}) {
    out += ' ';
    core::appendNumber(out, value);
  }
  // An ellipsoid's four follow; a planar obstacle's record is what it was before them.
  if (spec.ellipsoid) {
    const EllipsoidPart& part = *spec.ellipsoid;
    for (const double value : {part.z, part.roll, part.pitch, part.radius_z}) {
      out += ' ';
      core::appendNumber(out, value);
    }
  }
  out += '\n';
}

/// Reads "<length>:<bytes>" at `pos` of `line`, then skips one space.
bool readText(const std::string& line, std::size_t& pos, std::string& out) {
  const std::size_t colon = line.find(':', pos);
  if (colon == std::string::npos || colon == pos) return false;
  std::size_t length = 0;
  for (std::size_t i = pos; i < colon; ++i) {
    if (line[i] < '0' || line[i] > '9' || length > line.size()) return false;
    length = 10 * length + static_cast<std::size_t>(line[i] - '0');
  }
  if (colon + 1 + length > line.size()) return false;
  out = line.substr(colon + 1, length);
  pos = colon + 1 + length;
  if (pos < line.size() && line[pos] == ' ') ++pos;
  return true;
}

bool readNumbers(const std::string& line, EllipseSpec& spec) {
  static constexpr const char* kNames[] = {
      "x",  "y",  "angle",           "radius_x", "radius_y", "padding", "vx",
      "vy", "angular_velocity", "z",        "roll",     "pitch",   "radius_z"};
  double values[13] = {0.0};
  std::string error;
  // The velocities follow the ellipse (a store written before them has none: the obstacle
  // stands), an ellipsoid's z, roll, pitch and radius_z the velocities. The planar record, the
  // common one, is tried first: it is read once, as before there were ellipsoids.
  std::size_t count = 0;
  for (const std::size_t fields : {9, 13, 6}) {
    if (core::parseNumberFields(line, kNames, fields, values, error) ==
        core::NumberFields::Numbers) {
      count = fields;
      break;
    }
  }
  if (count == 0) return false;
  spec.x = values[0];
  spec.y = values[1];
  spec.angle = values[2];
  spec.radius_x = values[3];
  spec.radius_y = values[4];
  spec.padding = values[5];
  spec.vx = values[6];
  spec.vy = values[7];
  spec.angular_velocity = values[8];
  if (count == 13) spec.ellipsoid = EllipsoidPart{values[9], values[10], values[11], values[12]};
  return true;
}

/// `line` as a decimal count: digits only, no sign, no overflow.
bool readCount(const std::string& line, std::uint64_t& out) {
  if (line.empty() || line.size() > 19) return false;  // 19 digits never overflow 64 bits
  std::uint64_t value = 0;
  for (const char c : line) {
    if (c < '0' || c > '9') return false;
    value = 10 * value + static_cast<std::uint64_t>(c - '0');
  }
  out = value;
  return true;
}

std::string errnoText(const std::string& step, const std::string& path) {
  return step + " '" + path + "': " + std::strerror(errno);
}

}  // namespace

std::string serializeObstacles(const StoredObstacles& obstacles) {
  std::string out;
  // About 130 bytes per obstacle: one allocation for all of them.
  out.reserve(128 + obstacles.session.size() +
              160 * (obstacles.service.size() + obstacles.topic.size()));
  const auto is_ellipsoid = [](const EllipseSpec& spec) { return spec.ellipsoid.has_value(); };
  const bool holds_ellipsoid =
      std::any_of(obstacles.service.begin(), obstacles.service.end(), is_ellipsoid) ||
      std::any_of(obstacles.topic.begin(), obstacles.topic.end(), is_ellipsoid);
  out += headerOf(holds_ellipsoid ? kNewestVersion : kPlanarVersion);
  out += "\nsession ";
  appendText(out, obstacles.session);
  out += "\ntopic_stamp ";
  core::appendNumber(out, obstacles.topic_stamp_s);
  out += "\nservice_revision ";
  out += std::to_string(obstacles.service_revision);
  out += '\n';
  for (const EllipseSpec& spec : obstacles.service) appendSpec(out, "service", spec);
  for (const EllipseSpec& spec : obstacles.topic) appendSpec(out, "topic", spec);
  out += "end\n";
  return out;
}

std::string parseObstacles(const std::string& input, StoredObstacles& out) {
  // Records end with '\n'; names and frames are length-prefixed and may hold any byte, newlines
  // included, so the reader walks positions rather than lines.
  StoredObstacles parsed;
  std::size_t pos = 0;
  std::size_t record = 0;
  const auto at = [&](const std::string& what) {
    return "record " + std::to_string(record) + ": " + what;
  };
  const auto restOfLine = [&](std::string& rest) {
    const std::size_t newline = input.find('\n', pos);
    if (newline == std::string::npos) return false;
    rest = input.substr(pos, newline - pos);
    pos = newline + 1;
    return true;
  };
  if (input.empty()) return "empty file";
  std::string line;
  ++record;
  if (!restOfLine(line) ||
      (line != headerOf(kPlanarVersion) && line != headerOf(kNewestVersion))) {
    if (line.rfind(kHeaderStem, 0) == 0) {
      return at("'" + line + "' is a version this node does not read (it reads versions " +
                std::to_string(kPlanarVersion) + " to " + std::to_string(kNewestVersion) +
                "): written by a newer ellipse_collision?");
    }
    return at("expected '" + headerOf(kPlanarVersion) + "' or '" + headerOf(kNewestVersion) + "'");
  }
  while (true) {
    ++record;
    const std::size_t record_start = pos;
    if (pos >= input.size()) return "truncated: no 'end' record";
    const std::size_t space = input.find_first_of(" \n", pos);
    if (space == std::string::npos) return "truncated: no 'end' record";
    const std::string kind = input.substr(pos, space - pos);
    pos = space + (input[space] == ' ' ? 1 : 0);
    if (kind == "end") {
      if (!restOfLine(line) || !line.empty() || pos != input.size()) {
        return at("expected nothing after 'end'");
      }
      break;
    }
    if (kind == "session") {
      if (!readText(input, pos, parsed.session) || !restOfLine(line) || !line.empty()) {
        return at("expected session <length>:<id>");
      }
    } else if (kind == "topic_stamp") {
      std::istringstream value(restOfLine(line) ? line : "");
      std::string extra;
      if (!(value >> parsed.topic_stamp_s) || (value >> extra)) {
        return at("expected topic_stamp <seconds>");
      }
    } else if (kind == "service_revision") {
      if (!restOfLine(line) || !readCount(line, parsed.service_revision)) {
        return at("expected service_revision <count>");
      }
    } else if (kind == "service" || kind == "topic") {
      EllipseSpec spec;
      if (!readText(input, pos, spec.name) || !readText(input, pos, spec.frame_id) ||
          !restOfLine(line) || !readNumbers(line, spec)) {
        return at("expected " + kind +
                  " <name> <frame> x y angle radius_x radius_y padding [vx vy angular_velocity"
                  " [z roll pitch radius_z]]");
      }
      // The same field rules as every other way into the registry: a hand edit or a disk fault
      // that leaves NaN or a negative radius refuses the file instead of an obstacle that every
      // check would skip.
      if (const auto invalid = findInvalidField(spec)) {
        const auto line = 1 + std::count(input.begin(), input.begin() + record_start, '\n');
        return "record " + std::to_string(record) + " (line " + std::to_string(line) + "): " +
               describeFieldError(kind + " obstacle '" + spec.name + "'", *invalid);
      }
      (kind == "service" ? parsed.service : parsed.topic).push_back(spec);
    } else {
      return at("unknown entry '" + kind + "'");
    }
  }
  out = std::move(parsed);
  return {};
}

bool isObstacleStoreText(const std::string& text) { return text.rfind(kHeaderStem, 0) == 0; }

std::string serviceRecordPath(const std::string& store_path) { return store_path + ".service"; }

bool applyNewerServiceRecord(StoredObstacles& store, const StoredObstacles& record) {
  if (record.session != store.session || record.service_revision <= store.service_revision) {
    return false;
  }
  std::set<std::string> service_names;
  for (const EllipseSpec& spec : record.service) service_names.insert(spec.name);
  store.topic.erase(std::remove_if(store.topic.begin(), store.topic.end(),
                                   [&](const EllipseSpec& spec) {
                                     return service_names.count(spec.name) != 0;
                                   }),
                    store.topic.end());
  store.service = record.service;
  store.service_revision = record.service_revision;
  return true;
}

LoadedStore loadObstacleStore(const std::string& path, const std::string& session) {
  LoadedStore loaded;
  loaded.obstacles.session = session;
  // One file: parsed, or left out with a note; true when it is of this launch.
  const auto read = [&](const std::string& file, StoredObstacles& out) {
    std::string text, error;
    bool missing = false;
    if (!readWholeFile(file, text, missing, error)) {
      if (!missing) {
        loaded.notes.push_back({true, "'" + file + "' is unreadable: " + error});
        loaded.not_ours.push_back("'" + file + "' exists but cannot be read (" + error +
                                  "), so it is not known to be an obstacle store");
      }
      return false;
    }
    if (!isObstacleStoreText(text)) {
      // A typo or a shared folder: never write over a user's file.
      loaded.notes.push_back({true, "'" + file + "' is not an obstacle store"});
      loaded.not_ours.push_back("'" + file + "' is not an obstacle store (its first line is not '" +
                                kHeaderStem + "...')");
      return false;
    }
    error = parseObstacles(text, out);
    if (!error.empty()) {
      loaded.notes.push_back({true, "'" + file + "' is corrupt: " + error});
      return false;
    }
    if (out.session != session) {
      loaded.notes.push_back(
          {false, "'" + file + "' is from another launch (run_id '" + out.session + "')"});
      return false;
    }
    return true;
  };
  StoredObstacles store;
  if (read(path, store)) {
    loaded.obstacles = std::move(store);
    loaded.found = true;
  }
  StoredObstacles record;
  if (read(serviceRecordPath(path), record) && applyNewerServiceRecord(loaded.obstacles, record)) {
    loaded.found = true;
  }
  return loaded;
}

std::string writeFileAtomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return errnoText("cannot create", temporary);
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string error = errnoText("cannot write", temporary);
      ::close(fd);
      return error;
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const std::string error = errnoText("cannot fsync", temporary);
    ::close(fd);
    return error;
  }
  if (::close(fd) != 0) return errnoText("cannot close", temporary);
  if (::rename(temporary.c_str(), path.c_str()) != 0) return errnoText("cannot rename to", path);
  const std::size_t slash = path.rfind('/');
  const std::string directory = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return errnoText("cannot open directory", directory);
  const bool synced = ::fsync(dir) == 0;
  const std::string error = synced ? "" : errnoText("cannot fsync directory", directory);
  ::close(dir);
  return error;
}

std::string makeParentDirectories(const std::string& path) {
  for (std::size_t slash = path.find('/', 1); slash != std::string::npos;
       slash = path.find('/', slash + 1)) {
    const std::string directory = path.substr(0, slash);
    if (::mkdir(directory.c_str(), 0755) != 0 && errno != EEXIST) {
      return errnoText("cannot create directory", directory);
    }
  }
  return {};
}

bool readWholeFile(const std::string& path, std::string& content, bool& missing,
                   std::string& error) {
  missing = false;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    missing = errno == ENOENT;
    if (!missing) error = errnoText("cannot open", path);
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  content = buffer.str();
  return true;
}

}  // namespace ellipse_collision::app
