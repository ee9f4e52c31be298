// Runs the real check_ellipses binary (CHECK_ELLIPSES_BIN) through pipes and checks what it writes
// and its exit status.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#ifndef CHECK_ELLIPSES_BIN
#error "CHECK_ELLIPSES_BIN must be the path of the check_ellipses executable"
#endif

extern char** environ;

namespace {

// A hung child fails the test instead of hanging the test run.
constexpr auto kChildTimeout = std::chrono::seconds(120);

struct RunResult {
  int exit_status = -1;  // -1 unless the child exited normally
  int signal = 0;        // the signal that killed it, if one did
  bool timed_out = false;
  std::string out;  // standard output, unless a consumer took it
  std::string err;  // standard error
  long max_rss_kb = 0;
};

// Writes all of `data`; false once the reader has gone (EPIPE) or on another error.
bool writeAll(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t written = ::write(fd, data.data(), data.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

// Runs check_ellipses with `args`. `produce(fd)` writes its standard input from another thread
// (the pipe is closed when it returns); standard output goes to `consume` chunk by chunk, or into
// RunResult::out when no consumer is given.
RunResult runTool(const std::vector<std::string>& args, const std::function<void(int)>& produce,
                  const std::function<void(std::string_view)>& consume = nullptr) {
  RunResult result;
  // Writing to a child that has exited must fail with EPIPE, not kill the test.
  ::signal(SIGPIPE, SIG_IGN);

  int in_pipe[2];
  int out_pipe[2];
  if (::pipe2(in_pipe, O_CLOEXEC) != 0 || ::pipe2(out_pipe, O_CLOEXEC) != 0) {
    ADD_FAILURE() << "pipe2: " << std::strerror(errno);
    return result;
  }
  char err_path[] = "/tmp/test_check_ellipses_stderr_XXXXXX";
  const int err_fd = ::mkostemp(err_path, O_CLOEXEC);
  if (err_fd < 0) {
    ADD_FAILURE() << "mkostemp: " << std::strerror(errno);
    return result;
  }

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err_fd, STDERR_FILENO);
  std::vector<std::string> argv_strings = {CHECK_ELLIPSES_BIN};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_strings) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawn_error =
      ::posix_spawn(&pid, CHECK_ELLIPSES_BIN, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(in_pipe[0]);
  ::close(out_pipe[1]);
  ::close(err_fd);
  if (spawn_error != 0) {
    ::close(in_pipe[1]);
    ::close(out_pipe[0]);
    ::unlink(err_path);
    ADD_FAILURE() << "cannot run " << CHECK_ELLIPSES_BIN << ": " << std::strerror(spawn_error);
    return result;
  }

  std::thread writer([&produce, fd = in_pipe[1]] {
    produce(fd);
    ::close(fd);
  });

  const auto deadline = std::chrono::steady_clock::now() + kChildTimeout;
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd readable{out_pipe[0], POLLIN, 0};
    const int ready = left.count() > 0 ? ::poll(&readable, 1, static_cast<int>(left.count())) : 0;
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) {
      result.timed_out = true;
      ::kill(pid, SIGKILL);
      break;
    }
    const ssize_t got = ::read(out_pipe[0], buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    const std::string_view chunk(buffer.data(), static_cast<std::size_t>(got));
    if (consume) {
      consume(chunk);
    } else {
      result.out.append(chunk);
    }
  }
  ::close(out_pipe[0]);  // a child still writing now gets EPIPE rather than blocking
  writer.join();

  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) result.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
  result.max_rss_kb = usage.ru_maxrss;
  result.err = readFile(err_path);
  ::unlink(err_path);
  EXPECT_FALSE(result.timed_out) << "check_ellipses ran longer than " << kChildTimeout.count()
                                 << " s and was killed";
  return result;
}

