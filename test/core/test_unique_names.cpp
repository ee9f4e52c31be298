// The one uniqueness check of names (scenes, configuration, requests, the registry).
#include <gtest/gtest.h>

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

TEST(UniqueNames, NamesThatDifferOnlyInEmbeddedBytesAreDistinct) {
  EXPECT_FALSE(findNameProblem({std::string("a\0b", 3), std::string("a\0c", 3), "a"}));
}

}  // namespace
}  // namespace ellipse_collision::core
