// rostest client: the services through the `rosservice call` command line, parsed from its YAML
// answer, as a user would call them; the node runs with rate 0 (node_cli.test), so its topics
// change only on a full ~check_collisions call.
#include <sys/wait.h>
#include <visualization_msgs/MarkerArray.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "marker_view.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace test {
namespace {

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

/// What `rosservice call` printed, read as the block YAML it prints for these services.
struct CliAnswer {
  int exit_status{-1};
  std::string output;
  /// Every scalar by its path, unquoted: "success", "unavailable_frames[0]",
  /// "warnings[1].point_a.y", "nearest.distance".
  std::map<std::string, std::string> flat;
  std::map<std::string, std::string> fields;                   ///< top-level scalars
  std::vector<std::map<std::string, std::string>> collisions;  ///< name_a, name_b, contact_scale
  std::vector<std::string> unavailable_frames;

  double number(const std::string& path) const {
    const auto found = flat.find(path);
    return found == flat.end() ? std::nan("") : std::stod(found->second);
  }
};

std::string unquote(const std::string& text) {
  if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') &&
      text.back() == text.front()) {
    return text.substr(1, text.size() - 2);
  }
  return text;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" ");
  const auto last = text.find_last_not_of(" \r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

CliAnswer parse(const std::string& output) {
  CliAnswer answer;
  answer.output = output;
  std::vector<std::string> lines;
  {
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
  }
  // Open maps and lists: where they are indented, their path, how many items a list has so far.
  struct Open {
    int indent;
    std::string path;
    int items;
  };
  std::vector<Open> open = {{-1, "", 0}};
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string content = trim(lines[i]);
    if (content.empty()) continue;
    const int indent = static_cast<int>(lines[i].find_first_not_of(' '));
    while (open.size() > 1 && open.back().indent >= indent) open.pop_back();
    Open& parent = open.back();
    std::string path;
    std::string value;
    if (content[0] == '-') {
      path = parent.path + "[" + std::to_string(parent.items++) + "]";
      value = trim(content.substr(1));
    } else {
      const auto colon = content.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = content.substr(0, colon);
      path = parent.path.empty() ? key : parent.path + "." + key;
      value = trim(content.substr(colon + 1));
    }
    if (value.empty()) {
      open.push_back({indent, path, 0});
      continue;
    }
    // A long double-quoted string goes on over lines that end in '\' (the line break is dropped)
    // and start with '\' (escaping the space after it).
    while (value.front() == '"' && (value.size() < 2 || value.back() != '"') &&
           i + 1 < lines.size()) {
      if (value.back() == '\\') value.pop_back();
      std::string next = trim(lines[++i]);
      if (!next.empty() && next.front() == '\\') next.erase(0, 1);
      value += next;
    }
    answer.flat[path] = unquote(value);
  }
  for (const auto& [path, value] : answer.flat) {
    if (path.find_first_of(".[") == std::string::npos) answer.fields[path] = value;
  }
  for (int k = 0; answer.flat.count("unavailable_frames[" + std::to_string(k) + "]"); ++k) {
    answer.unavailable_frames.push_back(
        answer.flat["unavailable_frames[" + std::to_string(k) + "]"]);
  }
  for (int k = 0; answer.flat.count("collisions[" + std::to_string(k) + "].name_a"); ++k) {
    std::map<std::string, std::string> pair;
    for (const char* key : {"name_a", "name_b", "contact_scale"}) {
      pair[key] = answer.flat["collisions[" + std::to_string(k) + "]." + key];
    }
    answer.collisions.push_back(pair);
  }
  return answer;
}

/// Runs `rosservice call <service> '<yaml>'` with the system's ROS tools first on PATH.
CliAnswer rosserviceCall(const std::string& service, const std::string& yaml) {
  const std::string command =
      "PATH=/usr/bin:$PATH rosservice call " + nodeTopic(service) + " '" + yaml + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return CliAnswer{};
  std::string output;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  CliAnswer answer = parse(output);
  answer.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return answer;
}

