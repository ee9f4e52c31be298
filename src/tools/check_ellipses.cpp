// check_ellipses: reads ellipse pairs from standard input, one per line, and writes for each one
// `collision T` or `clear T`, T being the contact scale (see usage below). Streams: memory use does
// not grow with the input's length.

#include <charconv>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/motion_line_parser.h"
#include "ellipse_collision/ellipse_collision.h"

namespace {

using ellipse_collision::core::PairLine;

constexpr const char* kUsage =
    "usage: check_ellipses [--help] [--motion] < pairs.txt\n"
    "With --motion, lines are `cx1 cy1 rx1 ry1 angle1 vx1 vy1 w1 cx2 cy2 rx2 ry2 angle2 vx2 vy2 w2\n"
    "horizon` (velocities m/s, angular velocities rad/s about the centre, horizon s) and the answer\n"
    "is `contact T` (T the first contact time, 17 significant digits) or `clear`.\n"
    "\n"
    "Reads one pair of 2D ellipses per line from standard input:\n"
    "  cx1 cy1 rx1 ry1 angle1 cx2 cy2 rx2 ry2 angle2\n"
    "centres (cx, cy) and radii (rx, ry) in m, angle in rad counter-clockwise from the x axis\n"
    "to the ellipse's own x axis. Fields are separated by spaces or tabs; blank lines and lines\n"
    "starting with '#' are skipped.\n"
    "\n"
    "Writes one line per pair, in input order:\n"
    "  collision T   the closed ellipses share a point (containment included)\n"
    "  clear T       they do not\n"
    "T (17 significant digits) is the factor by which both ellipses, scaled about their own\n"
    "centres, just touch: T <= 1 means overlap, 0 means coincident centres.\n"
    "A bad line writes `error LINE: reason` in its place (LINE counts from 1, comments and\n"
    "blank lines included) and the following lines are still processed.\n"
    "\n"
    "Exit status: 0 all lines good, 1 some line bad, 2 usage or I/O error.\n";

// Longer lines are reported as errors without being stored, so that a file without newlines
// cannot make the tool hold all of it. A good line needs about 250 bytes.
constexpr std::size_t kMaxLineBytes = 65536;
constexpr std::size_t kChunkBytes = 65536;
// Output is handed to the stream in blocks of about this size: no per-line flush.
constexpr std::size_t kOutputBlockBytes = 65536;

// Splits a stream into lines (without '\n') reading fixed-size chunks.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in), chunk_(kChunkBytes) {}

  // The next line in `line` (valid until the next call) and whether it was longer than
  // kMaxLineBytes (its content is then dropped). False at the end of the input.
  bool next(std::string_view& line, bool& too_long) {
    pending_.clear();
    too_long = false;
    bool has_data = false;
    for (;;) {
      if (begin_ == end_ && !refill()) {
        if (!has_data) return false;
        line = pending_;  // last line without a newline
        return true;
      }
      has_data = true;
      const char* newline =
          static_cast<const char*>(std::memchr(chunk_.data() + begin_, '\n', end_ - begin_));
      const std::size_t stop = newline ? static_cast<std::size_t>(newline - chunk_.data()) : end_;
      const std::string_view piece(chunk_.data() + begin_, stop - begin_);
      begin_ = newline ? stop + 1 : end_;
      if (newline && pending_.empty() && !too_long && piece.size() <= kMaxLineBytes) {
        line = piece;  // whole line inside the chunk: no copy
        return true;
      }
      append(piece, too_long);
      if (newline) {
        line = pending_;
        return true;
      }
    }
  }

 private:
  bool refill() {
    if (!in_) return false;
    in_.read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
    begin_ = 0;
    end_ = static_cast<std::size_t>(in_.gcount());
    return end_ > 0;
  }

  void append(std::string_view piece, bool& too_long) {
    if (too_long) return;
    if (pending_.size() + piece.size() > kMaxLineBytes) {
      too_long = true;
      pending_.clear();
      return;
    }
    pending_.append(piece);
  }

  std::istream& in_;
  std::vector<char> chunk_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  std::string pending_;  // a line split across chunks
};

void appendResult(std::string& out, const char* decision, double scale) {
  char number[64];
  // to_chars, unlike printf, ignores the locale: the decimal point is always '.'.
  const auto result =
      std::to_chars(number, number + sizeof number, scale, std::chars_format::general, 17);
  out += decision;
  out += ' ';
  out.append(number, result.ptr);
  out += '\n';
}

void appendError(std::string& out, unsigned long long line_number, const std::string& reason) {
  out += "error ";
  out += std::to_string(line_number);
  out += ": ";
  out += reason;
  out += '\n';
}

// One --motion line: `contact T` (T the first contact time [s], 17 significant digits) or `clear`.
void appendMotion(std::string& out, const ellipse_collision::core::MotionLine& m) {
  const ellipse_collision::core::FirstContact c = ellipse_collision::core::firstContact(
      m.first, m.first_motion, m.second, m.second_motion, m.horizon);
  if (c.contact) {
    appendResult(out, "contact", c.time);
  } else {
    out += "clear\n";
  }
}

int run(bool motion) {
  std::ios::sync_with_stdio(false);
  std::cin.tie(nullptr);

  LineReader reader(std::cin);
  std::string out;
  out.reserve(kOutputBlockBytes + kMaxLineBytes);
  unsigned long long line_number = 0;
  bool any_bad = false;
  std::string_view line;
  bool too_long = false;
  while (reader.next(line, too_long)) {
    ++line_number;
    if (too_long) {
      appendError(out, line_number,
                  "line is longer than " + std::to_string(kMaxLineBytes) + " bytes");
      any_bad = true;
    } else if (motion) {
      const auto parsed = ellipse_collision::core::parseMotionLine(line);
      if (parsed.kind == ellipse_collision::core::MotionLine::Kind::Error) {
        appendError(out, line_number, parsed.error);
        any_bad = true;
      } else if (parsed.kind == ellipse_collision::core::MotionLine::Kind::Motion) {
        appendMotion(out, parsed);
      }
    } else {
      const PairLine parsed = ellipse_collision::core::parsePairLine(line);
      switch (parsed.kind) {
        case PairLine::Kind::Skip:
          break;
        case PairLine::Kind::Error:
          appendError(out, line_number, parsed.error);
          any_bad = true;
          break;
        case PairLine::Kind::Pair:
          appendResult(
              out, ellipse_collision::core::overlap(parsed.first, parsed.second) ? "collision" : "clear",
              ellipse_collision::core::contactScale(parsed.first, parsed.second));
          break;
      }
    }
    if (out.size() >= kOutputBlockBytes) {
      std::cout.write(out.data(), static_cast<std::streamsize>(out.size()));
      out.clear();
    }
  }
  std::cout.write(out.data(), static_cast<std::streamsize>(out.size()));
  std::cout.flush();

  if (std::cin.bad()) {
    std::cerr << "check_ellipses: error reading standard input after line " << line_number << "\n";
    return 2;
  }
  if (!std::cout) {
    std::cerr << "check_ellipses: error writing standard output\n";
    return 2;
  }
  return any_bad ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool motion = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--motion") {
      motion = true;
      continue;
    }
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    }
    std::cerr << "check_ellipses: unknown argument \"" << arg << "\"\n" << kUsage;
    return 2;
  }
  try {
    return run(motion);
  } catch (const std::exception& e) {
    // e.g. std::bad_alloc: report it rather than abort without a word.
    std::cerr << "check_ellipses: " << e.what() << "\n";
    return 2;
  }
}