RunResult runTool(const std::vector<std::string>& args, const std::string& input) {
  return runTool(args, [&input](int fd) { writeAll(fd, input); });
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The contact scale of an output line `collision T` / `clear T`, checking the decision word.
double scaleOf(const std::string& line, const std::string& decision) {
  const std::string prefix = decision + " ";
  EXPECT_EQ(line.rfind(prefix, 0), 0u)
      << "expected \"" << decision << " T\", got \"" << line << "\"";
  if (line.rfind(prefix, 0) != 0) return std::nan("");
  const std::string number = line.substr(prefix.size());
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  EXPECT_TRUE(!number.empty() && *end == '\0') << "T is not a number in \"" << line << "\"";
  return value;
}

void expectScale(const std::string& line, const std::string& decision, double expected) {
  EXPECT_NEAR(scaleOf(line, decision), expected, 1e-12 * std::max(1.0, expected)) << line;
}

std::string examplePath() {
  // This file is <repo>/test/core/test_check_ellipses.cpp; the example lives in <repo>/examples.
  std::string path = __FILE__;
  const std::string suffix = "test/core/test_check_ellipses.cpp";
  if (path.size() < suffix.size() ||
      path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0) {
    ADD_FAILURE() << "cannot locate the repository from __FILE__ = " << path;
    return {};
  }
  return path.substr(0, path.size() - suffix.size()) + "examples/pairs.txt";
}

// ------------------------------------------------------------------------------ command line

TEST(CheckEllipses, HelpPrintsUsageOnStdoutAndExitsZero) {
  for (const char* flag : {"--help", "-h"}) {
    const RunResult run = runTool({flag}, std::string("0 0 1 1 0 1 0 1 1 0\n"));
    EXPECT_EQ(run.exit_status, 0) << flag;
    EXPECT_EQ(run.out.rfind("usage: check_ellipses", 0), 0u) << run.out;
    EXPECT_NE(run.out.find("cx1 cy1 rx1 ry1 angle1 cx2 cy2 rx2 ry2 angle2"), std::string::npos);
    EXPECT_EQ(run.out.find("collision 0.5"), std::string::npos) << "--help must not read input";
  }
}

TEST(CheckEllipses, UnknownArgumentIsAUsageErrorWithStatusTwo) {
  const RunResult run = runTool({"--frobnicate"}, std::string());
  EXPECT_EQ(run.exit_status, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_NE(run.err.find("unknown argument \"--frobnicate\""), std::string::npos) << run.err;
}

// ------------------------------------------------------------------------------ good input

TEST(CheckEllipses, EmptyInputWritesNothingAndExitsZero) {
  const RunResult run = runTool({}, std::string());
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "");
}

TEST(CheckEllipses, EachPairWritesDecisionAndContactScaleInInputOrder) {
  const RunResult run = runTool({},
                                "0 0 1 1 0  1 0 1 1 0\n"       // unit circles 1 m apart
                                "0 0 1 1 0  3 0 1 1 0\n"       // 3 m apart
                                "0 0 1 1 0  0 4.5 1 3 0\n"     // gap on the y axis: 1 t = 4.5 - 3 t
                                "5 5 2 1 0.7  5 5 1 2 -0.2\n"  // coincident centres
                                "0 0 2 0.1 0  0 0.5 2 0.1 0\n"  // parallel rods 0.5 m apart
                                "-1 -1 0.5 0.5 0  1 1 0.5 0.5 0\n");
  EXPECT_EQ(run.exit_status, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 6u) << run.out;
  expectScale(lines[0], "collision", 0.5);
  expectScale(lines[1], "clear", 1.5);
  expectScale(lines[2], "clear", 1.125);
  EXPECT_EQ(lines[3], "collision 0");
  expectScale(lines[4], "clear", 2.5);
  expectScale(lines[5], "clear", std::sqrt(8.0));
}

TEST(CheckEllipses, ContactScaleIsWrittenWithSeventeenSignificantDigits) {
  // Unit circles 2/3 m apart: T = 1/3, which no shorter decimal gives back exactly.
  const RunResult run = runTool({}, std::string("0 0 1 1 0 0.66666666666666663 0 1 1 0\n"));
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 1u) << run.out;
  expectScale(lines[0], "collision", 1.0 / 3.0);
  const std::string number = lines[0].substr(std::string("collision ").size());
  ASSERT_EQ(number.rfind("0.", 0), 0u) << number;
  std::string digits = number.substr(2);
  digits.erase(0, digits.find_first_not_of('0'));  // leading zeros are not significant
  EXPECT_EQ(digits.size(), 17u) << number;
  EXPECT_EQ(digits.find_first_not_of("0123456789"), std::string::npos) << number;
}