const std::map<std::string, std::string>* findCollision(const CliAnswer& answer,
                                                        const std::string& a,
                                                        const std::string& b) {
  for (const auto& pair : answer.collisions) {
    if (pair.count("name_a") && pair.at("name_a") == a && pair.count("name_b") &&
        pair.at("name_b") == b) {
      return &pair;
    }
  }
  return nullptr;
}

class NodeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(nodeTopic("check_collisions"), ros::Duration(30)));
    // tf is up once every frame of the helper is seen (camera_link is missing on purpose).
    ASSERT_TRUE(waitUntil(
        [] {
          CheckCollisions srv;
          srv.request.names = {"plate"};
          return ros::service::call(nodeTopic("check_collisions"), srv) && srv.response.success &&
                 srv.response.unavailable_frames == std::vector<std::string>{"camera_link"};
        },
        30.0));
  }
  ros::NodeHandle nh_;
};

TEST_F(NodeCli, CheckCollisionsAnswersOnTheCommandLine) {
  const CliAnswer answer = rosserviceCall("check_collisions", "{}");
  ASSERT_EQ(answer.exit_status, 0) << answer.output;
  EXPECT_EQ(answer.fields.at("success"), "True") << answer.output;
  EXPECT_EQ(answer.fields.at("in_collision"), "True");
  const auto* pair = findCollision(answer, "plate", "post_near");
  ASSERT_TRUE(pair) << answer.output;
  EXPECT_NEAR(std::stod(pair->at("contact_scale")), 0.25 / 0.3, 1e-9);
  EXPECT_EQ(answer.unavailable_frames, std::vector<std::string>{"camera_link"});
  EXPECT_CONTAINS(answer.fields.at("message"), "camera_link");
}

TEST_F(NodeCli, FitLinkEllipsesReadsTheUrdfFromTheParameterServer) {
  const CommandRun package = runCommand("rospack find ellipse_collision", 30);
  ASSERT_EQ(package.exit_status, 0) << package.output;
  const std::string dir = package.output.substr(0, package.output.find_last_not_of('\n') + 1);
  std::ifstream file(dir + "/test/fixtures/every_geometry.urdf");
  std::stringstream xml;
  xml << file.rdbuf();
  ASSERT_FALSE(xml.str().empty()) << dir;
  ros::param::set("/fit_test_robot_description", xml.str());
  const CommandRun run = runCommand(
      "rosrun ellipse_collision fit_link_ellipses --param /fit_test_robot_description "
      "--links sphere_link,box_link --padding 0.01",
      30);
  EXPECT_EQ(run.exit_status, 0) << run.output;
  EXPECT_CONTAINS(run.output, "links:\n  - {name: 'sphere_link', frame: 'sphere_link', x: ");
  EXPECT_CONTAINS(run.output, "  - {name: 'box_link', frame: 'box_link', x: ");
  EXPECT_CONTAINS(run.output, "padding: 0.01}");
  const CommandRun missing =
      runCommand("rosrun ellipse_collision fit_link_ellipses --param /no_such_description", 30);
  EXPECT_EQ(missing.exit_status, 1) << missing.output;
  EXPECT_CONTAINS(missing.output, "parameter '/no_such_description'");
}

TEST_F(NodeCli, QueryWithNameFilterOnTheCommandLine) {
  const CliAnswer answer = rosserviceCall(
      "check_collisions",
      "{names: [probe], query: [{name: probe, frame_id: odom, x: 2.0, y: 0.0, angle: 0.0, "
      "radius_x: 0.1, radius_y: 0.1, padding: 0.0}]}");
  ASSERT_EQ(answer.exit_status, 0) << answer.output;
  EXPECT_EQ(answer.fields.at("success"), "True") << answer.output;
  ASSERT_EQ(answer.collisions.size(), 1u) << answer.output;
  EXPECT_TRUE(findCollision(answer, "probe", "crate")) << answer.output;
}

