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
  // Named by what lets the robot move, so that a value outside the enum (named "STOP" by
  // toString()) is counted, logged and drawn as the stop it is said to be.
  return action != GateAction::Pass && action != GateAction::Slow && action != GateAction::Escape &&
         action != GateAction::Disabled;
}

}  // namespace ellipse_collision::core
