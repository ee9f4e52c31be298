#pragma once

// An obstacle store on disk for the app tests: a directory of its own, and the store read back.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include "ellipse_collision/app/obstacle_store.h"

namespace ellipse_collision::test {

/// The store file at `path` parsed into `out`; false, `out` untouched, when it is missing,
/// unreadable or corrupt.
inline bool readStoredFile(const std::string& path, app::StoredObstacles& out) {
  std::string text, error;
  bool missing = false;
  return app::readWholeFile(path, text, missing, error) && app::parseObstacles(text, out).empty();
}

/// A fixture whose store path_ is `relative` (e.g. "sub/dir/store") inside a temporary directory
/// of its own, removed afterwards with the store, its service record and the directories between.
class TemporaryStore : public ::testing::Test {
 protected:
  explicit TemporaryStore(std::string relative) : relative_(std::move(relative)) {}
  void SetUp() override {
    ASSERT_NE(mkdtemp(directory_), nullptr);
    path_ = std::string(directory_) + "/" + relative_;
  }
  void TearDown() override {
    std::remove(path_.c_str());
    std::remove(app::serviceRecordPath(path_).c_str());
    // The directories on the way to the store, deepest first.
    for (std::string dir = path_.substr(0, path_.rfind('/')); dir.size() > std::strlen(directory_);
         dir = dir.substr(0, dir.rfind('/'))) {
      rmdir(dir.c_str());
    }
    rmdir(directory_);
  }

  char directory_[32] = "/tmp/obstacle_store_XXXXXX";
  std::string path_;

 private:
  std::string relative_;
};

}  // namespace ellipse_collision::test