TEST_F(NodeCli, AddAndRemoveObstaclesOnTheCommandLine) {
  CliAnswer answer = rosserviceCall("add_obstacles",
                                    "{obstacles: [{name: cli_box, frame_id: base_link, x: 0.0, y: "
                                    "0.0, angle: 0.0, radius_x: 0.2, "
                                    "radius_y: 0.2, padding: 0.0}]}");
  ASSERT_EQ(answer.fields["success"], "True") << answer.output;
  answer = rosserviceCall("check_collisions", "{names: [cli_box]}");
  EXPECT_TRUE(findCollision(answer, "body", "cli_box")) << answer.output;
  answer = rosserviceCall("remove_obstacles", "{names: [cli_box]}");
  EXPECT_EQ(answer.fields["success"], "True") << answer.output;
  answer = rosserviceCall("remove_obstacles", "{names: [cli_box]}");
  EXPECT_EQ(answer.fields["success"], "False") << answer.output;
  EXPECT_CONTAINS(answer.fields["message"], "names[0] = 'cli_box'");
}

TEST_F(NodeCli, BadRequestsAreAnswersOnTheCommandLine) {
  CliAnswer answer = rosserviceCall(
      "check_collisions",
      "{query: [{name: probe, frame_id: base_link, x: 0.0, y: 0.0, angle: 0.0, radius_x: -1.0, "
      "radius_y: 0.1, padding: 0.0}]}");
  EXPECT_EQ(answer.exit_status, 0) << answer.output;
  EXPECT_EQ(answer.fields["success"], "False") << answer.output;
  EXPECT_CONTAINS(answer.fields["message"], "query[0].radius_x = -1");

  answer = rosserviceCall("add_obstacles",
                          "{obstacles: [{name: nan_box, frame_id: base_link, x: .nan, y: 0.0, "
                          "angle: 0.0, radius_x: 0.1, "
                          "radius_y: 0.1, padding: 0.0}]}");
  EXPECT_EQ(answer.fields["success"], "False") << answer.output;
  EXPECT_CONTAINS(answer.fields["message"], "obstacles[0].x = nan");

  answer = rosserviceCall("remove_obstacles", "{names: [arm]}");
  EXPECT_EQ(answer.fields["success"], "False") << answer.output;
  EXPECT_CONTAINS(answer.fields["message"], "names[0] = 'arm'");

  answer = rosserviceCall("check_collisions", "{names: [ghost]}");
  EXPECT_EQ(answer.fields["success"], "False") << answer.output;
  EXPECT_CONTAINS(answer.fields["message"], "names[0] = 'ghost'");
}

TEST_F(NodeCli, WarningsAndMinDistanceOnTheCommandLine) {
  // test_scene.yaml: plate's rim at (0, 10.2) is 0.05 m from post's at (0, 10.25).
  const CliAnswer answer = rosserviceCall("check_collisions", "{min_distance_of: post}");
  ASSERT_EQ(answer.exit_status, 0) << answer.output;
  EXPECT_EQ(answer.fields.at("success"), "True") << answer.output;
  EXPECT_EQ(answer.flat.at("warnings[0].name_a"), "plate") << answer.output;
  EXPECT_EQ(answer.flat.at("warnings[0].name_b"), "post");
  EXPECT_NEAR(answer.number("warnings[0].distance"), 0.05, 1e-9);
  EXPECT_NEAR(answer.number("warnings[0].point_a.y"), 10.2, 1e-9);
  EXPECT_NEAR(answer.number("warnings[0].point_b.y"), 10.25, 1e-9);
  EXPECT_EQ(answer.flat.count("warnings[1].name_a"), 0u) << answer.output;
  EXPECT_EQ(answer.fields.at("has_min_distance"), "True");
  EXPECT_EQ(answer.flat.at("nearest.name_a"), "post");
  EXPECT_EQ(answer.flat.at("nearest.name_b"), "plate");
  EXPECT_NEAR(answer.number("nearest.distance"), 0.05, 1e-9);
  EXPECT_NEAR(answer.number("nearest.point_a.x"), 0.0, 1e-9);
  EXPECT_NEAR(answer.number("nearest.point_a.y"), 10.25, 1e-9);
  EXPECT_NEAR(answer.number("nearest.point_b.y"), 10.2, 1e-9);
  EXPECT_EQ(answer.number("nearest.point_b.z"), 0.0);

  const CliAnswer unknown = rosserviceCall("check_collisions", "{min_distance_of: ghost}");
  EXPECT_EQ(unknown.exit_status, 0) << unknown.output;
  EXPECT_EQ(unknown.fields.at("success"), "False") << unknown.output;
  EXPECT_EQ(unknown.fields.at("message"),
            "min_distance_of = 'ghost': expected the name of a link, obstacle or query (or empty), "
            "got an unknown name");
  EXPECT_EQ(unknown.fields.at("has_min_distance"), "False");
}