TEST(CheckEllipses, CommentsBlankLinesAndCrLfEndingsWriteNothingExtra) {
  const RunResult run = runTool({},
                                "# header comment\r\n"
                                "\r\n"
                                "   \t\n"
                                "  # indented comment\n"
                                "0 0 1 1 0\t1 0 1 1 0\r\n"
                                "\n"
                                "0 0 1 1 0 3 0 1 1 0\r\n");
  EXPECT_EQ(run.exit_status, 0) << run.out;
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 2u) << run.out;
  expectScale(lines[0], "collision", 0.5);
  expectScale(lines[1], "clear", 1.5);
}

TEST(CheckEllipses, LastLineWithoutNewlineIsChecked) {
  const RunResult run = runTool({}, std::string("0 0 1 1 0 1 0 1 1 0\n0 0 1 1 0 3 0 1 1 0"));
  EXPECT_EQ(run.exit_status, 0);
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 2u) << run.out;
  expectScale(lines[1], "clear", 1.5);
}

// ------------------------------------------------------------------------------ bad input

TEST(CheckEllipses, BadLinesWriteErrorsInPlaceWithLineNumbersAndTheRestIsStillChecked) {
  const RunResult run = runTool({},
                                "# line 1 is a comment\n"
                                "0 0 1 1 0 1 0 1 1 0\n"
                                "0 0 1 1 0 1 0 1 1\n"
                                "\n"
                                "0 0 abc 1 0 1 0 1 1 0\n"
                                "0 0 1 1 0 3 0 1 1 0\n"
                                "0 0 -1 1 0 3 0 1 1 0\n"
                                "0 0 1 1 0 3 0 1 nan 0\n"
                                "0 0 1 1 0 1 0 1 1 0\n");
  EXPECT_EQ(run.exit_status, 1);
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 7u) << run.out;
  expectScale(lines[0], "collision", 0.5);
  EXPECT_EQ(lines[1], "error 3: expected 10 fields, got 9");
  EXPECT_EQ(lines[2], "error 5: field 3 (rx1) is not a number: \"abc\"");
  expectScale(lines[3], "clear", 1.5);
  EXPECT_EQ(lines[4].rfind("error 7: ellipse 1: ", 0), 0u) << lines[4];
  EXPECT_NE(lines[4].find("-1"), std::string::npos) << lines[4];
  EXPECT_EQ(lines[5].rfind("error 8: ellipse 2: ", 0), 0u) << lines[5];
  EXPECT_NE(lines[5].find("nan"), std::string::npos) << lines[5];
  expectScale(lines[6], "collision", 0.5);
}

TEST(CheckEllipses, OverlongLineIsAnErrorAndTheNextLineIsStillChecked) {
  const std::string overlong(200000, '1');
  const RunResult run = runTool({}, overlong + "\n0 0 1 1 0 3 0 1 1 0\n" + overlong);
  EXPECT_EQ(run.exit_status, 1);
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 3u) << run.out.substr(0, 1000);
  EXPECT_EQ(lines[0], "error 1: line is longer than 65536 bytes");
  expectScale(lines[1], "clear", 1.5);
  EXPECT_EQ(lines[2], "error 3: line is longer than 65536 bytes");
}

TEST(CheckEllipses, LongGoodLineSplitAcrossReadChunksIsChecked) {
  // Padding pushes the line across the tool's 64 KiB read chunks without exceeding the line limit.
  const std::string padding(30000, ' ');  // a line of ~60 kB
  std::string input;
  for (int i = 0; i < 4; ++i) input += padding + "0 0 1 1 0" + padding + "3 0 1 1 0" + "\n";
  const RunResult run = runTool({}, input);
  EXPECT_EQ(run.exit_status, 0) << run.out;
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 4u) << run.out;
  for (const std::string& line : lines) expectScale(line, "clear", 1.5);
}

// ------------------------------------------------------------------------------ example file

