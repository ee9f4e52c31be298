// check_scene of named ellipses: the core's checkScene() with its rules as keyword arguments.
// The core refuses a bad scene itself (an empty or duplicate name, a negative warning distance),
// naming the entry; its error is raised as ValueError.
#include <pybind11/stl.h>

#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.h"
#include "ellipse_collision/core/scene_check.h"
#include "refusal.h"

namespace ellipse_collision::python {

namespace py = pybind11;

void bindSceneFunctions(py::module_& module) {
  py::enum_<core::EllipseRole>(module, "Role",
                               "What an ellipse stands for: link-obstacle pairs are always "
                               "checked, link-link iff self_collision, obstacle-obstacle never, "
                               "a query against every link and obstacle.")
      .value("QUERY", core::EllipseRole::Query)
      .value("LINK", core::EllipseRole::Link)
      .value("OBSTACLE", core::EllipseRole::Obstacle);

  py::class_<core::CollidingPair>(module, "CollidingPair")
      .def_readonly("name_a", &core::CollidingPair::name_a)
      .def_readonly("name_b", &core::CollidingPair::name_b)
      .def_readonly("contact_scale", &core::CollidingPair::contact_scale)
      .def("__repr__", [](const core::CollidingPair& p) {
        return "CollidingPair('" + p.name_a + "', '" + p.name_b + "')";
      });
  py::class_<core::NearPair>(module, "NearPair")
      .def_readonly("name_a", &core::NearPair::name_a)
      .def_readonly("name_b", &core::NearPair::name_b)
      .def_readonly("distance", &core::NearPair::distance)
      .def_property_readonly("point_a",
                             [](const core::NearPair& p) { return pointTuple(p.point_a); })
      .def_property_readonly("point_b",
                             [](const core::NearPair& p) { return pointTuple(p.point_b); })
      .def("__repr__", [](const core::NearPair& p) {
        return "NearPair('" + p.name_a + "', '" + p.name_b + "')";
      });
  py::class_<core::SceneCheckResult>(module, "SceneCheckResult",
                                     "collisions (CollidingPair, sorted by role and name) and "
                                     "warnings (NearPair: separated but closer than the warning "
                                     "distance).")
      .def_readonly("collisions", &core::SceneCheckResult::collisions)
      .def_readonly("warnings", &core::SceneCheckResult::warnings)
      .def_readonly("pair_tests", &core::SceneCheckResult::pair_tests);

  module.def(
      "check_scene",
      [](const std::vector<std::tuple<std::string, core::EllipseRole, core::Ellipse>>& entries,
         bool self_collision, const std::vector<std::pair<std::string, std::string>>& allowed_pairs,
         double warning_distance, const std::set<std::string>& only_names) {
        std::vector<core::NamedEllipse> scene;
        scene.reserve(entries.size());
        for (const auto& [name, role, ellipse] : entries) scene.push_back({name, role, ellipse});
        core::SceneRules rules;
        rules.self_collision = self_collision;
        for (const auto& [a, b] : allowed_pairs) rules.allowed.add(a, b);
        rules.warning_distance = warning_distance;
        core::SceneCheckResult result;
        {
          py::gil_scoped_release release;
          result = core::checkScene(scene, rules, only_names);
        }
        refuseIfInvalid(result.error);
        return result;
      },
      py::arg("ellipses"), py::arg("self_collision") = true, py::arg("allowed_pairs") = py::list(),
      py::arg("warning_distance") = 0.0, py::arg("only_names") = py::set(),
      "Every wanted pair of a list of (name, Role, Ellipse) checked: the colliding pairs with "
      "their "
      "contact scale and, with warning_distance > 0 [m], the separated pairs closer than that "
      "(a SceneCheckResult). allowed_pairs: (name, name) pairs never reported; only_names: check "
      "only pairs with one of these names (empty: every pair).");
}

}  // namespace ellipse_collision::python