TEST_F(NodeCli, WithRateZeroTheTopicsChangeOnlyOnAFullCheck) {
  AddObstacles add;
  add.request.obstacles = {ellipseMsg("cli_rock", "base_link", 0.0, 0.0, 0.1, 0.1)};
  ASSERT_TRUE(ros::service::call(nodeTopic("add_obstacles"), add) && add.response.success);
  {
    // No periodic check: whatever state is latched was computed before cli_rock existed.
    Recorder<CollisionState> collisions(nh_, nodeTopic("collisions"));
    ros::Duration(1.0).sleep();
    for (const CollisionState& state : collisions.all()) {
      EXPECT_FALSE(mentions(state.collisions, "cli_rock"));
    }
  }
  ASSERT_EQ(rosserviceCall("check_collisions", "{}").fields["success"], "True");
  {
    // A late subscriber gets the state of that call from the latch alone.
    Recorder<CollisionState> collisions(nh_, nodeTopic("collisions"));
    EXPECT_TRUE(collisions.waitForLatest(
        [](const CollisionState& s) { return findPair(s.collisions, "body", "cli_rock"); }, 10.0));
    // And the markers: red triangles where cli_rock is, from what a late subscriber is sent.
    Recorder<visualization_msgs::MarkerArray> markers(nh_, nodeTopic("markers"));
    EXPECT_TRUE(waitUntil(
        [&] {
          return test::isRed(test::fillOf(MarkerView(markers.all()), "obstacles",
                                          test::makeEllipse(0.0, 0.0, 0.1, 0.1)));
        },
        10.0));
  }
  {
    // With rate 0 every full call is the topic's only update, so each one publishes, even with
    // nothing changed: the stamp says how fresh the state is.
    Recorder<CollisionState> collisions(nh_, nodeTopic("collisions"));
    ASSERT_TRUE(waitUntil([&] { return collisions.count() >= 1; }, 10.0));  // the latched one
    ros::ServiceClient check = nh_.serviceClient<CheckCollisions>(nodeTopic("check_collisions"));
    for (int call = 0; call < 2; ++call) {
      CheckCollisions srv;
      ASSERT_TRUE(check.call(srv) && srv.response.success);
    }
    ASSERT_TRUE(waitUntil([&] { return collisions.count() >= 3; }, 10.0))
        << "an unchanged full call was not published with rate 0";
    const std::vector<CollisionState> states = collisions.all();
    EXPECT_LT(states[states.size() - 2].header.stamp, states.back().header.stamp);
  }
  RemoveObstacles remove;
  remove.request.names = {"cli_rock"};
  ASSERT_TRUE(ros::service::call(nodeTopic("remove_obstacles"), remove) && remove.response.success);
  ASSERT_EQ(rosserviceCall("check_collisions", "{}").fields["success"], "True");
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  return ellipse_collision::test::runRostestClient(argc, argv, "test_node_cli");
}
