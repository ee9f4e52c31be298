#include "ellipse_collision/core/contact_prediction.h"

#include <algorithm>
#include <tuple>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/path_motion.h"

namespace ellipse_collision::core {

PredictionResult predictContacts(const std::vector<NamedEllipse>& ellipses,
                                 const std::vector<Motion>& motions, const SceneRules& rules,
                                 const std::set<std::string>& only_names, double horizon,
                                 const std::set<std::pair<std::string, std::string>>* colliding) {
  PredictionResult result;
  if (!(horizon > 0.0)) return result;
  const auto moves = [](const Motion& m) {
    return m.velocity.x() != 0.0 || m.velocity.y() != 0.0 || m.angular_velocity != 0.0;
  };
  std::vector<BoundingBox> boxes;
  boxes.reserve(ellipses.size());
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    boxes.push_back(sweptBox(ellipses[i].ellipse, motions[i], horizon));
  }
  for (const IndexPair& pair : overlappingBoxPairs(boxes)) {
    const NamedEllipse* a = &ellipses[pair.first];
    const NamedEllipse* b = &ellipses[pair.second];
    const Motion* ma = &motions[pair.first];
    const Motion* mb = &motions[pair.second];
    if (!moves(*ma) && !moves(*mb)) continue;
    if (!pairWanted(*a, *b, rules, only_names)) continue;
    if (std::tie(b->role, b->name) < std::tie(a->role, a->name)) std::swap(a, b), std::swap(ma, mb);
    // In collision now: reported as such, not here.
    if (colliding ? colliding->count({a->name, b->name}) != 0 : overlap(a->ellipse, b->ellipse)) {
      continue;
    }
    const std::string invalid = invalidMotionReason(a->ellipse, *ma, b->ellipse, *mb, horizon);
    if (!invalid.empty()) {
      result.refused.push_back(a->name + " / " + b->name + ": " + invalid);
      continue;
    }
    ++result.pair_tests;
    const FirstContact contact = firstContact(a->ellipse, *ma, b->ellipse, *mb, horizon);
    if (contact.contact) result.predicted.push_back({a->name, b->name, contact.time});
  }
  std::sort(result.predicted.begin(), result.predicted.end(),
            [](const PredictedContact& x, const PredictedContact& y) {
              return std::tie(x.time, x.name_a, x.name_b) < std::tie(y.time, y.name_a, y.name_b);
            });
  return result;
}

}  // namespace ellipse_collision::core
