// The one uniqueness check of names (scenes, configuration, requests, the registry).
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>

#include "ellipse_collision/core/unique_names.h"

namespace ellipse_collision::core {
namespace {

TEST(UniqueNames, DistinctNamesHaveNoProblem) {
  EXPECT_FALSE(findNameProblem({}));
  EXPECT_FALSE(findNameProblem({"a", "b", "ab", "ba", "A"}));
}

TEST(UniqueNames, FirstEmptyNameIsReported) {
  const auto problem = findNameProblem({"a", "", "a"});
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->kind, NameProblem::Kind::Empty);
  EXPECT_EQ(problem->index, 1u);
}

TEST(UniqueNames, DuplicateNamesItsFirstOccurrence) {
  const auto problem = findNameProblem({"x", "y", "z", "y", "x"});
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->kind, NameProblem::Kind::Duplicate);
  EXPECT_EQ(problem->index, 3u);
  EXPECT_EQ(problem->first_index, 1u);
}

TEST(UniqueNames, ManyNamesWithOneRepeatAtTheEnd) {
  // Enough names to fill many slots and force probe sequences past collisions.
  std::vector<std::string> names;
  for (int i = 0; i < 20000; ++i) names.push_back("obstacle_" + std::to_string(i));
  EXPECT_FALSE(findNameProblem(names));
  names.push_back("obstacle_12345");
  const auto problem = findNameProblem(names);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->index, 20000u);
  EXPECT_EQ(problem->first_index, 12345u);
}

TEST(UniqueNames, FirstProblemMatchesAPlainSetOnRandomLists) {
  // Short names over a small alphabet: many repeats, many names of one length, and lists long
  // enough that the slots outgrow the cache (the prefetching path).
  std::mt19937 random(42);
  for (int list = 0; list < 200; ++list) {
    const std::size_t count = list < 190 ? 1 + random() % 300 : 20000 + random() % 20000;
    const std::size_t length = 1 + random() % 4;
    std::vector<std::string> names(count);
    if (list < 190) {
      for (std::string& name : names) {
        name.resize(1 + random() % length);
        for (char& c : name) c = static_cast<char>('a' + random() % 5);
        if (random() % 500 == 0) name.clear();
      }
    } else {  // distinct names of one length, and in most lists one repeat somewhere
      for (std::size_t i = 0; i < count; ++i) names[i] = std::to_string(1000000 + i * 7919 % count);
      if (list % 4 != 0) {
        const std::size_t later = 1 + random() % (count - 1);
        names[later] = names[random() % later];
      }
    }
    // The oracle: the first entry that is empty or already in a std::set.
    std::optional<NameProblem> expected;
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < count && !expected; ++i) {
      if (names[i].empty()) {
        expected = NameProblem{NameProblem::Kind::Empty, i, i};
      } else if (!seen.emplace(names[i], i).second) {
        expected = NameProblem{NameProblem::Kind::Duplicate, i, seen[names[i]]};
      }
    }
    const std::optional<NameProblem> found = findNameProblem(names);
    ASSERT_EQ(found.has_value(), expected.has_value()) << "list " << list;
    if (!expected) continue;
    EXPECT_EQ(found->kind, expected->kind) << "list " << list;
    EXPECT_EQ(found->index, expected->index) << "list " << list;
    EXPECT_EQ(found->first_index, expected->first_index) << "list " << list;
  }
}

TEST(UniqueNames, NamesThatDifferOnlyInEmbeddedBytesAreDistinct) {
  EXPECT_FALSE(findNameProblem({std::string("a\0b", 3), std::string("a\0c", 3), "a"}));
}

}  // namespace
}  // namespace ellipse_collision::core
