// The obstacle store's writer thread (app/obstacle_store_writer.h): what writeNow() returns is on
// disk, the newest snapshot always lands last, a burst is written once, failures are reported,
// and nothing queued is lost when the writer goes. No master.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "ellipse_collision/app/obstacle_store.h"
#include "ellipse_collision/app/obstacle_store_writer.h"
#include "temporary_store.h"

namespace ellipse_collision::app {
namespace {

/// `count` topic obstacles and the stamp that tells snapshots apart.
StoredObstacles snapshot(double stamp, int count = 1) {
  StoredObstacles stored;
  stored.session = "test";
  stored.topic_stamp_s = stamp;
  for (int i = 0; i < count; ++i) {
    EllipseSpec spec;
    spec.name = "rock_" + std::to_string(i);
    spec.frame_id = "map";
    spec.x = 0.1 * i;
    spec.y = -1.0 / 3.0;
    spec.radius_x = 0.3;
    spec.radius_y = 0.1;
    stored.topic.push_back(spec);
  }
  return stored;
}

/// The store at `path` as parsed back; topic_stamp_s -1 when it cannot be read.
StoredObstacles onDisk(const std::string& path) {
  StoredObstacles stored;
  stored.topic_stamp_s = -1.0;
  test::readStoredFile(path, stored);
  return stored;
}

/// The store two directories down, which the writer must create.
class StoreWriter : public test::TemporaryStore {
 protected:
  StoreWriter() : TemporaryStore("sub/dir/store") {}
};

TEST_F(StoreWriter, WriteNowIsOnDiskWhenItReturnsWithItsDirectories) {
  ObstacleStoreWriter writer(path_);
  ASSERT_EQ(writer.writeNow(snapshot(1.5, 3)), "");
  const StoredObstacles back = onDisk(path_);
  EXPECT_EQ(back.topic_stamp_s, 1.5);
  EXPECT_EQ(back.topic.size(), 3u);
  EXPECT_EQ(writer.writes(), 1u);
  EXPECT_EQ(writer.lastError(), "");
}

TEST_F(StoreWriter, TheNewestSnapshotLandsLastAndABurstIsWrittenOnce) {
  ObstacleStoreWriter writer(path_);
  // 200 snapshots queued back to back, as a 30 Hz stream would in seven seconds: each write is
  // an fsync, each queueing a move, so the thread writes a few of them, the newest last.
  for (int i = 1; i <= 200; ++i) writer.writeLater(snapshot(i, 1000));
  writer.flush();
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 200.0);
  EXPECT_LT(writer.writes(), 100u) << "snapshots queued during a write replace each other";
  EXPECT_GE(writer.writes(), 1u);
}

TEST_F(StoreWriter, AQueuedOlderSnapshotNeverOverwritesANewerOne) {
  ObstacleStoreWriter writer(path_);
  writer.writeLater(snapshot(1.0, 5000));
  ASSERT_EQ(writer.writeNow(snapshot(2.0)), "");
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 2.0);
  writer.flush();
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 2.0);
}

TEST_F(StoreWriter, AFailedWriteIsReportedWithTheStepAndPathUntilOneSucceeds) {
  // The store's directory is a regular file: the directories cannot be made.
  const std::string blocker = std::string(directory_) + "/sub";
  std::FILE* file = std::fopen(blocker.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fclose(file);
  {
    ObstacleStoreWriter writer(path_);
    const std::string error = writer.writeNow(snapshot(1.0));
    EXPECT_NE(error.find("cannot create"), std::string::npos) << error;
    EXPECT_NE(error.find(blocker), std::string::npos) << error;
    EXPECT_EQ(writer.lastError(), error);
    writer.writeLater(snapshot(2.0));
    writer.flush();
    EXPECT_EQ(writer.lastError(), error) << "still failing";
    std::remove(blocker.c_str());
    ASSERT_EQ(writer.writeNow(snapshot(3.0)), "");
    EXPECT_EQ(writer.lastError(), "");
  }
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 3.0);
}

TEST_F(StoreWriter, AServiceRecordIsOnDiskBesideTheStoreWhenItReturns) {
  ObstacleStoreWriter writer(path_);
  writer.writeLater(snapshot(1.0, 5000));
  StoredObstacles record;
  record.session = "test";
  record.service_revision = 7;
  record.service = snapshot(0.0, 2).topic;
  ASSERT_EQ(writer.writeServiceNow(record), "");
  const StoredObstacles back = onDisk(serviceRecordPath(path_));
  EXPECT_EQ(back.service_revision, 7u);
  EXPECT_EQ(back.service.size(), 2u);
  EXPECT_TRUE(back.topic.empty());
  writer.flush();
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 1.0) << "the store itself, untouched by the record";
  EXPECT_EQ(onDisk(path_).topic.size(), 5000u);
}

TEST_F(StoreWriter, WhatIsQueuedWhenTheWriterGoesIsWritten) {
  {
    ObstacleStoreWriter writer(path_);
    writer.writeLater(snapshot(1.0, 2000));
    writer.writeLater(snapshot(7.0, 2000));
  }
  EXPECT_EQ(onDisk(path_).topic_stamp_s, 7.0);
}

}  // namespace
}  // namespace ellipse_collision::app