TEST(CheckEllipses, ExampleFileGivesTheAnswersItsCommentsState) {
  const std::string input = readFile(examplePath());
  ASSERT_FALSE(input.empty()) << "cannot read " << examplePath();
  const RunResult run = runTool({}, input);
  EXPECT_EQ(run.exit_status, 1) << "the example has one deliberate bad line";
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 10u) << run.out;
  expectScale(lines[0], "collision", 0.5);
  expectScale(lines[1], "clear", 1.5);
  expectScale(lines[2], "collision", 1.0);
  EXPECT_LT(scaleOf(lines[3], "collision"), 1.0);
  expectScale(lines[4], "clear", 1.25);
  expectScale(lines[5], "collision", 0.5 / 2.3);
  EXPECT_LT(scaleOf(lines[6], "collision"), 1.0);
  expectScale(lines[7], "clear", 2.5);
  EXPECT_EQ(lines[8].rfind("error ", 0), 0u) << lines[8];
  EXPECT_NE(lines[8].find(": ellipse 1: "), std::string::npos) << lines[8];
  expectScale(lines[9], "clear", 2.0);
}

// ------------------------------------------------------------------------------ streaming

// Line i of the generated input and the output word it must produce ("" for a comment).
struct GeneratedLine {
  std::string text;
  const char* expected;
};

GeneratedLine generatedLine(long i) {
  if (i % 1000 == 999) return {"0.000000000 0.000000000 1.000000000", "error"};
  if (i % 100 == 50) return {"# comment line " + std::to_string(i), ""};
  // Numbers are padded to about 100 bytes a line, so that 10^6 lines are ~100 MB: holding the
  // input would show in the child's peak memory.
  switch (i % 6) {
    case 0:
      return {
          "0.000000000 0.000000000 1.000000000 1.000000000 0.000000000 "
          "1.000000000 0.000000000 1.000000000 1.000000000 0.000000000",
          "collision"};
    case 1:
      return {
          "0.000000000 0.000000000 1.000000000 1.000000000 0.000000000 "
          "3.000000000 0.000000000 1.000000000 1.000000000 0.000000000",
          "clear"};
    case 2:  // thin ellipse along x reaching a circle at x = 2.5
      return {
          "0.000000000 0.000000000 2.000000000 0.500000000 0.000000000 "
          "2.500000000 0.000000000 1.000000000 1.000000000 0.000000000",
          "collision"};
    case 3:  // the same ellipse turned to point along y misses it
      return {
          "0.000000000 0.000000000 2.000000000 0.500000000 1.570796327 "
          "2.500000000 0.000000000 1.000000000 1.000000000 0.000000000",
          "clear"};
    case 4:  // contained
      return {
          "1.000000000 -1.00000000 3.000000000 2.000000000 0.300000000 "
          "1.200000000 -0.90000000 0.500000000 0.250000000 -1.00000000",
          "collision"};
    default:  // parallel rods
      return {
          "0.000000000 0.000000000 2.000000000 0.100000000 0.000000000 "
          "0.000000000 0.500000000 2.000000000 0.100000000 0.000000000",
          "clear"};
  }
}

