// The pair functions on N pairs at once: row i of `a` with row i of `b`, (N, 5) float64 arrays.
// The loop runs in C++ with the GIL released, so a million pairs cost what the core costs (the
// Python alternative pays an interpreter round trip per pair) and other Python threads run.
#include <string>

#include "bindings.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_rows.h"

namespace ellipse_collision::python {

namespace py = pybind11;

namespace {

/// Calls per_pair(i, a[i], b[i]) for every row, without the GIL, after checking both arrays'
/// shape and dtype; rows are validated as they are read (isValid(): five comparisons) and the
/// first invalid one is refused with ValueError naming its array, row, field and value.
template <typename PerPair>
void forEachPair(const py::array& a_array, const py::array& b_array, PerPair per_pair) {
  const EllipseRows a(a_array, "a"), b(b_array, "b");
  requireSameRows(a, b);
  py::ssize_t invalid = -1;
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < a.size(); ++i) {
      const core::Ellipse ellipse_a = a[i], ellipse_b = b[i];
      if (!core::isValid(ellipse_a) || !core::isValid(ellipse_b)) {
        invalid = i;
        break;
      }
      per_pair(i, ellipse_a, ellipse_b);
    }
  }
  if (invalid >= 0) {
    if (!core::isValid(a[invalid])) a.refuseRow(invalid);
    b.refuseRow(invalid);
  }
}

/// An (N,) array of per_pair(a[i], b[i]): the batch form of a pair function with one answer.
template <typename Result, typename PerPair>
py::array_t<Result> batchOf(const py::array& a, const py::array& b, PerPair per_pair) {
  py::array_t<Result> result(a.ndim() > 0 ? a.shape(0) : 0);
  Result* out = result.mutable_data();
  forEachPair(a, b,
              [out, per_pair](py::ssize_t i, const core::Ellipse& ea, const core::Ellipse& eb) {
                out[i] = per_pair(ea, eb);
              });
  return result;
}

/// Row i of an (N, 3) float64 array of motions [vx, vy, angular_velocity], read without the GIL.
core::Motion motionRow(const py::detail::unchecked_reference<double, 2>& rows, py::ssize_t i) {
  core::Motion motion;
  motion.velocity = {rows(i, 0), rows(i, 1)};
  motion.angular_velocity = rows(i, 2);
  return motion;
}

/// The motions of `name`: an (N, 3) float64 array with as many rows as the ellipses.
py::detail::unchecked_reference<double, 2> motionRows(const py::array& array, const char* name,
                                                      const EllipseRows& ellipses) {
  requireFloat64Rows(array, name, 3, "vx, vy, angular_velocity");
  if (array.shape(0) != ellipses.size()) {
    throw py::value_error(std::string(name) + " has " + std::to_string(array.shape(0)) +
                          " rows and " + ellipses.name() + " " + std::to_string(ellipses.size()) +
                          ": one motion per ellipse");
  }
  return array.unchecked<double, 2>();
}

}  // namespace

void bindBatchFunctions(py::module_& module) {
  module.def(
      "overlap_batch",
      [](const py::array& a, const py::array& b) {
        return batchOf<bool>(a, b, [](const core::Ellipse& ea, const core::Ellipse& eb) {
          return core::overlap(ea, eb);
        });
      },
      py::arg("a"), py::arg("b"),
      "overlap() of row i of a with row i of b: (N, 5) float64 arrays [x, y, radius_x, radius_y, "
      "angle] in, an (N,) bool array out.");
  module.def(
      "contact_scale_batch",
      [](const py::array& a, const py::array& b) {
        return batchOf<double>(a, b, [](const core::Ellipse& ea, const core::Ellipse& eb) {
          return core::contactScale(ea, eb);
        });
      },
      py::arg("a"), py::arg("b"),
      "contact_scale() of row i of a with row i of b: an (N,) float64 array out.");
  module.def(
      "first_contact_batch",
      [](const py::array& a, const py::array& motion_a, const py::array& b,
         const py::array& motion_b, double horizon) {
        const EllipseRows ellipses_a(a, "a"), ellipses_b(b, "b");
        requireSameRows(ellipses_a, ellipses_b);
        const auto motions_a = motionRows(motion_a, "motion_a", ellipses_a);
        const auto motions_b = motionRows(motion_b, "motion_b", ellipses_b);
        py::array_t<bool> contacts(ellipses_a.size());
        py::array_t<double> times(ellipses_a.size());
        bool* contact_out = contacts.mutable_data();
        double* time_out = times.mutable_data();
        py::ssize_t invalid = -1;
        std::string reason;
        {
          py::gil_scoped_release release;
          for (py::ssize_t i = 0; i < ellipses_a.size(); ++i) {
            const core::Ellipse ea = ellipses_a[i], eb = ellipses_b[i];
            const core::Motion ma = motionRow(motions_a, i), mb = motionRow(motions_b, i);
            // The one rule of firstContact()'s input, for every pair: an empty string costs
            // nothing beside the contact search.
            reason = core::invalidMotionReason(ea, ma, eb, mb, horizon);
            if (!reason.empty()) {
              invalid = i;
              break;
            }
            const core::FirstContact contact = core::firstContact(ea, ma, eb, mb, horizon);
            contact_out[i] = contact.contact;
            time_out[i] = contact.time;
          }
        }
        if (invalid >= 0) {
          throw py::value_error("pair " + std::to_string(invalid) + ": " + reason);
        }
        return py::make_tuple(contacts, times);
      },
      py::arg("a"), py::arg("motion_a"), py::arg("b"), py::arg("motion_b"), py::arg("horizon"),
      "first_contact() of row i of a and b, moving by row i of motion_a and motion_b ((N, 3) "
      "float64 arrays [vx, vy, angular_velocity]), within one horizon [s]: (contacts (N,) bool, "
      "times (N,) float64, 0 where there is no contact). A bad pair is refused as 'pair i: ...' "
      "with ellipse 1 / motion 1 the row of a, ellipse 2 / motion 2 the row of b.");
  module.def(
      "distance_batch",
      [](const py::array& a, const py::array& b) {
        const py::ssize_t rows = a.ndim() > 0 ? a.shape(0) : 0;
        py::array_t<double> distances(rows);
        py::array_t<double> points_a({rows, py::ssize_t{2}}), points_b({rows, py::ssize_t{2}});
        double* distance_out = distances.mutable_data();
        double* a_out = points_a.mutable_data();
        double* b_out = points_b.mutable_data();
        forEachPair(a, b, [=](py::ssize_t i, const core::Ellipse& ea, const core::Ellipse& eb) {
          const core::Clearance clearance = core::distance(ea, eb);
          distance_out[i] = clearance.distance;
          a_out[2 * i] = clearance.point_a.x();
          a_out[2 * i + 1] = clearance.point_a.y();
          b_out[2 * i] = clearance.point_b.x();
          b_out[2 * i + 1] = clearance.point_b.y();
        });
        return py::make_tuple(distances, points_a, points_b);
      },
      py::arg("a"), py::arg("b"),
      "distance() of row i of a with row i of b: (distances (N,), points_a (N, 2), points_b "
      "(N, 2)); distance 0 and points at the origin where a pair overlaps.");
}

}  // namespace ellipse_collision::python
