#include "ellipse_collision/core/gate_action.h"

namespace ellipse_collision::core {

const char* toString(GateAction action) {
  switch (action) {
    case GateAction::Pass:
      return "PASS";
    case GateAction::Slow:
      return "SLOW";
    case GateAction::Stop:
      return "STOP";
    case GateAction::Escape:
      return "ESCAPE";
    case GateAction::Timeout:
      return "TIMEOUT";
    case GateAction::Incomplete:
      return "INCOMPLETE";
    case GateAction::Disabled:
      return "DISABLED";
  }
  return "STOP";
}

bool stops(GateAction action) {
  return action == GateAction::Stop || action == GateAction::Timeout ||
         action == GateAction::Incomplete;
}

}  // namespace ellipse_collision::core
