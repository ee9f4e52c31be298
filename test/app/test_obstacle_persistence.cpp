// When the runtime obstacles are made durable and in which file (app/obstacle_persistence.h):
// a service call writes the service record (or the whole store when it removed a topic
// obstacle) before it answers, topic changes wait for the periodic write, every file carries the
// launch's session and the count of service calls; a store that is off or refused writes nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/obstacle_persistence.h"
#include "spec_builders.h"
#include "temporary_store.h"

namespace ellipse_collision::app {
namespace {

EllipseSpec spec(const std::string& name, const std::string& frame, double x) {
  return test::circle(name, frame, x, 0.0, 0.3);
}

/// A store in a directory of its own, removed with what is in it.
class PersistenceDirectory : public test::TemporaryStore {
 protected:
  PersistenceDirectory() : TemporaryStore("store") {}
};

TEST_F(PersistenceDirectory, WritesTheRecordOrTheWholeStoreCountingFromTheLoadedRevision) {
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(path_, "launch", 7);
  ASSERT_TRUE(persistence.enabled());
  ASSERT_EQ(live.addObstacles({spec("crate", "map", 1.0)}, "o"), "");
  ASSERT_EQ(persistence.afterServiceCall(live, false), "");
  StoredObstacles record, store;
  ASSERT_TRUE(test::readStoredFile(serviceRecordPath(path_), record));
  EXPECT_FALSE(test::readStoredFile(path_, store)) << "a service-only call leaves the store alone";
  EXPECT_EQ(record.session, "launch");
  EXPECT_EQ(record.service_revision, 8u);
  ASSERT_EQ(record.service.size(), 1u);
  EXPECT_EQ(record.service[0].name, "crate");

  ASSERT_EQ(live.replaceTopicObstacles({spec("rock", "map", 2.0)}, "e", 5.0), "");
  persistence.topicChanged();
  EXPECT_FALSE(test::readStoredFile(path_, store))
      << "a topic message waits for the periodic write";
  persistence.writeIfBehind(live);
  persistence.flush();
  ASSERT_TRUE(test::readStoredFile(path_, store));
  EXPECT_EQ(store.service_revision, 8u);
  ASSERT_EQ(store.topic.size(), 1u);
  EXPECT_EQ(store.topic[0].name, "rock");

  ASSERT_EQ(live.removeObstacles({"rock"}, "n"), "");
  ASSERT_EQ(persistence.afterServiceCall(live, true), "");
  ASSERT_TRUE(test::readStoredFile(path_, store))
      << "removing a topic obstacle writes the whole store";
  EXPECT_EQ(store.service_revision, 9u);
  EXPECT_TRUE(store.topic.empty());
  EXPECT_EQ(store.service.size(), 1u);

  ObstaclePersistence off("", "launch", 3);
  EXPECT_FALSE(off.enabled());
  EXPECT_EQ(off.afterServiceCall(live, true), "");
  EXPECT_EQ(off.serviceRevision(), 4u);
  off.topicChanged();
  off.writeIfBehind(live);
  EXPECT_EQ(off.lastError(), "");
}

TEST_F(PersistenceDirectory, AServiceOnlyCallLeavesTheStoreBehindForThePeriodicWrite) {
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(path_, "launch", 0);
  ASSERT_EQ(live.replaceTopicObstacles({spec("rock", "map", 2.0)}, "e", 5.0), "");
  persistence.topicChanged();
  EXPECT_TRUE(persistence.behind());
  ASSERT_EQ(live.addObstacles({spec("crate", "map", 1.0)}, "o"), "");
  ASSERT_EQ(persistence.afterServiceCall(live, false), "");
  EXPECT_TRUE(persistence.behind()) << "the record holds no topic obstacle";
  StoredObstacles record, store;
  ASSERT_TRUE(test::readStoredFile(serviceRecordPath(path_), record));
  EXPECT_TRUE(record.topic.empty());
  persistence.writeIfBehind(live);
  EXPECT_FALSE(persistence.behind());
  persistence.flush();
  ASSERT_TRUE(test::readStoredFile(path_, store));
  EXPECT_EQ(store.session, "launch");
  EXPECT_EQ(store.service_revision, 1u);
  ASSERT_EQ(store.topic.size(), 1u);
  ASSERT_EQ(store.service.size(), 1u);
  // A removal of a topic obstacle writes everything at once: nothing is left behind.
  persistence.topicChanged();
  ASSERT_EQ(live.removeObstacles({"rock"}, "n"), "");
  ASSERT_EQ(persistence.afterServiceCall(live, true), "");
  EXPECT_FALSE(persistence.behind());
  EXPECT_EQ(persistence.serviceRevision(), 2u);
  EXPECT_EQ(persistence.lastError(), "");
}

TEST_F(PersistenceDirectory, NothingIsWrittenWhileNothingIsBehind) {
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(path_, "launch", 0);
  EXPECT_FALSE(persistence.behind());
  persistence.writeIfBehind(live);
  persistence.flush();
  StoredObstacles store;
  EXPECT_FALSE(test::readStoredFile(path_, store));
  EXPECT_FALSE(test::readStoredFile(serviceRecordPath(path_), store));
}

TEST_F(PersistenceDirectory, ARefusedStoreIsNeverWrittenAndEveryCallSaysWhy) {
  const std::string refusal = "the file is not an obstacle store";
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(path_, "launch", 4, refusal);
  EXPECT_FALSE(persistence.enabled());
  EXPECT_EQ(persistence.lastError(), refusal);
  ASSERT_EQ(live.addObstacles({spec("crate", "map", 1.0)}, "o"), "");
  EXPECT_EQ(persistence.afterServiceCall(live, false), refusal);
  EXPECT_EQ(persistence.afterServiceCall(live, true), refusal);
  EXPECT_EQ(persistence.serviceRevision(), 6u) << "calls are counted all the same";
  persistence.topicChanged();
  persistence.writeIfBehind(live);
  persistence.flush();
  StoredObstacles store;
  EXPECT_FALSE(test::readStoredFile(path_, store));
  EXPECT_FALSE(test::readStoredFile(serviceRecordPath(path_), store));
  // With the store off a refusal means nothing: there is no file to refuse.
  ObstaclePersistence off("", "launch", 0, refusal);
  EXPECT_EQ(off.afterServiceCall(live, false), "");
  EXPECT_EQ(off.lastError(), "");
}

TEST_F(PersistenceDirectory, AFailedWriteIsTheAnswerAndTheLastError) {
  // The store's directory is a plain file: no write can succeed.
  const std::string blocker = path_ + "_file";
  std::FILE* file = std::fopen(blocker.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fclose(file);
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(blocker + "/store", "launch", 0);
  ASSERT_TRUE(persistence.enabled());
  ASSERT_EQ(live.addObstacles({spec("crate", "map", 1.0)}, "o"), "");
  const std::string error = persistence.afterServiceCall(live, true);
  EXPECT_NE(error, "");
  EXPECT_EQ(persistence.lastError(), error);
  std::remove(blocker.c_str());
}

}  // namespace
}  // namespace ellipse_collision::app
