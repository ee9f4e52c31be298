// Name rules of the stored ellipses (links, configured, service and topic obstacles); no master.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_registry.h"

namespace ellipse_collision::app {
namespace {

EllipseSpec spec(const std::string& name, double x = 0.0) {
  EllipseSpec s;
  s.name = name;
  s.frame_id = "map";
  s.x = x;
  s.radius_x = 0.1;
  s.radius_y = 0.1;
  return s;
}

EllipseRegistry makeRegistry() {
  return EllipseRegistry({spec("arm"), spec("hand")}, {spec("table")});
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(EllipseRegistry, ConfiguredEllipsesHaveTheirRoles) {
  const EllipseRegistry registry = makeRegistry();
  EXPECT_EQ(registry.entries().at("arm").role(), core::EllipseRole::Link);
  EXPECT_EQ(registry.entries().at("table").role(), core::EllipseRole::Obstacle);
  EXPECT_EQ(registry.count(EllipseSource::ConfiguredLink), 2u);
  EXPECT_EQ(registry.count(EllipseSource::ConfiguredObstacle), 1u);
}

TEST(EllipseRegistry, ServiceObstacleIsAddedReplacedAndRemoved) {
  EllipseRegistry registry = makeRegistry();
  EXPECT_EQ(registry.addObstacles({spec("box", 1.0)}, "obstacles"), "");
  EXPECT_EQ(registry.entries().at("box").spec.x, 1.0);
  EXPECT_EQ(registry.addObstacles({spec("box", 2.0)}, "obstacles"), "");
  EXPECT_EQ(registry.entries().at("box").spec.x, 2.0);
  EXPECT_EQ(registry.count(EllipseSource::ServiceObstacle), 1u);
  EXPECT_EQ(registry.removeObstacles({"box"}, "names"), "");
  EXPECT_FALSE(registry.contains("box"));
}

TEST(EllipseRegistry, ConfiguredObstacleCanBeReplacedAndRemoved) {
  EllipseRegistry registry = makeRegistry();
  EXPECT_EQ(registry.addObstacles({spec("table", 5.0)}, "obstacles"), "");
  EXPECT_EQ(registry.entries().at("table").spec.x, 5.0);
  EXPECT_EQ(registry.removeObstacles({"table"}, "names"), "");
  EXPECT_FALSE(registry.contains("table"));
}

TEST(EllipseRegistry, LinkCanNeitherBeReplacedNorRemoved) {
  EllipseRegistry registry = makeRegistry();
  EXPECT_CONTAINS(registry.addObstacles({spec("box"), spec("hand")}, "obstacles"),
                  "obstacles[1].name = 'hand'");
  EXPECT_FALSE(registry.contains("box"));  // all or nothing
  const std::string refused = registry.removeObstacles({"arm"}, "names");
  EXPECT_CONTAINS(refused, "names[0] = 'arm'");
  EXPECT_CONTAINS(refused, "configured link");
  EXPECT_TRUE(registry.contains("arm"));
  EXPECT_EQ(registry.entries().at("hand").role(), core::EllipseRole::Link);
}

TEST(EllipseRegistry, RemovingAnUnknownNameRemovesNothing) {
  EllipseRegistry registry = makeRegistry();
  const std::string refused = registry.removeObstacles({"table", "ghost"}, "names");
  EXPECT_CONTAINS(refused, "names[1] = 'ghost'");
  EXPECT_CONTAINS(refused, "unknown name");
  EXPECT_TRUE(registry.contains("table"));
}

TEST(EllipseRegistry, EmptyAndDuplicateNamesInARequestAreRefused) {
  EllipseRegistry registry = makeRegistry();
  EXPECT_CONTAINS(registry.addObstacles({spec("")}, "obstacles"), "obstacles[0].name = ''");
  EXPECT_CONTAINS(registry.addObstacles({spec("a"), spec("a")}, "obstacles"),
                  "obstacles[1].name = 'a'");
  EXPECT_FALSE(registry.contains("a"));
  EXPECT_CONTAINS(registry.removeObstacles({"table", "table"}, "names"), "names[1] = 'table'");
  EXPECT_CONTAINS(registry.removeObstacles({""}, "names"), "names[0] = ''");
  EXPECT_TRUE(registry.contains("table"));
}

TEST(EllipseRegistry, TopicMessageReplacesOnlyTheTopicObstacles) {
  EllipseRegistry registry = makeRegistry();
  ASSERT_EQ(registry.addObstacles({spec("box")}, "obstacles"), "");
  EXPECT_EQ(registry.replaceTopicObstacles({spec("rock1"), spec("rock2")}, "ellipses"), "");
  EXPECT_EQ(registry.count(EllipseSource::TopicObstacle), 2u);
  EXPECT_EQ(registry.replaceTopicObstacles({spec("rock3")}, "ellipses"), "");
  EXPECT_FALSE(registry.contains("rock1"));
  EXPECT_FALSE(registry.contains("rock2"));
  EXPECT_TRUE(registry.contains("rock3"));
  EXPECT_TRUE(registry.contains("box"));
  EXPECT_TRUE(registry.contains("table"));
  EXPECT_EQ(registry.replaceTopicObstacles({}, "ellipses"), "");
  EXPECT_EQ(registry.count(EllipseSource::TopicObstacle), 0u);
}

TEST(EllipseRegistry, TopicAndServiceDoNotTakeEachOthersNames) {
  EllipseRegistry registry = makeRegistry();
  ASSERT_EQ(registry.replaceTopicObstacles({spec("rock")}, "ellipses"), "");
  EXPECT_CONTAINS(registry.addObstacles({spec("rock")}, "obstacles"), "obstacles[0].name = 'rock'");
  EXPECT_CONTAINS(registry.replaceTopicObstacles({spec("rock"), spec("table")}, "ellipses"),
                  "ellipses[1].name = 'table'");
  // The refused message left the previous topic obstacles in place.
  EXPECT_EQ(registry.entries().at("rock").source, EllipseSource::TopicObstacle);
  EXPECT_CONTAINS(registry.replaceTopicObstacles({spec("arm")}, "ellipses"), "configured link");
}

TEST(EllipseRegistry, TopicObstacleCanBeRemovedByTheService) {
  EllipseRegistry registry = makeRegistry();
  ASSERT_EQ(registry.replaceTopicObstacles({spec("rock")}, "ellipses"), "");
  EXPECT_EQ(registry.removeObstacles({"rock"}, "names"), "");
  EXPECT_FALSE(registry.contains("rock"));
}

TEST(EllipseRegistry, TopicObstaclesOlderThanTheTimeoutAreDropped) {
  EllipseRegistry registry = makeRegistry();
  ASSERT_EQ(registry.replaceTopicObstacles({spec("rock1"), spec("rock2")}, "ellipses", 100.0), "");
  ASSERT_EQ(registry.addObstacles({spec("box")}, "obstacles"), "");
  EXPECT_EQ(registry.topicStamp(), 100.0);
  EXPECT_EQ(registry.dropExpiredTopicObstacles(1000.0, 0.0), 0u) << "timeout 0 = never";
  EXPECT_EQ(registry.dropExpiredTopicObstacles(101.0, 1.0), 0u) << "exactly the timeout is kept";
  EXPECT_TRUE(registry.contains("rock1"));
  EXPECT_EQ(registry.dropExpiredTopicObstacles(101.5, 1.0), 2u);
  EXPECT_FALSE(registry.contains("rock1"));
  EXPECT_FALSE(registry.contains("rock2"));
  EXPECT_TRUE(registry.contains("box")) << "service obstacles never time out";
  EXPECT_TRUE(registry.contains("table"));
  EXPECT_EQ(registry.dropExpiredTopicObstacles(102.0, 1.0), 0u) << "nothing left to drop";
  // A new message brings them back.
  ASSERT_EQ(registry.replaceTopicObstacles({spec("rock3")}, "ellipses", 101.9), "");
  EXPECT_EQ(registry.dropExpiredTopicObstacles(102.0, 1.0), 0u);
  EXPECT_TRUE(registry.contains("rock3"));
}

TEST(EllipseRegistry, RuntimeObstaclesBeyondTheLimitsAreRefusedNamingTheLimit) {
  EllipseRegistry registry({spec("arm")}, {spec("table")}, RegistryLimits{3, 8});
  EXPECT_EQ(registry.addObstacles({spec("a"), spec("b")}, "obstacles"), "");
  EXPECT_EQ(registry.addObstacles({spec("a"), spec("b")}, "obstacles"), "")
      << "replacing does not count twice";
  EXPECT_EQ(registry.addObstacles({spec("c"), spec("d")}, "obstacles"),
            "obstacles: expected at most max_obstacles = 3 runtime obstacles (service and topic) in "
            "total, got 4");
  EXPECT_FALSE(registry.contains("c")) << "all or nothing";
  EXPECT_EQ(registry.replaceTopicObstacles({spec("r1"), spec("r2")}, "ellipses"),
            "ellipses: expected at most max_obstacles = 3 runtime obstacles (service and topic) in "
            "total, got 4");
  EXPECT_EQ(registry.replaceTopicObstacles({spec("r1")}, "ellipses"), "");
  EXPECT_EQ(registry.addObstacles({spec("123456789")}, "obstacles"),
            "obstacles[0].name: expected at most max_name_length = 8 characters, got 9");
  EXPECT_EQ(registry.replaceTopicObstacles({spec("r"), spec("123456789")}, "ellipses"),
            "ellipses[1].name: expected at most max_name_length = 8 characters, got 9");
  EXPECT_EQ(registry.removeObstacles({"a"}, "names"), "");
  EXPECT_EQ(registry.addObstacles({spec("12345678")}, "obstacles"), "");
}

TEST(EllipseRegistry, CountsAndServiceObstaclesFollowEveryChangeAsAScanOfTheEntriesFindsThem) {
  EllipseRegistry registry = makeRegistry();
  std::mt19937 rng(7);
  const auto name = [&rng] {
    static const char* const kNames[] = {"arm", "table", "a", "b", "c", "d", "e", "f"};
    return std::string(kNames[std::uniform_int_distribution<int>(0, 7)(rng)]);
  };
  for (int step = 0; step < 2000; ++step) {
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
      case 0:
        registry.addObstacles({spec(name())}, "o");
        break;
      case 1:
        registry.removeObstacles({name()}, "n");
        break;
      case 2: {
        std::vector<EllipseSpec> topic;
        for (int k = std::uniform_int_distribution<int>(0, 2)(rng); k > 0; --k) {
          topic.push_back(spec(name()));
        }
        registry.replaceTopicObstacles(topic, "e", step);
        break;
      }
      case 3:
        registry.dropExpiredTopicObstacles(step, 1.0);
        break;
      default: {
        StoredObstacles stored;
        stored.service = {spec(name())};
        stored.topic = {spec(name())};
        registry.restore(stored);  // refused whole on a clash: the counts too
      }
    }
    for (const EllipseSource source :
         {EllipseSource::ConfiguredLink, EllipseSource::ConfiguredObstacle,
          EllipseSource::ServiceObstacle, EllipseSource::TopicObstacle}) {
      std::size_t scanned = 0;
      for (const auto& entry : registry.entries()) scanned += entry.second.source == source ? 1 : 0;
      ASSERT_EQ(registry.count(source), scanned)
          << "step " << step << ", source " << static_cast<int>(source);
    }
    std::vector<std::string> service, listed;
    for (const auto& entry : registry.entries()) {
      if (entry.second.source == EllipseSource::ServiceObstacle) service.push_back(entry.first);
    }
    for (const EllipseSpec& spec : registry.serviceObstacles().service) listed.push_back(spec.name);
    ASSERT_EQ(listed, service) << "step " << step;
  }
}

// The registry remembers where the last message's names are; any change in between must not
// leave it pointing at entries that went away or changed hands.
TEST(EllipseRegistry, AMessageInTheLastOnesOrderAfterOtherChangesFindsTheEntriesAsTheyAreNow) {
  EllipseRegistry registry = makeRegistry();
  const std::vector<EllipseSpec> message = {spec("r1", 1.0), spec("r2", 2.0), spec("r3", 3.0)};
  ASSERT_EQ(registry.replaceTopicObstacles(message, "ellipses"), "");
  ASSERT_EQ(registry.removeObstacles({"r2"}, "names"), "");
  ASSERT_EQ(registry.replaceTopicObstacles(message, "ellipses"), "");
  ASSERT_TRUE(registry.contains("r2")) << "removed by the service, back with the next message";
  EXPECT_EQ(registry.entries().at("r2").spec.x, 2.0);
  EXPECT_EQ(registry.count(EllipseSource::TopicObstacle), 3u);

  ASSERT_EQ(registry.removeObstacles({"r2"}, "names"), "");
  ASSERT_EQ(registry.addObstacles({spec("r2", 9.0)}, "obstacles"), "");
  EXPECT_CONTAINS(registry.replaceTopicObstacles(message, "ellipses"), "~add_obstacles");
  EXPECT_EQ(registry.entries().at("r2").source, EllipseSource::ServiceObstacle);
  EXPECT_EQ(registry.entries().at("r2").spec.x, 9.0);
  ASSERT_EQ(registry.removeObstacles({"r2"}, "names"), "");

  ASSERT_EQ(registry.replaceTopicObstacles(message, "ellipses", 10.0), "");
  ASSERT_EQ(registry.dropExpiredTopicObstacles(20.0, 1.0), 3u);
  ASSERT_EQ(registry.replaceTopicObstacles(message, "ellipses", 20.0), "");
  EXPECT_EQ(registry.count(EllipseSource::TopicObstacle), 3u);
  for (const EllipseSpec& s : message) {
    ASSERT_TRUE(registry.contains(s.name)) << s.name;
    EXPECT_EQ(registry.entries().at(s.name).spec.x, s.x);
  }
}

TEST(EllipseRegistry, ACopyAndTheOriginalTakeTheSameMessageEachIntoItsOwnEntries) {
  EllipseRegistry original = makeRegistry();
  const std::vector<EllipseSpec> first = {spec("r1", 1.0), spec("r2", 2.0)};
  const std::vector<EllipseSpec> next = {spec("r1", 5.0), spec("r2", 6.0)};
  ASSERT_EQ(original.replaceTopicObstacles(first, "ellipses"), "");
  EllipseRegistry copy = original;
  ASSERT_EQ(copy.replaceTopicObstacles(next, "ellipses"), "");
  EXPECT_EQ(copy.entries().at("r1").spec.x, 5.0);
  EXPECT_EQ(original.entries().at("r1").spec.x, 1.0) << "the copy wrote into the original";
  ASSERT_EQ(original.replaceTopicObstacles(next, "ellipses"), "");
  EXPECT_EQ(original.entries().at("r2").spec.x, 6.0);
  EllipseRegistry moved = std::move(original);
  ASSERT_EQ(moved.replaceTopicObstacles(first, "ellipses"), "");
  EXPECT_EQ(moved.entries().at("r2").spec.x, 2.0);
  EXPECT_EQ(moved.count(EllipseSource::TopicObstacle), 2u);
}

// Topic messages that mostly repeat the last one's names (a perception stream), against a model
// of the documented rule: an accepted message leaves exactly its obstacles, with its values, as
// topic obstacles; every other entry stays as it was; a refused one changes nothing.
TEST(EllipseRegistry, TopicMessagesLeaveExactlyTheirObstaclesWithTheirValues) {
  EllipseRegistry registry = makeRegistry();
  std::map<std::string, std::pair<EllipseSource, double>> model;  // name -> (source, x)
  for (const auto& [name, entry] : registry.entries()) model[name] = {entry.source, entry.spec.x};
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pick(0, 14);
  const auto nameOf = [](int k) {
    return k == 0 ? std::string("table") : k == 1 ? std::string("arm") : "r" + std::to_string(k);
  };
  int accepted = 0, refused = 0;
  std::vector<EllipseSpec> last_message;
  for (int step = 0; step < 3000; ++step) {
    if (step % 10 == 9) {  // now and then the service takes or frees a name
      const std::string name = nameOf(pick(rng));
      const bool add = rng() % 2 == 0;
      const std::string error = add ? registry.addObstacles({spec(name, step)}, "o")
                                    : registry.removeObstacles({name}, "n");
      if (error.empty() && add) model[name] = {EllipseSource::ServiceObstacle, step};
      if (error.empty() && !add) model.erase(name);
      continue;
    }
    std::vector<EllipseSpec> message;
    if (rng() % 2 == 0) {
      // A stream: the last message's names in the same order with new values, now and then one
      // left out or one more at the end.
      message = last_message;
      for (EllipseSpec& s : message) s.x = step + 0.5;
      if (!message.empty() && rng() % 4 == 0) message.erase(message.begin() + rng() % message.size());
      if (rng() % 4 == 0) {
        const std::string extra = nameOf(pick(rng));
        bool taken = false;
        for (const EllipseSpec& s : message) taken = taken || s.name == extra;
        if (!taken) message.push_back(spec(extra, step + 0.75));
      }
    } else {
      std::set<int> used;
      for (int k = std::uniform_int_distribution<int>(0, 8)(rng); k > 0; --k) {
        const int which = pick(rng);
        if (used.insert(which).second) message.push_back(spec(nameOf(which), step + 0.25 * k));
      }
    }
    bool clash = false;
    for (const EllipseSpec& s : message) {
      const auto found = model.find(s.name);
      clash = clash || (found != model.end() && found->second.first != EllipseSource::TopicObstacle);
    }
    const std::string error = registry.replaceTopicObstacles(message, "ellipses", step);
    ASSERT_EQ(error.empty(), !clash) << "step " << step << ": " << error;
    if (!clash) {
      ++accepted;
      last_message = message;
      for (auto it = model.begin(); it != model.end();) {
        it = it->second.first == EllipseSource::TopicObstacle ? model.erase(it) : std::next(it);
      }
      for (const EllipseSpec& s : message) model[s.name] = {EllipseSource::TopicObstacle, s.x};
    } else {
      ++refused;
    }
    std::map<std::string, std::pair<EllipseSource, double>> now;
    for (const auto& [name, entry] : registry.entries()) {
      ASSERT_EQ(entry.spec.name, name) << "step " << step;
      now[name] = {entry.source, entry.spec.x};
    }
    ASSERT_EQ(now, model) << "step " << step;
    std::size_t topic = 0;
    for (const auto& [name, entry] : model) topic += entry.first == EllipseSource::TopicObstacle;
    ASSERT_EQ(registry.count(EllipseSource::TopicObstacle), topic) << "step " << step;
  }
  EXPECT_GT(accepted, 500);
  EXPECT_GT(refused, 500);
}

TEST(EllipseRegistry, DuplicateConfiguredNameIsRejected) {
  EXPECT_THROW(EllipseRegistry({spec("a")}, {spec("a")}), std::invalid_argument);
}

}  // namespace
}  // namespace ellipse_collision::app
