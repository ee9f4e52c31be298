#include "ellipse_collision/core/scene.h"

#include <utility>

namespace ellipse_collision::core {

Scene::Scene(const std::vector<NamedEllipse>& entries) {
  reserve(entries.size());
  for (const NamedEllipse& entry : entries) push_back(entry);
}

void Scene::reserve(std::size_t count) {
  names_.reserve(count);
  roles_.reserve(count);
  ellipses_.reserve(count);
}

void Scene::push_back(std::string name, EllipseRole role, const Ellipse& ellipse) {
  names_.push_back(std::move(name));
  roles_.push_back(role);
  ellipses_.push_back(ellipse);
}

void Scene::insertFront(const std::vector<NamedEllipse>& entries) {
  if (entries.empty()) return;
  std::vector<std::string> names;
  std::vector<EllipseRole> roles;
  std::vector<Ellipse> ellipses;
  for (const NamedEllipse& entry : entries) {
    names.push_back(entry.name);
    roles.push_back(entry.role);
    ellipses.push_back(entry.ellipse);
  }
  names_.insert(names_.begin(), std::make_move_iterator(names.begin()),
                std::make_move_iterator(names.end()));
  roles_.insert(roles_.begin(), roles.begin(), roles.end());
  ellipses_.insert(ellipses_.begin(), ellipses.begin(), ellipses.end());
}

void Scene::eraseFront(std::size_t count) {
  const auto n = static_cast<std::ptrdiff_t>(count);
  names_.erase(names_.begin(), names_.begin() + n);
  roles_.erase(roles_.begin(), roles_.begin() + n);
  ellipses_.erase(ellipses_.begin(), ellipses_.begin() + n);
}

void Scene::truncate(std::size_t count) {
  names_.resize(count);
  roles_.resize(count);
  ellipses_.resize(count);
}

std::vector<NamedEllipse> Scene::entries() const {
  std::vector<NamedEllipse> records;
  records.reserve(size());
  for (std::size_t i = 0; i < size(); ++i) records.push_back(entry(i));
  return records;
}

}  // namespace ellipse_collision::core