TEST(CheckEllipses, MillionLinesStreamThroughAPipeInBoundedMemory) {
  constexpr long kLines = 1000000;
  constexpr long kMaxRssKb = 64 * 1024;

  long input_bytes = 0;
  auto produce = [&input_bytes](int fd) {
    std::string block;
    for (long i = 0; i < kLines; ++i) {
      block += generatedLine(i).text;
      block += '\n';
      if (block.size() >= (1 << 16) || i + 1 == kLines) {
        input_bytes += static_cast<long>(block.size());
        if (!writeAll(fd, block)) return;
        block.clear();
      }
    }
  };

  // Output lines are checked as they arrive, against the input line each must answer.
  long next_input = 0;
  long output_lines = 0;
  long mismatches = 0;
  std::string first_mismatch;
  std::string partial;
  auto checkLine = [&](const std::string& line) {
    while (next_input < kLines && generatedLine(next_input).expected[0] == '\0') ++next_input;
    ++output_lines;
    const std::string expected = next_input < kLines ? generatedLine(next_input).expected : "";
    const std::string word = line.substr(0, line.find(' '));
    bool good = !expected.empty() && word == expected;
    if (good && expected == "error") {
      good = line == "error " + std::to_string(next_input + 1) + ": expected 10 fields, got 3";
    }
    if (!good && mismatches++ == 0) {
      first_mismatch = "input line " + std::to_string(next_input + 1) + " expected \"" + expected +
                       "\", got \"" + line + "\"";
    }
    ++next_input;
  };
  auto consume = [&](std::string_view chunk) {
    for (;;) {
      const std::size_t newline = chunk.find('\n');
      if (newline == std::string_view::npos) {
        partial.append(chunk);
        return;
      }
      partial.append(chunk.substr(0, newline));
      checkLine(partial);
      partial.clear();
      chunk.remove_prefix(newline + 1);
    }
  };

  const auto start = std::chrono::steady_clock::now();
  const RunResult run = runTool({}, produce, consume);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("seconds", std::to_string(seconds));
  RecordProperty("max_rss_kb", std::to_string(run.max_rss_kb));
  std::printf("10^6 lines (%.1f MB) in %.2f s, child peak RSS %ld kB\n",
              static_cast<double>(input_bytes) / 1e6, seconds, run.max_rss_kb);

  long expected_outputs = 0;
  for (long i = 0; i < kLines; ++i) expected_outputs += generatedLine(i).expected[0] != '\0';
  EXPECT_EQ(input_bytes, [] {
    long bytes = 0;
    for (long i = 0; i < kLines; ++i) bytes += static_cast<long>(generatedLine(i).text.size()) + 1;
    return bytes;
  }()) << "the whole input must reach the tool";
  EXPECT_GT(input_bytes, 90'000'000L);
  EXPECT_EQ(partial, "") << "output must end with a newline";
  EXPECT_EQ(output_lines, expected_outputs);
  EXPECT_EQ(mismatches, 0) << first_mismatch;
  EXPECT_EQ(run.exit_status, 1) << "the input has bad lines; stderr: " << run.err;
  EXPECT_GT(run.max_rss_kb, 0);
  EXPECT_LT(run.max_rss_kb, kMaxRssKb);
}

}  // namespace

// catkin_add_gtest links gtest but not gtest_main.
int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

// ------------------------------------------------------------------------------ --motion

// Unit circles 4 m apart closing at 2 m/s touch when the gap of 2 m is gone: t = 1 s, by hand.
// Circles moving apart, or too slow to close the gap within the horizon, stay clear.
TEST(CheckEllipses, MotionLinesAnswerFirstContactTimeOrClear) {
  const RunResult run = runTool({"--motion"},
                                "# cx cy rx ry angle vx vy w (twice), horizon\n"
                                "0 0 1 1 0  1 0 0  4 0 1 1 0  -1 0 0  10\n"
                                "0 0 1 1 0  -1 0 0  4 0 1 1 0  1 0 0  10\n"
                                "0 0 1 1 0  0.1 0 0  4 0 1 1 0  0 0 0  10\n"
                                "0 0 1 1 0  0 0 0  1 0 1 1 0  0 0 0  5\n"
                                "0 0 1 1 0 0 0 0 3 0 1 1 0 0 0 0 -4\n"
                                "0 0 1 1 0 0 0 0 3 0 1 1 0 0 0\n");
  EXPECT_EQ(run.exit_status, 1);
  const std::vector<std::string> lines = splitLines(run.out);
  ASSERT_EQ(lines.size(), 6u) << run.out;
  ASSERT_EQ(lines[0].rfind("contact ", 0), 0u) << lines[0];
  EXPECT_NEAR(std::stod(lines[0].substr(8)), 1.0, 1e-12);
  EXPECT_EQ(lines[1], "clear");
  EXPECT_EQ(lines[2], "clear");  // 0.1 m/s closes 1 m of the 2 m gap in 10 s
  EXPECT_EQ(lines[3], "contact 0");  // overlapping at t = 0
  EXPECT_EQ(lines[4], "error 6: horizon = -4 must be >= 0");
  EXPECT_EQ(lines[5].rfind("error 7: ", 0), 0u) << lines[5];
}
